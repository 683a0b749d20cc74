// Extreme scales and degenerate inputs: each must either render with no NaN or infinite pixel
// (and no NaN sample), or be reported as a located SceneError (scene building) or RenderError
// (rendering) with a clear message. Nothing may crash or abort.
#include <cmath>
#include <functional>
#include <string>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "render/renderer.hpp"
#include "render/builder/scene_builder.hpp"
#include "render/sample/camera.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

const char* const kFile = "extreme.rts";
SourceRef at(uint32_t line, uint32_t col = 1) { return SourceRef{kFile, line, col}; }

// A small lit scene with a floor and a shiny material that exercises every secondary ray.
SceneDesc base_scene() {
  SceneDesc s;
  s.settings.width = 24;
  s.settings.height = 18;
  s.settings.samples = 2;
  s.has_camera = true;
  s.camera.position = Vec3(0, 1, -5);
  s.camera.look_at = Vec3(0, 0.5, 0);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}));
  LightDesc l;
  l.position = Vec3(3, 6, -4);
  place(s, add_light(s, l));
  return s;
}

MaterialId shiny(SceneDesc& s) {
  MaterialDesc m;
  m.reflect = Color(0.4);
  m.transmit = Color(0.5);
  m.ior = 1.5;
  m.fresnel = true;
  m.specular = 0.8;
  return add_material(s, m);
}

void require_clean_render(const SceneDesc& s) {
  RenderOptions o;
  o.threads = 2;
  o.aovs = {"normal", "depth", "albedo"};
  RenderResult r = render(s, o);
  for (float v : r.color.rgb) REQUIRE(std::isfinite(v));
  for (const auto& [name, img] : r.aovs) {
    CAPTURE(name);
    for (float v : img.rgb) REQUIRE(std::isfinite(v));
  }
  CHECK(r.stats.rays.nan_samples == 0);
}

// The RenderError's message and location, or "(no error)".
std::string render_error(const SceneDesc& s, SourceRef* where = nullptr) {
  try {
    RenderOptions o;
    o.threads = 2;
    render(s, o);
  } catch (const RenderError& e) {
    if (where) *where = e.where;
    return e.what();
  }
  return "(no error)";
}

