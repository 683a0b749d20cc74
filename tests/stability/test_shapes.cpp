// Group 11, the POV-Ray shape families (isosurface and blob so far): each image is the same for 1 and 3
// threads, has no speckles (pixels unlike all four agreeing neighbours), no NaN and no black
// pixels; the same view a million units from the origin differs in at most 1% of pixels;
// a shape cut flush by a CSG box (coincident surfaces) does not speckle.
#include <cmath>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "render/geometry/shapes/blob.hpp"
#include "render/geometry/shapes/isosurface.hpp"
#include "render/geometry/shapes/sor.hpp"
#include "render/geometry/shapes/lathe.hpp"
#include "render/geometry/shapes/prism.hpp"
#include "render/geometry/function/compiled_function.hpp"
#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {

SceneDesc base(Vec3 eye, Vec3 at) {
  SceneDesc s;
  s.settings.width = 64;
  s.settings.height = 48;
  s.settings.background = Color(0.3, 0.4, 0.6);
  s.has_camera = true;
  s.camera.position = eye;
  s.camera.look_at = at;
  LightDesc l;
  l.position = eye + Vec3(1, 4, 1);
  place(s, add_light(s, l));
  return s;
}

// x^2 + y^2 + z^2 + 0.15 sin(5x) sin(5y): a rippled ball of radius about 0.8.
Isosurface rippled_ball() {
  auto f = std::make_shared<CompiledFunction>();
  using Op = CompiledFunction::Op;
  uint16_t five, k, xx, yy, zz, s1, s2, x5, y5, sx, sy, p, w, r;
  f->constant(5.0, five);
  f->constant(0.15, k);
  f->emit(Op::Mul, {CompiledFunction::kX, CompiledFunction::kX}, xx);
  f->emit(Op::Mul, {CompiledFunction::kY, CompiledFunction::kY}, yy);
  f->emit(Op::Mul, {CompiledFunction::kZ, CompiledFunction::kZ}, zz);
  f->emit(Op::Add, {xx, yy}, s1);
  f->emit(Op::Add, {s1, zz}, s2);
  f->emit(Op::Mul, {CompiledFunction::kX, five}, x5);
  f->emit(Op::Mul, {CompiledFunction::kY, five}, y5);
  f->emit(Op::Sin, {x5}, sx);
  f->emit(Op::Sin, {y5}, sy);
  f->emit(Op::Mul, {sx, sy}, p);
  f->emit(Op::Mul, {p, k}, w);
  f->emit(Op::Add, {s2, w}, r);
  f->set_result(r);
  IsosurfaceData g;
  g.function = f;
  g.threshold = 0.64;
  g.max_gradient = 3.0;
  g.box_min = Vec3(-1, -1, -1);
  g.box_max = Vec3(1, 0.5, 1);  // cuts the top flat: the container closes the solid there
  g.monitor = std::make_shared<IsoGradientMonitor>();
  return g;
}

// Three spheres and a cylinder fused, with a thin neck between two of them (the sum barely
// exceeds the threshold there) and a carving negative component.
Blob necked_blob() {
  Blob b;
  b.threshold = 0.6;
  b.components = {BlobComponent{Vec3(-0.55, 0, 0), Vec3(-0.55, 0, 0), 0.8, 1.0, false},
                  BlobComponent{Vec3(0.55, 0, 0), Vec3(0.55, 0, 0), 0.8, 1.0, false},
                  BlobComponent{Vec3(0, 0.6, 0), Vec3(0, 0.6, 0), 0.6, 1.0, false},
                  BlobComponent{Vec3(-0.9, -0.35, 0), Vec3(0.9, -0.35, 0), 0.3, 1.0, true},
                  BlobComponent{Vec3(0, 0.2, -0.6), Vec3(0, 0.2, -0.6), 0.4, -1.0, false}};
  return b;
}

// A vase: a bulge, a narrow waist, a flared lip, closed by its discs.
SorData vase() {
  SorData s;
  s.points = {Vec3(0.1, -1.3, 0), Vec3(0.5, -1, 0), Vec3(0.85, -0.5, 0), Vec3(0.25, 0.2, 0),
              Vec3(0.3, 0.6, 0),  Vec3(0.7, 1, 0),  Vec3(0.9, 1.3, 0)};
  sor_setup(s);
  return s;
}

// A cup: a flat bottom, a slanted wall, a rim and a hollow, the profile from the axis to the
// axis. (A foot under the wall casts a true shadow one pixel wide into its inner corner, which
// the speckle count would flag; so would a blue cup, whose lit rim reads as the background's
// colour around one unlit pixel of wall at the silhouette.)
LatheData cup() {
  LatheData l;
  l.points = {Vec3(0, -0.7, 0), Vec3(0.5, -0.7, 0), Vec3(1.1, 0.6, 0), Vec3(1, 0.7, 0),
              Vec3(0.9, 0.55, 0), Vec3(0, -0.35, 0)};
  lathe_setup(l);
  return l;
}

