// Group 1, scale and offset sweep: one scene (spheres, a mesh, a plane, shadows, a mirror and
// glass) rendered at scales 1e-6..1e6 and translated by 1e5, 1e7, 1e9, 1e11 (camera and lights
// moved with it), written with literal coordinates and through a group transform. Each
// image must match the unit-scale one: at most 0.1% of pixels differ by more than 8/255.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {

enum class Mode { Literal, Group };

SceneDesc sweep_scene(double k, Vec3 t, Mode mode) {
  // Literal mode writes every coordinate as t + k * p; group mode writes the unit scene and
  // places it with translate(t) * scale(k).
  const bool lit = mode == Mode::Literal;
  auto P = [&](Vec3 p) { return lit ? t + k * p : p; };
  auto L = [&](double len) { return lit ? k * len : len; };
  SceneDesc s;
  s.settings.width = 64;
  s.settings.height = 48;
  s.settings.background = Color(0.2, 0.3, 0.5);
  s.has_camera = true;
  s.camera.position = t + k * Vec3(0, 2, -6);
  s.camera.look_at = t + k * Vec3(0, 0.5, 0);
  std::vector<Child> kids;
  auto put = [&](NodeId n) {
    if (lit)
      place(s, n);
    else
      kids.push_back(Child{n, Mat4(1.0), {}});
  };
  MaterialDesc floor = matte(Color(0.7, 0.7, 0.6));
  MaterialDesc mirror = matte(Color(0.1));
  mirror.reflect = Color(0.8);
  MaterialDesc glass = matte(Color(1.0));
  glass.diffuse = 0.05;
  glass.transmit = Color(0.95);
  glass.ior = 1.5;
  glass.fresnel = true;
  put(add_shape(s, Plane{Vec3(0, 1, 0), lit ? t.y : 0.0}, add_material(s, floor)));
  put(add_shape(s, Sphere{P(Vec3(-1.3, 0.5, 0)), L(0.5)}, add_material(s, matte(Color(0.8, 0.2, 0.2)))));
  put(add_shape(s, Sphere{P(Vec3(0.1, 0.6, 1.2)), L(0.6)}, add_material(s, mirror)));
  put(add_shape(s, Sphere{P(Vec3(1.3, 0.5, -0.4)), L(0.5)}, add_material(s, glass)));
  put(add_shape(s, Box{P(Vec3(1.6, 0, 1.2)), P(Vec3(2.4, 0.9, 2.0))}, add_material(s, matte(Color(0.3, 0.7, 0.3)))));
  auto mesh = uv_sphere_mesh(Vec3(0, 0.45, -1.4), 0.45, 12, 24);
  if (lit) {  // the literal vertices, stored as the scene builder stores them
    auto moved = std::make_shared<MeshData>(*mesh);
    Vec3 origin = t + k * mesh->origin;
    moved->origin = origin;
    for (auto& p : moved->positions) p = glm::vec3(k * Vec3(p));
    mesh = moved;
  }
  put(add_mesh(s, mesh, add_material(s, matte(Color(0.9, 0.8, 0.2)))));
  LightDesc l;
  l.position = P(Vec3(3, 6, -4));
  put(add_light(s, l));
  LightDesc fill;
  fill.position = P(Vec3(-4, 3, -3));
  fill.intensity = 0.4;
  put(add_light(s, fill));
  if (!lit) place(s, add_group(s, kids), translate(t) * scale(k));
  return s;
}

void check_against_unit(const Image& unit, double k, Vec3 t, Mode mode, const std::string& label) {
  RenderResult r = render_scene(sweep_scene(k, t, mode));
  double diff = differing_fraction(unit, r.color);
  std::string name = fmt::format("{} {}", label, mode == Mode::Literal ? "literal" : "group");
  std::string file = fmt::format("scale_{}_{}", label, mode == Mode::Literal ? "literal" : "group");
  for (char& c : file)
    if (c == ' ' || c == '+') c = '_';
  std::string img = save(r.color, file);
  record("scale", name, "differing pixels (fraction > 8/255)", diff, "<= 0.001", img);
  record("scale", name, "NaN samples", static_cast<double>(r.stats.rays.nan_samples), "0");
  CAPTURE(name);
  CHECK(diff <= 0.001);
  CHECK(r.stats.rays.nan_samples == 0);
}

}  // namespace

TEST_CASE("scale sweep: every scale from 1e-6 to 1e6 matches the unit-scale image", "[scale]") {
  RenderResult unit = render_scene(sweep_scene(1.0, Vec3(0.0), Mode::Literal));
  record("scale", "unit", "reference", 0, "", save(unit.color, "scale_unit"));
  for (double k : {1e-6, 1e-4, 1e-2, 1e2, 1e4, 1e6})
    for (Mode mode : {Mode::Literal, Mode::Group}) check_against_unit(unit.color, k, Vec3(0.0), mode, fmt::format("scale {:g}", k));
}

TEST_CASE("offset sweep: the scene translated by 1e5, 1e7, 1e9 and 1e11 matches it at the origin", "[scale]") {
  // Failures 4 and 5 of issue 8: float mesh vertices became a blob at 1e7, and 1e-9*|p| ray
  // offsets changed 0.5% of the pixels there. At 1e11 coordinates round at 1e-5 units (this
  // scene has no surfaces closer than the tie; test_csg.cpp's die far away is the one whose
  // thin pips a coarser coincidence tie lost).
  RenderResult unit = render_scene(sweep_scene(1.0, Vec3(0.0), Mode::Literal));
  for (double d : {1e5, 1e7, 1e9, 1e11})
    for (Mode mode : {Mode::Literal, Mode::Group})
      check_against_unit(unit.color, 1.0, Vec3(d, d, -d), mode, fmt::format("translate {:g}", d));
}

TEST_CASE("a quad facing its light is lit at every camera distance and scale", "[scale]") {
  // Issue 16: a quad's hit carried no error bound, so its shadow rays started inside the
  // rounding of the hit point and a wall facing a point light shadowed itself (ambient only)
  // with the camera at z = -3.4 and was lit at z = -3.35. The centre pixel must be lit
  // (diffuse 0.7 * 0.8 plus ambient 0.08, against 0.08 when shadowed) for every distance and
  // at scales 1e-4 to 1e4, with the scene written in literal coordinates.
  int shadowed = 0, cases = 0;
  for (double k : {1e-4, 1e-2, 1.0, 1e2, 1e4}) {
    for (double z : {-3.5, -3.45, -3.4, -3.35, -3.3, -2.0, -6.0}) {
      SceneDesc s;
      s.settings.width = 9;
      s.settings.height = 9;
      s.has_camera = true;
      s.camera.position = k * Vec3(0, 1, z);
      s.camera.look_at = k * Vec3(0, 1, 0);
      place(s, add_shape(s, Quad{k * Vec3(-1, 0, 1), k * Vec3(2, 0, 0), k * Vec3(0, 2, 0)},
                         add_material(s, matte(Color(0.8)))));
      LightDesc l;
      l.position = k * Vec3(0, 1, -2);
      place(s, add_light(s, l));
      RenderResult r = render_scene(s, 1);
      const float centre = r.color.at(4, 4)[1];
      ++cases;
      if (!(centre > 0.3f)) ++shadowed;
      CAPTURE(k, z, centre);
      CHECK(centre > 0.3f);
    }
  }
  record("scale", "quad wall facing its light", "shadowed centre pixels", shadowed, "0");
  CHECK(cases == 35);
}