std::string scene_error(const std::function<void()>& f, SourceRef* where = nullptr) {
  try {
    f();
  } catch (const SceneError& e) {
    if (where) *where = e.where;
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("extreme sphere radii render without NaN", "[extremes]") {
  SECTION("radius 1e-8, seen up close") {
    SceneDesc s = base_scene();
    s.camera.position = Vec3(0, 0.5, -5e-8);
    s.camera.look_at = Vec3(0, 0.5, 0);
    place(s, add_shape(s, Sphere{Vec3(0, 0.5, 0), 1e-8}, shiny(s)));
    require_clean_render(s);
  }
  SECTION("radius 1e-8 among normal objects") {
    SceneDesc s = base_scene();
    place(s, add_shape(s, Sphere{Vec3(0, 0.5, 0), 1e-8}, shiny(s)));
    place(s, add_shape(s, Sphere{Vec3(1, 0.5, 0), 0.5}, shiny(s)));
    require_clean_render(s);
  }
  SECTION("radius 1e8, camera outside") {
    SceneDesc s = base_scene();
    place(s, add_shape(s, Sphere{Vec3(0, 0, 1e8 + 10), 1e8}, shiny(s)));
    require_clean_render(s);
  }
  SECTION("radius 1e8, camera inside") {
    SceneDesc s = base_scene();
    place(s, add_shape(s, Sphere{Vec3(0), 1e8}, shiny(s)));
    require_clean_render(s);
  }
}

TEST_CASE("degenerate shapes render without NaN", "[extremes]") {
  SceneDesc s = base_scene();
  MaterialId m = shiny(s);
  place(s, add_shape(s, triangle(Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(1, 2, 0)), m));   // zero area (collinear)
  Triangle smooth = triangle(Vec3(0.3), Vec3(0.3), Vec3(0.3));                        // a point, with normals
  smooth.normals = Boxed<TriangleNormals>(TriangleNormals{Vec3(0.0), Vec3(0.0), Vec3(0.0)});
  place(s, add_shape(s, smooth, m));
  place(s, add_shape(s, Cylinder{Vec3(0, 0.5, 0), Vec3(0, 0.5, 0), 1.0, true}, m));    // from == to
  place(s, add_shape(s, Cylinder{Vec3(0, 0.5, 0), Vec3(0, 0.5, 0), 1.0, false}, m));
  place(s, add_shape(s, Box{Vec3(1), Vec3(-1)}, m));                                 // min > max
  place(s, add_shape(s, Box{Vec3(0.5, 0, 0), Vec3(0.5, 1, 1)}, m));                  // zero thickness
  require_clean_render(s);
}

TEST_CASE("degenerate cameras render without NaN", "[extremes]") {
  SECTION("position == look_at") {
    SceneDesc s = base_scene();
    place(s, add_shape(s, Sphere{Vec3(0, 0.5, 2), 0.5}, shiny(s)));
    s.camera.look_at = s.camera.position;
    require_clean_render(s);
  }
  SECTION("up parallel to the view direction") {
    SceneDesc s = base_scene();
    place(s, add_shape(s, Sphere{Vec3(0, 0.5, 0), 0.5}, shiny(s)));
    s.camera.position = Vec3(0, 5, 0);
    s.camera.look_at = Vec3(0, 0, 0);
    s.camera.up = Vec3(0, 1, 0);
    require_clean_render(s);
    s.camera.up = Vec3(0);  // no up at all
    require_clean_render(s);
  }
}

TEST_CASE("singular and non-finite transforms are located render errors", "[extremes]") {
  SceneDesc s = base_scene();
  s.roots.clear();
  NodeId ball = add_shape(s, Sphere{Vec3(0), 1.0}, shiny(s));
  SECTION("scale 0 on a placed shape") {
    s.roots.push_back(Child{ball, scale(Vec3(0)), at(7, 3)});
  }
  SECTION("one flattened axis") {
    s.roots.push_back(Child{ball, scale(Vec3(1, 0, 1)), at(7, 3)});
  }
  SECTION("tiny scales whose product underflows to 0") {
    // (1e-100 twice is 1e-200, a small scale but not a singular one: the scaled scenes below.)
    NodeId g = add_group(s, {Child{ball, scale(Vec3(1e-200)), at(7, 3)}});
    s.roots.push_back(Child{g, scale(Vec3(1e-200)), at(9, 1)});
  }
  SECTION("scale 0 on a group holding a light") {
    LightDesc l;
    l.kind = LightKind::Directional;
    NodeId g = add_group(s, {Child{add_light(s, l), Mat4(1.0), at(7, 3)}});
    s.roots.push_back(Child{g, scale(Vec3(0)), at(9, 1)});
  }
  SourceRef where;
  std::string msg = render_error(s, &where);
  CHECK(msg == "transform is singular (scale 0?)");
  CHECK(std::string(where.file) == kFile);
  CHECK(where.line == 7);
  CHECK(where.col == 3);
}

TEST_CASE("an infinite composed scale is a located render error", "[extremes]") {
  SceneDesc s = base_scene();
  NodeId ball = add_shape(s, Sphere{Vec3(0), 1.0});
  NodeId g = add_group(s, {Child{ball, scale(Vec3(1e200)), at(7, 3)}});
  s.roots.push_back(Child{g, scale(Vec3(1e200)), at(9, 1)});
  SourceRef where;
  CHECK_THAT(render_error(s, &where), Catch::Contains("transform is not finite"));
  CHECK(where.line == 7);
}

TEST_CASE("the scene builder rejects degenerate shapes and cameras with located errors", "[extremes]") {
  SceneBuilder b;
  SourceRef where;
  {
    ParamSet p("cylinder", at(3));
    p.add("from", Vec3(1, 2, 3), at(3, 12));
    p.add("to", Vec3(1, 2, 3), at(3, 30));
    p.add("radius", 1.0, at(3, 50));
    CHECK_THAT(scene_error([&] { b.shape("cylinder", p); }, &where), Catch::Contains("'to' of cylinder must differ from 'from'"));
    CHECK(where.line == 3);
    CHECK(where.col == 30);
  }
  {
    ParamSet p("box", at(4));
    p.add("min", Vec3(1), at(4, 7));
    p.add("max", Vec3(-1), at(4, 20));
    CHECK_THAT(scene_error([&] { b.shape("box", p); }, &where), Catch::Contains("max must be >= min"));
    CHECK(where.line == 4);
    CHECK(where.col == 20);
  }
  {
    ParamSet p("triangle", at(5));
    p.add("v0", Vec3(0), at(5, 12));
    p.add("v1", Vec3(1), at(5, 24));
    p.add("v2", Vec3(2), at(5, 36));
    CHECK_NOTHROW(b.shape("triangle", p));  // zero area: allowed, never hit (rendered above)
  }
  {
    ParamSet p("camera", at(6));
    p.add("position", Vec3(0, 1, 0), at(6, 10));
    p.add("look_at", Vec3(0, 1, 0), at(6, 30));
    CHECK_THAT(scene_error([&] { b.camera(p); }, &where), Catch::Contains("position and look_at must differ"));
    CHECK(where.line == 6);
  }
  {
    ParamSet p("camera", at(8));
    p.add("position", Vec3(0, 5, 0), at(8, 10));
    p.add("look_at", Vec3(0), at(8, 30));
    p.add("up", Vec3(0, 2, 0), at(8, 50));
    CHECK_THAT(scene_error([&] { b.camera(p); }, &where), Catch::Contains("up must not be parallel"));
    CHECK(where.line == 8);
  }
  {
    ParamSet p("sphere", at(9));
    p.add("radius", 1e-8, at(9, 10));
    CHECK_NOTHROW(b.shape("sphere", p));
    ParamSet q("sphere", at(10));
    q.add("radius", 1e8, at(10, 10));
    CHECK_NOTHROW(b.shape("sphere", q));
  }
}

TEST_CASE("a camera far past the squares' range keeps its direction", "[extremes]") {
  // |look_at - position|^2 overflows past about 1e154: glm::normalize then gave a zero
  // forward vector (rays without a direction) and the builder called up parallel to it.
  for (double d : {1e200, 1e-200}) {
    CAPTURE(d);
    CameraDesc desc;
    desc.position = Vec3(0, 0, -d);
    desc.look_at = Vec3(0, 0, 0);
    desc.up = Vec3(0, d, 0);
    Camera camera(desc, 64, 48);
    const Ray centre = camera.generate(32, 24, glm::dvec2(0.5));
    CHECK(centre.direction.x == Approx(0.0).margin(1e-12));
    CHECK(centre.direction.y == Approx(0.0).margin(1e-12));
    CHECK(centre.direction.z == Approx(1.0));
    const Ray top = camera.generate(32, 0, glm::dvec2(0.5));
    CHECK(top.direction.y > 0.1);  // up is still up
  }
  SceneBuilder b;
  ParamSet p("camera", at(2));
  p.add("position", Vec3(0, 0, -1e200), at(2, 10));
  p.add("look_at", Vec3(0), at(2, 40));
  CHECK(scene_error([&] { b.camera(p); }) == "(no error)");
}

TEST_CASE("the builder takes a scene modelled at 1e-13 or 1e-100 units: only equal points are refused", "[extremes]") {
  // Lengths were refused below an absolute 1e-12 ("must be a non-zero vector", "position and
  // look_at must differ"), so a scene in femtometres could not be described at all.
  for (double k : {1e-13, 1e-100}) {
    CAPTURE(k);
    SceneBuilder b;
    ParamSet cam("camera", at(1));
    cam.add("position", Vec3(0, 1, -3) * k, at(1, 10));
    cam.add("look_at", Vec3(0), at(1, 40));
    CHECK(scene_error([&] { b.camera(cam); }) == "(no error)");
    ParamSet cyl("cylinder", at(2));
    cyl.add("from", Vec3(0), at(2, 10));
    cyl.add("to", Vec3(0, 1, 0) * k, at(2, 30));
    cyl.add("radius", 0.5 * k, at(2, 50));
    CHECK(scene_error([&] { b.shape("cylinder", cyl); }) == "(no error)");
    ParamSet quad("quad", at(3));
    quad.add("edge_u", Vec3(1, 0, 0) * k, at(3, 10));
    quad.add("edge_v", Vec3(0, 1, 0) * k, at(3, 30));
    CHECK(scene_error([&] { b.shape("quad", quad); }) == "(no error)");
    ParamSet plane("plane", at(4));
    plane.add("normal", Vec3(0, 2, 0) * k, at(4, 10));
    CHECK(scene_error([&] { b.shape("plane", plane); }) == "(no error)");
    ParamSet spot("spot_light", at(5));
    spot.add("position", Vec3(0, 4, 0) * k, at(5, 10));
    spot.add("point_at", Vec3(0), at(5, 30));
    CHECK(scene_error([&] { b.light("spot_light", spot); }) == "(no error)");
    const SceneDesc& s = b.scene();
    REQUIRE(s.shapes.size() == 3);
    REQUIRE(s.shapes[2].geometry.holds<Plane>());
    CHECK(shape_get<Plane>(s.shapes[2].geometry).normal.y == 1.0);  // normalised without underflow
  }
  SceneBuilder b;
  ParamSet cam("camera", at(1));
  cam.add("position", Vec3(1e-100), at(1, 10));
  cam.add("look_at", Vec3(1e-100), at(1, 40));
  CHECK_THAT(scene_error([&] { b.camera(cam); }), Catch::Contains("position and look_at must differ"));
}

TEST_CASE("a scene scaled by 1e-150 to 1e150 renders the unit scene's image", "[extremes]") {
  // Every square the tests take (|oc|^2, slab products, edge functions) stays finite and
  // normal from about 1e-154 to 1e154; the tests whose terms are cubes or fourth powers (a
  // triangle's depth, a quad's dual basis, a torus's quartic, a transform's inverse) rescale
  // by a power of two outside 1e+-30..1e+-90. So the same shapes, light and camera, scaled,
  // must give the same picture (the point light has no falloff in Whitted mode, so its
  // intensity needs no scale).
  auto scene = [](double k, int which) {
    SceneDesc s;
    s.settings.width = 32;
    s.settings.height = 24;
    s.settings.samples = 1;
    s.has_camera = true;
    s.camera.position = Vec3(0, 1, -3) * k;
    s.camera.look_at = Vec3(0);
    MaterialDesc red;
    red.color = Color(1, 0.2, 0.2);
    red.specular = 0.5;
    red.reflect = Color(0.3);
    MaterialDesc grey;
    grey.color = Color(0.8);
    const MaterialId r = add_material(s, red), g = add_material(s, grey);
    place(s, add_shape(s, Plane{Vec3(0, 1, 0), -k}, g));
    LightDesc l;
    l.position = Vec3(-2, 4, -3) * k;
    place(s, add_light(s, l));
    switch (which) {
      case 0:
        place(s, add_shape(s, Sphere{Vec3(0), k}, r));
        place(s, add_shape(s, Box{Vec3(1.5, -1, -0.5) * k, Vec3(2.5, 0, 0.5) * k}, g));
        break;
      case 1:
        place(s, add_shape(s, Triangle{Vec3(-2, -1, 1) * k, Vec3(1, -1, 1.5) * k, Vec3(-0.5, 1.2, 1) * k, {}}, r));
        place(s, add_shape(s, Quad{Vec3(0.5, -1, 0) * k, Vec3(1.5, 0, 0.4) * k, Vec3(0, 1.4, 0) * k}, g));
        break;
      case 2:
        place(s, add_shape(s, Cylinder{Vec3(-2, -1, 0) * k, Vec3(-1, 0.5, 0.5) * k, 0.4 * k, true}, r));
        place(s, add_shape(s, Cone{Vec3(0, -1, 0) * k, Vec3(0.5, 0.8, 0) * k, 0.6 * k, 0.1 * k, true}, g));
        place(s, add_shape(s, Disc{Vec3(1.6, 0, 0.5) * k, Vec3(0, 0.3, -1), 0.7 * k, 0.2 * k}, r));
        break;
      default:  // a torus sized by its radii, and one and a sphere sized by a transform
        place(s, add_shape(s, Torus{0.6 * k, 0.2 * k}, r),
              glm::translate(Mat4(1.0), Vec3(-1.5, -0.3, 0) * k) * glm::rotate(Mat4(1.0), 1.0, Vec3(1, 0, 0)));
        place(s, add_shape(s, Torus{0.6, 0.2}, g),
              glm::translate(Mat4(1.0), Vec3(0.2, 0, 0) * k) * glm::scale(Mat4(1.0), Vec3(k)));
        place(s, add_shape(s, Sphere{Vec3(0), 1.0}, r),
              glm::translate(Mat4(1.0), Vec3(1.8, -0.5, 0) * k) * glm::scale(Mat4(1.0), Vec3(0.5, 0.25, 0.5) * k));
        break;
    }
    return s;
  };
  RenderOptions o;
  o.threads = 2;
  for (int which = 0; which < 4; ++which) {
    const RenderResult unit = render(scene(1.0, which), o);
    double lit = 0;
    for (float v : unit.color.rgb) lit = std::max(lit, static_cast<double>(v));
    REQUIRE(lit > 0.3);  // the shapes are in view and lit
    for (double k : {1e-150, 1e-100, 1e-50, 1e-13, 1e50, 1e100, 1e150}) {
      INFO("shapes " << which << ", scale 1e" << std::lround(std::log10(k)));
      const RenderResult scaled = render(scene(k, which), o);
      REQUIRE(scaled.color.rgb.size() == unit.color.rgb.size());
      double worst = 0;
      for (std::size_t i = 0; i < unit.color.rgb.size(); ++i)
        worst = std::max(worst, std::abs(static_cast<double>(scaled.color.rgb[i]) - unit.color.rgb[i]));
      CHECK(worst < 1e-4);  // radiance ~0.1-1: the same picture up to the float image's rounding
    }
  }
}
