// The POV-Ray shape families from the language: an isosurface's macro is compiled and traced,
// its container read from a box or sphere block, and bad parameters are located errors.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "eval_helpers.hpp"
#include "render/geometry/shapes/blob.hpp"
#include "render/geometry/shapes/isosurface.hpp"
#include "render/geometry/shapes/lathe.hpp"
#include "render/geometry/shapes/prism.hpp"
#include "render/geometry/shapes/sor.hpp"
#include "render/renderer.hpp"

using namespace rts;
using rts::test::eval_diagnostic;
using rts::test::eval_text;

namespace {
const render::IsosurfaceData& only_isosurface(const render::SceneDesc& s) {
  for (const render::ShapeDesc& d : s.shapes)
    if (const auto* g = shape_if<render::Isosurface>(d.geometry)) return **g;
  FAIL("no isosurface in the scene");
  throw 0;
}
}  // namespace

TEST_CASE("an isosurface traces its compiled macro inside a sphere container", "[shapes]") {
  render::SceneDesc s = eval_text(
      "macro ball(p, r = 0.5) { return length(p) - r }\n"
      "isosurface { function = ball  threshold = 0.25  max_gradient = 1.1  accuracy = 1e-4\n"
      "             contained_by = sphere { center = <0, 0, 0>  radius = 2 } }\n");
  const render::IsosurfaceData& iso = only_isosurface(s);
  CHECK(iso.container_sphere);
  CHECK(iso.radius == 2.0);
  render::SurfaceHit h;
  // length(p) < 0.75: the crossing along -z is at 0.75 within the accuracy.
  REQUIRE(intersect(iso, render::Ray{render::Vec3(0, 0, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(5.0 - 0.75).margin(1e-4));
  CHECK(h.normal.z == Approx(-1.0).margin(1e-6));
  // A ray that passes beside the solid but through the container misses.
  CHECK_FALSE(intersect(iso, render::Ray{render::Vec3(0.9, 0, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
}

TEST_CASE("an isosurface's box container closes the solid where the function is inside", "[shapes]") {
  render::SceneDesc s = eval_text(
      "macro slab(p) { return p.y }\n"
      "isosurface { function = slab  contained_by = box { min = <-1, -1, -1>  max = <1, 1, 1> } }\n");
  const render::IsosurfaceData& iso = only_isosurface(s);
  render::SurfaceHit h;
  // From below, the box's bottom face (y < 0 is inside); from above, the plane y = 0.
  REQUIRE(intersect(iso, render::Ray{render::Vec3(0.2, -5, 0.1), render::Vec3(0, 1, 0)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(4.0));
  CHECK(h.normal.y == Approx(-1.0));
  REQUIRE(intersect(iso, render::Ray{render::Vec3(0.2, 5, 0.1), render::Vec3(0, -1, 0)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(5.0).margin(1e-3));
  CHECK(h.normal.y == Approx(1.0).margin(1e-6));
  // The whole line crosses the solid (y in [-1, 0]) twice: the box face, then the plane.
  double t[4];
  bool on[4];
  double t0 = 0, t1 = 0;
  render::Ray up{render::Vec3(0.2, -5, 0.1), render::Vec3(0, 1, 0)};
  REQUIRE(render::iso_container_span(iso, up, t0, t1));
  REQUIRE(render::iso_crossings(iso, up, t0, t1, t0, t1, t, on, 4) == 2);
  CHECK(on[0]);
  CHECK_FALSE(on[1]);
  CHECK(t[1] == Approx(5.0).margin(1e-3));
}

TEST_CASE("an isosurface warns when max_gradient is below the slopes it met", "[shapes]") {
  render::SceneDesc s = eval_text(
      "macro steep(p) { return 4 * (length(p) - 0.5) }\n"
      "isosurface { function = steep  max_gradient = 1 }\n");
  const render::IsosurfaceData& iso = only_isosurface(s);
  CHECK_FALSE(render::after_render_warning(iso));
  render::SurfaceHit h;
  for (int i = 0; i < 20; ++i)
    (void)intersect(iso, render::Ray{render::Vec3(0.05 * i - 0.5, 0.1, -5), render::Vec3(0, 0, 1)},
                    render::Interval::positive(), h);
  auto w = render::after_render_warning(iso);
  REQUIRE(w);
  CHECK(w->find("above max_gradient 1") != std::string::npos);
  CHECK(iso.monitor->max_seen.load() <= 4.0 + 1e-9);
  CHECK(iso.monitor->max_seen.load() > 3.0);
}

TEST_CASE("the max_gradient warning comes after a render, the scene borrowed or taken", "[shapes]") {
  // A scene rendered once is taken and its shapes released before the BVH build; the warning
  // is read from the prepared scene's own copy of the isosurface, whose monitor the traced
  // one shares.
  const std::string text =
      "settings { width = 24  height = 18 }\n"
      "camera { position = <0, 0, -4>  look_at = <0, 0, 0> }\n"
      "point_light { position = <2, 3, -4> }\n"
      "macro steep(p) { return 4 * (length(p) - 0.5) }\n"
      "isosurface { function = steep  max_gradient = 1 }\n";
  render::RenderOptions o;
  o.threads = 1;
  auto warned = [](const render::RenderResult& r) {
    for (const render::Warning& w : r.warnings)
      if (w.message.find("above max_gradient 1") != std::string::npos) return w.where.line == 5;
    return false;
  };
  const render::SceneDesc borrowed = eval_text(text);
  render::SceneDesc taken = eval_text(text);
  const render::RenderResult a = render::render(borrowed, o);
  const render::RenderResult b = render::render(std::move(taken), o);
  CHECK(warned(a));
  CHECK(warned(b));
  CHECK(a.color.rgb == b.color.rgb);
  CHECK_FALSE(borrowed.shapes.empty());  // borrowed: left as it was
}

TEST_CASE("an isosurface of a distance function does not warn: rounding over a last, one-ulp step is no slope",
          "[shapes]") {
  // A torus's distance function has gradient length 1 everywhere. The steps along a ray add up
  // to the container's far end one ulp short; the function's rounding over that last step once
  // read as a gradient of 4 and warned "set max_gradient = 4.4" on bench/race/isosurface.rts.
  render::SceneDesc s = eval_text(
      "macro ring(p) { return sqrt(pow(sqrt(p.x * p.x + p.z * p.z) - 0.8, 2) + p.y * p.y) - 0.3 }\n"
      "isosurface { function = ring  max_gradient = 1.1\n"
      "             contained_by = box { min = <-1.2, -0.4, -1.2>  max = <1.2, 0.4, 1.2> } }\n");
  const render::IsosurfaceData& iso = only_isosurface(s);
  render::SurfaceHit h;
  int hits = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      // Rays from a camera's distance and rays that start inside the container (a shadow
      // ray's), across the whole container.
      const render::Vec3 target(-1.2 + 0.06 * i, -0.4 + 0.02 * j, 0.03 * (i - j));
      const render::Vec3 from = (i + j) % 2 ? render::Vec3(0.3, 3.0, -7.0) : render::Vec3(-1.1, -0.3, -1.1);
      hits += intersect(iso, render::Ray{from, target - from}, render::Interval{1e-9, 1e30}, h);
    }
  CHECK(hits > 100);
  CHECK(iso.monitor->max_seen.load() <= 1.0 + 1e-9);
  CHECK(iso.monitor->max_seen.load() > 0.5);
  CHECK_FALSE(render::after_render_warning(iso));
}

TEST_CASE("bad isosurface parameters are located errors", "[shapes]") {
  Diagnostic d = eval_diagnostic("isosurface { threshold = 1 }");
  CHECK(d.message.find("isosurface needs property 'function'") == 0);
  d = eval_diagnostic("isosurface {\n  function = 3 }");
  CHECK(d.message == "property 'function' of isosurface expects a macro of one point, got a number");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 3);
  d = eval_diagnostic("macro f(p) { return p.x }\nisosurface { function = f  max_gradient = 0 }");
  CHECK(d.message == "property 'max_gradient' of isosurface must be > 0, got 0");
  d = eval_diagnostic("macro f(p) { return p.x }\nisosurface { function = f  contained_by = cylinder { from = <0,0,0> to = <0,1,0> radius = 1 } }");
  CHECK(d.message.find("only an isosurface's 'contained_by' takes an object, a box or a sphere") != std::string::npos);
  d = eval_diagnostic("macro f(p) { return p.x }\nisosurface { function = f  contained_by = sphere { radius = 1 } scale 2 }");
  CHECK(d.message.find("takes an untransformed sphere") != std::string::npos);
  d = eval_diagnostic("macro f(p) { return p.x }\nisosurface { function = f  max_trace = 0 }");
  CHECK(d.message == "property 'max_trace' of isosurface must be >= 1, got 0");
}

namespace {
const render::Blob& only_blob(const render::SceneDesc& s) {
  for (const render::ShapeDesc& d : s.shapes)
    if (const auto* g = shape_if<render::Blob>(d.geometry)) return *g;
  FAIL("no blob in the scene");
  throw 0;
}
}  // namespace

TEST_CASE("a one-sphere blob is a sphere of POV-Ray's radius r sqrt(1 - sqrt(threshold / strength))", "[shapes]") {
  render::SceneDesc s = eval_text("blob { threshold = 0.25  spheres = [[<0, 0, 0>, 2, 1]] }\n");
  const render::Blob& b = only_blob(s);
  // s (1 - d^2/r^2)^2 = t  <=>  d = r sqrt(1 - sqrt(t / s)) = 2 sqrt(0.5).
  const double radius = 2.0 * std::sqrt(0.5);
  for (render::Vec3 dir : {render::Vec3(0, 0, 1), glm::normalize(render::Vec3(0.3, -0.2, 1))}) {
    render::SurfaceHit h;
    REQUIRE(intersect(b, render::Ray{-5.0 * dir, dir}, render::Interval::positive(), h));
    CHECK(h.t == Approx(5.0 - radius).epsilon(1e-12));
    CHECK(glm::dot(h.normal, -dir) == Approx(1.0).epsilon(1e-9));
    double t[4];
    REQUIRE(render::blob_crossings(b, render::Ray{-5.0 * dir, dir}, t, 4) == 2);
    CHECK(t[1] == Approx(5.0 + radius).epsilon(1e-12));
  }
}

TEST_CASE("blob components add: two spheres fuse, a cylinder is a capsule, a negative strength carves", "[shapes]") {
  // Two spheres of radius 1, strength 1, 1.2 apart, threshold 0.5: alone each reaches
  // sqrt(1 - sqrt(0.5)) = 0.541 from its centre, so only the sum bridges the gap at x = 0.
  render::SceneDesc s = eval_text("blob { threshold = 0.5  spheres = [[<-0.6, 0, 0>, 1, 1], [<0.6, 0, 0>, 1, 1]] }\n");
  const render::Blob& two = only_blob(s);
  render::SurfaceHit h;
  REQUIRE(intersect(two, render::Ray{render::Vec3(0, 0, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
  // At x = 0 the field is 2 (1 - (0.36 + z^2))^2 = 0.5: z^2 = 0.64 - 0.5.
  CHECK(h.t == Approx(5.0 - std::sqrt(0.14)).epsilon(1e-12));
  CHECK(render::blob_field(two, h.point) == Approx(0.5).epsilon(1e-9));
  // A cylinder along y from 0 to 2, radius 1: beside its body at the body's radius; above
  // its end, a hemisphere.
  s = eval_text("blob { threshold = 0.25  cylinders = [[<0, 0, 0>, <0, 2, 0>, 1, 1]] }\n");
  const render::Blob& cap = only_blob(s);
  const double reach = std::sqrt(0.5);
  REQUIRE(intersect(cap, render::Ray{render::Vec3(0, 1.3, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(5.0 - reach).epsilon(1e-12));
  REQUIRE(intersect(cap, render::Ray{render::Vec3(0, 7, 0), render::Vec3(0, -1, 0)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(5.0 - reach).epsilon(1e-12));
  CHECK(h.normal.y == Approx(1.0).epsilon(1e-9));
  // Along the axis from below: into the bottom hemisphere at -reach.
  REQUIRE(intersect(cap, render::Ray{render::Vec3(0, -5, 0), render::Vec3(0, 1, 0)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(5.0 - reach).epsilon(1e-12));
  // A negative sphere at the centre of a positive one hollows it: four crossings through it.
  s = eval_text("blob { threshold = 0.25  spheres = [[<0, 0, 0>, 2, 1], [<0, 0, 0>, 1, -1]] }\n");
  double t[8];
  CHECK(render::blob_crossings(only_blob(s), render::Ray{render::Vec3(0, 0, -5), render::Vec3(0, 0, 1)}, t, 8) == 4);
}

TEST_CASE("bad blob parameters are located errors", "[shapes]") {
  Diagnostic d = eval_diagnostic("blob { threshold = 0.5 }");
  CHECK(d.message == "blob needs at least one component: 'spheres' or 'cylinders'");
  d = eval_diagnostic("blob { threshold = 0  spheres = [[<0, 0, 0>, 1, 1]] }");
  CHECK(d.message == "property 'threshold' of blob must be > 0, got 0");
  d = eval_diagnostic("blob {\n  spheres = [[<0, 0, 0>, -1, 1]] }");
  CHECK(d.message == "blob spheres entry 1: the radius must be > 0, got -1");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 3);
  d = eval_diagnostic("blob { spheres = [[<0, 0, 0>, 1, 0]] }");
  CHECK(d.message == "blob spheres entry 1: the strength must be a non-zero number, got 0");
  d = eval_diagnostic("blob { spheres = [[<0, 0, 0>, 1]] }");
  CHECK(d.message == "blob spheres entry 1 must be [center, radius, strength]");
  d = eval_diagnostic("blob { cylinders = [[<0, 0, 0>, <0, 0, 0>, 1, 1]] }");
  CHECK(d.message == "blob cylinders entry 1: 'from' and 'to' must differ (use a sphere)");
  d = eval_diagnostic("blob { spheres = [[<0, 0, 0>, \"big\", 1]] }");
  CHECK(d.message.find("each entry is a list of vectors then numbers") != std::string::npos);
}

TEST_CASE("a sor from the language: pairs or vectors, open, and bad points are located errors", "[shapes]") {
  render::SceneDesc s = eval_text("sor { points = [[1, -1], [1, 0], [1, 1], [1, 2]]  open = true }\n");
  const render::Sor* g = nullptr;
  for (const render::ShapeDesc& d : s.shapes) g = g ? g : shape_if<render::Sor>(d.geometry);
  REQUIRE(g);
  CHECK((*g)->open);
  REQUIRE((*g)->segments.size() == 1);
  render::SurfaceHit h;
  REQUIRE(intersect(*g, render::Ray{render::Vec3(0, 0.5, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(4.0).epsilon(1e-12));
  CHECK(h.normal.z == Approx(-1.0).epsilon(1e-12));
  s = eval_text("sor { points = [<1, -1, 0>, <1, 0, 0>, <1, 1, 0>, <1, 2, 0>] }\n");
  CHECK(s.shapes.size() == 1);

  Diagnostic d = eval_diagnostic("sor {\n  points = [[1, 0], [1, 1], [1, 2]] }");
  CHECK(d.message == "sor needs at least 4 points (the first and last set the end slopes), got 3");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 3);
  d = eval_diagnostic("sor {\n  points = [[1, 0], [1, 1], [1, 1], [1, 2]] }");
  CHECK(d.message == "sor point 3 [1, 1]: the heights must increase from point 2 to point 3, but 1 follows 1");
  CHECK(d.loc.line() == 2);
  d = eval_diagnostic("sor { points = [[1, 0], [1, 2], [1, 1], [1, 3]] }");
  CHECK(d.message == "sor point 3 [1, 1]: the heights must increase from point 2 to point 3, but 1 follows 2");
  d = eval_diagnostic("sor {\n  points = [[1, 0], [-0.5, 1], [1, 2], [1, 3]] }");
  CHECK(d.message == "sor point 2 [-0.5, 1]: the radius must be >= 0");
  CHECK(d.loc.line() == 2);
  d = eval_diagnostic("sor { points = [[1, 1], [1, 0], [1, 1], [1, 2]] }");
  CHECK(d.message == "sor points 1 and 3 must differ in height (they set the bottom slope)");
  d = eval_diagnostic("sor { points = [[1, 0], [1], [1, 1], [1, 2]] }");
  CHECK(d.message == "sor point 2 must be a pair [r, h]");
  d = eval_diagnostic("sor { open = true }");
  CHECK(d.message == "sor needs property 'points'");
  d = eval_diagnostic("difference { sor { points = [[1, 0], [1, 1], [1, 2], [1, 3]]  open = true } sphere { radius = 1 } }");
  CHECK(d.message.find("an uncapped sor cannot be part of 'difference'") != std::string::npos);
}

TEST_CASE("a lathe from the language: a closed profile is a CSG operand, bad points are located errors", "[shapes]") {
  render::SceneDesc s = eval_text("lathe { points = [[0, 0], [1, 0], [1, 1], [0, 1]] }\n");
  const render::Lathe* g = nullptr;
  for (const render::ShapeDesc& d : s.shapes) g = g ? g : shape_if<render::Lathe>(d.geometry);
  REQUIRE(g);
  CHECK((*g)->closed);
  render::SurfaceHit h;
  REQUIRE(intersect(*g, render::Ray{render::Vec3(0, 0.5, -5), render::Vec3(0, 0, 1)}, render::Interval::positive(), h));
  CHECK(h.t == Approx(4.0).epsilon(1e-12));
  CHECK(h.normal.z == Approx(-1.0).epsilon(1e-12));
  eval_text("difference { lathe { points = [[0, 0], [1, 0], [1, 1], [0, 1]] } sphere { radius = 0.5 } }\n");

  Diagnostic d = eval_diagnostic("lathe {\n  points = [[1, 0]] }");
  CHECK(d.message == "lathe needs at least 2 points, got 1");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 3);
  d = eval_diagnostic("lathe {\n  points = [[1, 0], [-1, 1]] }");
  CHECK(d.message == "lathe point 2 [-1, 1]: the radius must be >= 0");
  CHECK(d.loc.line() == 2);
  d = eval_diagnostic("lathe {\n  spline = \"cubic\"  points = [[1, 0], [0, 0], [1, 1]] }");
  CHECK(d.message == "a lathe with a cubic spline needs at least 4 points (the first and last are control points), "
                     "got 3");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 21);
  d = eval_diagnostic("lathe { spline = \"bezier\"  points = [[0, 0], [1, 0], [1, 1], [0, 1], [0, 2]] }");
  CHECK(d.message.find("a lathe with a bezier spline needs a multiple of 4 points") == 0);
  d = eval_diagnostic("lathe {\n  spline = \"nurbs\"  points = [[0, 0], [1, 1]] }");
  CHECK(d.message == "lathe spline \"nurbs\" is not one of \"linear\", \"quadratic\", \"cubic\", \"bezier\"");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 3);
  // A cubic's first and last points only shape the curve: they may have r < 0, the others not.
  s = eval_text("lathe { spline = \"cubic\"  points = [[-1, -1], [0, 0], [1, 0.5], [0, 1], [-1, 2]] }\n");
  g = shape_if<render::Lathe>(s.shapes.at(0).geometry);
  REQUIRE(g);
  CHECK((*g)->closed);
  CHECK((*g)->segments.size() == 2);
  d = eval_diagnostic("lathe { spline = \"cubic\"  points = [[1, -1], [-0.5, 0], [1, 0.5], [0, 1], [1, 2]] }");
  CHECK(d.message == "lathe point 2 [-0.5, 0]: the radius must be >= 0");
  d = eval_diagnostic("difference { lathe { points = [[1, 0], [1, 1]] } sphere { radius = 1 } }");
  CHECK(d.message.find("lathe cannot be part of 'difference'") != std::string::npos);
}

TEST_CASE("a prism from the language: sub-polygons, open, and bad points, heights and splines are located errors",
          "[shapes]") {
  render::SceneDesc s = eval_text(
      "prism { points = [[-2, -2], [2, -2], [2, 2], [-2, 2], [-2, -2], [-1, -1], [1, -1], [1, 1], [-1, 1]]\n"
      "        height1 = 1  height2 = -1 }\n");
  const render::PrismData* g = nullptr;
  for (const render::ShapeDesc& d : s.shapes)
    if (const auto* p = shape_if<render::Prism>(d.geometry); p && !g) g = &**p;
  REQUIRE(g);
  CHECK(!g->open);
  CHECK(g->edges.size() == 8);  // the hole closed by its missing last edge
  CHECK(g->y_min == -1.0);
  render::SurfaceHit h;
  REQUIRE(intersect(*g, render::Ray{render::Vec3(-5, 0, 0.5), render::Vec3(1, 0, 0)}, render::Interval::positive(), h));
  CHECK(h.t == 3.0);
  CHECK(h.normal == render::Vec3(-1, 0, 0));
  REQUIRE(intersect(*g, render::Ray{render::Vec3(0, 0, 0.5), render::Vec3(1, 0, 0)}, render::Interval::positive(), h));
  CHECK(h.t == 1.0);  // from inside the hole, into the frame
  CHECK(h.normal == render::Vec3(-1, 0, 0));
  eval_text("difference { prism { points = [[0, 0], [1, 0], [0, 1]] } sphere { radius = 0.5 } }\n");
  s = eval_text("prism { points = [[0, 0], [1, 0], [0, 1]]  open = true  sweep = \"linear\"  spline = \"linear\" }\n");
  CHECK(shape_get<render::Prism>(s.shapes.at(0).geometry)->open);

  Diagnostic d = eval_diagnostic("prism {\n  points = [[0, 0], [1, 0]] }");
  CHECK(d.message == "prism needs at least 3 points, got 2");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 3);
  d = eval_diagnostic("prism { points = [[0, 0], [1, 0, 2], [0, 1]] }");
  CHECK(d.message == "prism point 2 must be a pair [x, z]");
  d = eval_diagnostic("prism {\n  points = [[0, 0], [1, 0], [0, 1]]\n  height1 = 2  height2 = 2 }");
  CHECK(d.message == "prism height1 and height2 must differ (both are 2)");
  CHECK(d.loc.line() == 3);
  CHECK(d.loc.col() == 16);
  d = eval_diagnostic("prism {\n  points = [[0, 0], [1, 0], [0, 1]]\n  spline = \"bezier\" }");
  CHECK(d.message == "a prism with a bezier spline needs a multiple of 4 points (4 per segment: end, control, "
                     "control, end), got 3");
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 3);
  d = eval_diagnostic("prism {\n  points = [[0, 0], [1, 0], [0, 1]]\n  spline = \"smooth\" }");
  CHECK(d.message == "prism spline \"smooth\" is not one of \"linear\", \"quadratic\", \"cubic\", \"bezier\"");
  CHECK(d.loc.line() == 3);
  CHECK(d.loc.col() == 3);
  d = eval_diagnostic("prism {\n  points = [[0, 1], [0, 0], [1, 0], [0, 1], [1, 1]]\n  spline = \"quadratic\" }");
  CHECK(d.message == "prism: the quadratic outline from point 2 does not close (a later point must repeat point 2)");
  CHECK(d.loc.line() == 2);
  s = eval_text("prism { spline = \"quadratic\"  points = [[0, 1], [0, 0], [1, 0], [0, 1], [0, 0]] }\n");
  CHECK(shape_get<render::Prism>(s.shapes.at(0).geometry)->curves.size() == 3);
  d = eval_diagnostic("prism {\n  points = [[0, 0], [1, 0], [0, 1]]\n  sweep = \"radial\" }");
  CHECK(d.message == "prism sweep \"radial\" is not one of \"linear\" or \"conic\"");
  CHECK(d.loc.line() == 3);
  s = eval_text("prism { points = [[0, 0], [1, 0], [0, 1]]  sweep = \"conic\"  height1 = 0.5 }\n");
  CHECK(shape_get<render::Prism>(s.shapes.at(0).geometry)->conic);
  d = eval_diagnostic("prism { height1 = 0 }");
  CHECK(d.message == "prism needs property 'points'");
  d = eval_diagnostic("difference { prism { points = [[0, 0], [1, 0], [0, 1]]  open = true } sphere { radius = 1 } }");
  CHECK(d.message.find("an uncapped prism cannot be part of 'difference'") != std::string::npos);
}

namespace {

// The picture of `shape` (a block or group in scene units, `k` its scale) over a plane, lit,
// with the camera and light scaled by k too.
render::RenderResult scaled_picture(const std::string& shape, double k) {
  const std::string text = fmt::format(
      "let k = {:.17g}\n"
      "macro rip(p) {{ return length(p) - 0.85 + 0.12 * sin(7 * p.x) * sin(7 * p.y) * sin(7 * p.z) }}\n"
      "let M = material {{ color = rgb(0.85, 0.15, 0.1) specular = 0.6 }}\n"
      "settings {{ width = 32  height = 24  samples = 1  background = rgb(0.1, 0.12, 0.18) }}\n"
      "camera {{ position = <0, 2.2, -7>*k  look_at = <0, 0.8, 0>*k  fov = 30 }}\n"
      "point_light {{ position = <-5, 8, -6>*k }}\n"
      "plane {{ normal = <0, 1, 0>  offset = -1*k  material = material {{ color = rgb(0.75) }} }}\n"
      "group {{ {} }} translate <0, 0.8, 0>*k\n",
      k, shape);
  render::RenderOptions o;
  o.threads = 2;
  return render::render(eval_text(text), o);
}

double worst_difference(const render::RenderResult& a, const render::RenderResult& b) {
  REQUIRE(a.color.rgb.size() == b.color.rgb.size());
  double worst = 0;
  for (std::size_t i = 0; i < a.color.rgb.size(); ++i)
    worst = std::max(worst, std::abs(static_cast<double>(a.color.rgb[i]) - b.color.rgb[i]));
  return worst;
}

}  // namespace

TEST_CASE("POV-Ray's shapes scaled by a transform (1e-150 to 1e150) or their numbers (1e-50 to 1e50) look the same",
          "[shapes][extremes]") {
  // A blob 1e4 units across, or placed with `scale 1e4`, showed holes: its quartic's leading
  // coefficient, (|d| / r)^4, fell below the tolerance that drops it. Sor heights and prism
  // points closer than POV-Ray's absolute 1e-10 were refused or merged at 1e-13 units.
  const std::vector<std::string> by_transform = {
      "blob { threshold = 0.6 spheres = [[<-0.6, 0, 0>, 0.8, 1], [<0.6, 0, 0>, 0.8, 1], [<0, 0.7, 0>, 0.6, 1]] "
      "material = M } scale k",
      "superellipsoid { e = 0.25  n = 0.25 material = M } scale 0.7 rotate <0, 30, 0> scale k",
      "isosurface { function = rip max_gradient = 2.5 contained_by = box { min = <-1, -1, -1>  max = <1, 0.6, 1> } "
      "material = M } scale k",
      "poly { order = 4 coefficients = [1, 0, 0, 0,  0, 0, 0, 0, 0, -5,  0, 0, 0, 0, 0, 0, 0, 0, 0, 0, "
      "1, 0, 0, 0, 0, -5,  0, 0, 0, 0,  1, 0, -5, 0, 11.8] material = M } scale 0.33 scale k",
      "lathe { spline = \"cubic\"  points = [[0.2, -0.8], [0, -0.7], [0.7, -0.65], [0.9, 0], [0.5, 0.5], [0, 1], "
      "[-0.2, 1]] material = M } scale k"};
  const std::vector<std::string> by_numbers = {
      "blob { threshold = 0.6 spheres = [[<-0.6, 0, 0>*k, 0.8*k, 1], [<0.6, 0, 0>*k, 0.8*k, 1], [<0, 0.7, 0>*k, "
      "0.6*k, 1]] cylinders = [[<-1.1, -0.3, 0>*k, <1.1, -0.3, 0>*k, 0.35*k, 1]] material = M }",
      "sor { points = [[0.3*k, -0.2*k], [0.35*k, 0], [0.7*k, 0.5*k], [0.25*k, 1.1*k], [0.3*k, 1.4*k], "
      "[0.45*k, 1.6*k]] material = M }",
      "prism { points = [[-k, -k], [k, -k], [k, k], [-k, k], [-k, -k], [-0.4*k, -0.4*k], [0.4*k, -0.4*k], "
      "[0.4*k, 0.4*k], [-0.4*k, 0.4*k]] height1 = 0  height2 = 0.3*k material = M } rotate <-30, 0, 0>"};
  for (const auto& [shapes, scales] :
       {std::pair{by_transform, std::vector<double>{1e-150, 1e-50, 1e-4, 1e4, 1e50, 1e150}},
        std::pair{by_numbers, std::vector<double>{1e-50, 1e-13, 1e-4, 1e4, 1e13, 1e50}}}) {
    for (const std::string& shape : shapes) {
      const render::RenderResult unit = scaled_picture(shape, 1.0);
      for (double k : scales) {
        INFO(shape << "\nscaled by " << k);
        CHECK(worst_difference(unit, scaled_picture(shape, k)) < 1e-4);
      }
    }
  }
}