// A five-pointed star with a pentagonal hole (two sub-polygons, even-odd), closed by its caps.
Prism star() {
  PrismData p;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i <= 10; ++i) {
    double a = 2 * pi * (i % 10) / 10.0 + pi / 2, r = i % 2 == 0 ? 1.2 : 0.5;
    p.points.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
  }
  for (int i = 0; i <= 5; ++i) {
    double a = 2 * pi * (i % 5) / 5.0 + pi / 2;
    p.points.emplace_back(0.25 * std::cos(a), 0.25 * std::sin(a), 0.0);
  }
  p.height1 = -0.4;
  p.height2 = 0.3;
  prism_setup(p);
  return p;
}

void check_stable(const SceneDesc& s, const std::string& name, const std::string& file) {
  RenderResult one = render_scene(s, 1), three = render_scene(s, 3);
  bool same = one.color.rgb == three.color.rgb;
  int speckles = count_speckles(one.color), black = count_black(one.color);
  int nan = count_non_finite(one.color);
  std::string img = save(one.color, file);
  record("shapes", name, "speckles", speckles, "0", img);
  record("shapes", name, "black or NaN pixels", black + nan, "0");
  record("shapes", name, "1 vs 3 threads identical", same ? 1 : 0, "1");
  CAPTURE(name);
  CHECK(same);
  CHECK(speckles == 0);
  CHECK(black == 0);
  CHECK(nan == 0);
}

}  // namespace

TEST_CASE("an isosurface closed by its box, near the origin and a million units away", "[shapes]") {
  const Vec3 eye(1.2, 2.0, -2.6), at(0, 0, 0);
  SceneDesc near = base(eye, at);
  MaterialId m = add_material(near, matte(Color(0.8, 0.6, 0.2)));
  place(near, add_shape(near, rippled_ball(), m));
  check_stable(near, "isosurface cut by its container", "shapes_isosurface");
  const Vec3 far(1e6, -1e6, 1e6);
  SceneDesc away = base(eye + far, far);
  place(away, add_shape(away, rippled_ball(), add_material(away, matte(Color(0.8, 0.6, 0.2)))), translate(far));
  RenderResult a = render_scene(near, 2), b = render_scene(away, 2);
  double diff = differing_fraction(a.color, b.color);
  record("shapes", "isosurface at 1e6 vs at the origin", "pixels differing", diff, "<= 0.01",
         save(b.color, "shapes_isosurface_far"));
  CHECK(diff <= 0.01);
  CHECK(count_speckles(b.color) == 0);
}

TEST_CASE("an isosurface minus a box flush with its container's top", "[shapes]") {
  SceneDesc s = base(Vec3(1.5, 2.5, -3), Vec3(0, 0, 0));
  MaterialId red = add_material(s, matte(Color(0.8, 0.2, 0.15)));
  MaterialId green = add_material(s, matte(Color(0.2, 0.7, 0.2)));
  place(s, add_csg(s, CsgOp::Difference,
                   {Child{add_shape(s, rippled_ball(), red), Mat4(1.0), {}},
                    Child{add_shape(s, Box{Vec3(0, 0.5, -2), Vec3(2, 2, 0)}, green), Mat4(1.0), {}}}));
  check_stable(s, "isosurface minus a box sharing its top face", "shapes_isosurface_csg");
}

TEST_CASE("a blob with a thin neck, near the origin and a million units away", "[shapes]") {
  const Vec3 eye(0.8, 1.6, -2.8), at(0, 0.1, 0);
  SceneDesc near = base(eye, at);
  place(near, add_shape(near, necked_blob(), add_material(near, matte(Color(0.3, 0.5, 0.8)))));
  check_stable(near, "blob: spheres, a cylinder, a carving component", "shapes_blob");
  const Vec3 far(-1e6, 1e6, 1e6);
  SceneDesc away = base(eye + far, at + far);
  place(away, add_shape(away, necked_blob(), add_material(away, matte(Color(0.3, 0.5, 0.8)))), translate(far));
  RenderResult a = render_scene(near, 2), b = render_scene(away, 2);
  double diff = differing_fraction(a.color, b.color);
  record("shapes", "blob at 1e6 vs at the origin", "pixels differing", diff, "<= 0.01", save(b.color, "shapes_blob_far"));
  CHECK(diff <= 0.01);
  CHECK(count_speckles(b.color) == 0);
}

TEST_CASE("a sor vase near the origin and a million units away, and cut flush at its top", "[shapes]") {
  const Vec3 eye(0.9, 1.8, -3.2), at(0, 0, 0);
  SceneDesc near = base(eye, at);
  place(near, add_shape(near, vase(), add_material(near, matte(Color(0.8, 0.4, 0.2)))));
  check_stable(near, "sor: a vase with a waist and a flared lip", "shapes_sor");
  const Vec3 far(1e6, 1e6, -1e6);
  SceneDesc away = base(eye + far, at + far);
  place(away, add_shape(away, vase(), add_material(away, matte(Color(0.8, 0.4, 0.2)))), translate(far));
  RenderResult a = render_scene(near, 2), b = render_scene(away, 2);
  double diff = differing_fraction(a.color, b.color);
  record("shapes", "sor at 1e6 vs at the origin", "pixels differing", diff, "<= 0.01", save(b.color, "shapes_sor_far"));
  CHECK(diff <= 0.01);
  CHECK(count_speckles(b.color) == 0);

  SceneDesc s = base(eye, at);
  MaterialId red = add_material(s, matte(Color(0.8, 0.2, 0.15)));
  MaterialId green = add_material(s, matte(Color(0.2, 0.7, 0.2)));
  place(s, add_csg(s, CsgOp::Difference,
                   {Child{add_shape(s, vase(), red), Mat4(1.0), {}},
                    Child{add_shape(s, Box{Vec3(-2, 0.6, -2), Vec3(0, 1, 0)}, green), Mat4(1.0), {}}}));
  check_stable(s, "sor minus a box sharing its top disc's height", "shapes_sor_csg");
}

TEST_CASE("a lathe cup near the origin and a million units away, and cut flush at its rim", "[shapes]") {
  const Vec3 eye(0.9, 2.2, -3.2), at(0, 0, 0);
  SceneDesc near = base(eye, at);
  place(near, add_shape(near, cup(), add_material(near, matte(Color(0.8, 0.6, 0.2)))));
  check_stable(near, "lathe: a cup with a rim and a hollow", "shapes_lathe");
  const Vec3 far(-1e6, 1e6, 1e6);
  SceneDesc away = base(eye + far, at + far);
  place(away, add_shape(away, cup(), add_material(away, matte(Color(0.8, 0.6, 0.2)))), translate(far));
  RenderResult a = render_scene(near, 2), b = render_scene(away, 2);
  double diff = differing_fraction(a.color, b.color);
  record("shapes", "lathe at 1e6 vs at the origin", "pixels differing", diff, "<= 0.01",
         save(b.color, "shapes_lathe_far"));
  CHECK(diff <= 0.01);
  CHECK(count_speckles(b.color) == 0);

  SceneDesc s = base(eye, at);
  MaterialId red = add_material(s, matte(Color(0.8, 0.2, 0.15)));
  MaterialId green = add_material(s, matte(Color(0.2, 0.7, 0.2)));
  place(s, add_csg(s, CsgOp::Difference,
                   {Child{add_shape(s, cup(), red), Mat4(1.0), {}},
                    Child{add_shape(s, Box{Vec3(-2, 0.3, -2), Vec3(0, 0.7, 0)}, green), Mat4(1.0), {}}}));
  check_stable(s, "lathe minus a box sharing its rim's height", "shapes_lathe_csg");
}

TEST_CASE("a prism star with a hole near the origin and a million units away, and cut flush at its top", "[shapes]") {
  const Vec3 eye(0.9, 2.2, -2.6), at(0, 0, 0);
  SceneDesc near = base(eye, at);
  place(near, add_shape(near, star(), add_material(near, matte(Color(0.8, 0.6, 0.2)))));
  check_stable(near, "prism: a star with a pentagonal hole", "shapes_prism");
  const Vec3 far(1e6, -1e6, 1e6);
  SceneDesc away = base(eye + far, at + far);
  place(away, add_shape(away, star(), add_material(away, matte(Color(0.8, 0.6, 0.2)))), translate(far));
  RenderResult a = render_scene(near, 2), b = render_scene(away, 2);
  double diff = differing_fraction(a.color, b.color);
  record("shapes", "prism at 1e6 vs at the origin", "pixels differing", diff, "<= 0.01",
         save(b.color, "shapes_prism_far"));
  CHECK(diff <= 0.01);
  CHECK(count_speckles(b.color) == 0);

  SceneDesc s = base(eye, at);
  MaterialId red = add_material(s, matte(Color(0.8, 0.2, 0.15)));
  MaterialId green = add_material(s, matte(Color(0.2, 0.7, 0.2)));
  place(s, add_csg(s, CsgOp::Difference,
                   {Child{add_shape(s, star(), red), Mat4(1.0), {}},
                    Child{add_shape(s, Box{Vec3(-2, 0.0, -2), Vec3(0, 0.3, 0)}, green), Mat4(1.0), {}}}));
  check_stable(s, "prism minus a box sharing its top cap's height", "shapes_prism_csg");
}
