// Group 6, glass: total internal reflection, a light inside glass, a thin shell (radius 1
// inside 1 + 4e-5), and nested dielectrics written with absolute indices (water 1.33 inside
// glass 1.5, diamond 2.42 in water, an air bubble 1.0 in glass): the medium stack makes each
// surface refract by the ratio of its two media. Energy never exceeds the brightest
// emitter, no NaN.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "render/sample/camera.hpp"
#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {

MaterialDesc clear(double ior, bool fresnel = true) {
  MaterialDesc m = matte(Color(1.0));
  m.ambient = 0;
  m.diffuse = 0;
  m.transmit = Color(1.0);
  m.ior = ior;
  m.fresnel = fresnel;
  return m;
}

// One ray at `deg` from vertical down through horizontal layers (glass box y in [-3, 0] with
// a second box inside it at y in [-2, -1]), onto a small emissive disc centred where the
// analytic refraction lands on y = -4. Returns that pixel's value (1 on target, 0 off).
double landing(double deg, const MaterialDesc& outer, const MaterialDesc& inner, double n_inner_absolute) {
  const double theta = deg * M_PI / 180.0;
  const Vec3 dir(std::sin(theta), -std::cos(theta), 0.0);
  const Vec3 origin(0, 5, 0);
  auto tan_in = [&](double n) {
    double s = std::sin(theta) / n;
    return s / std::sqrt(1 - s * s);
  };
  // Snell's invariant n sin(angle) holds across parallel layers: each layer's angle depends
  // only on its own absolute index.
  double x = 5 * std::tan(theta) + tan_in(outer.ior) + tan_in(n_inner_absolute) + tan_in(outer.ior) + std::tan(theta);
  SceneDesc s;
  s.settings.width = 1;
  s.settings.height = 1;
  s.settings.max_depth = 8;
  s.has_camera = true;
  s.camera.projection = Projection::Orthographic;
  s.camera.view_width = 1e-9;
  s.camera.position = origin;
  s.camera.look_at = origin + dir;
  s.camera.up = Vec3(0, 0, 1);
  place(s, add_shape(s, Box{Vec3(-100, -3, -100), Vec3(100, 0, 100)}, add_material(s, outer)));
  place(s, add_shape(s, Box{Vec3(-90, -2, -90), Vec3(90, -1, 90)}, add_material(s, inner)));
  place(s, add_shape(s, Disc{Vec3(x, -4, 0), Vec3(0, 1, 0), 0.01, 0.0}, add_material(s, emissive(Color(1.0)))));
  RenderResult r = render_scene(s);
  return r.color.at(0, 0)[0];
}

}  // namespace

TEST_CASE("nested dielectrics refract by the ratio of absolute indices", "[glass]") {
  struct Case {
    const char* name;
    double outer, inner;
  } cases[] = {{"water 1.33 inside glass 1.5", 1.5, 1.33},
               {"diamond 2.42 inside water 1.33", 1.33, 2.42},
               {"air bubble 1.0 inside glass 1.5", 1.5, 1.0}};
  for (const Case& c : cases)
    for (double deg : {20.0, 35.0}) {
      double v = landing(deg, clear(c.outer, false), clear(c.inner, false), c.inner);
      record("glass", fmt::format("{}, {:g} deg", c.name, deg), "lands on the analytic spot (1 = yes)", v, "1");
      CAPTURE(c.name, deg);
      CHECK(v == Approx(1.0));
    }
  // The pre-medium-stack idiom: the bubble written as the ratio to the glass around it.
  MaterialDesc relative = clear(1.0 / 1.5, false);
  relative.ior_relative = true;
  double v = landing(35.0, clear(1.5, false), relative, 1.0);
  record("glass", "air bubble as ior = 1/1.5 with ior_relative", "lands on the analytic spot (1 = yes)", v, "1");
  CHECK(v == Approx(1.0));
  // Without ior_relative, 1/1.5 is now an absolute index (a medium thinner than vacuum):
  // the spot is missed, which shows the stack really pairs media.
  CHECK(landing(35.0, clear(1.5, false), clear(1.0 / 1.5, false), 1.0) == Approx(0.0));
}

namespace {

// Scenes lit only by a white sky (the background, 1.0): no pixel may exceed it.
SceneDesc sky_scene() {
  SceneDesc s;
  s.settings.width = 64;
  s.settings.height = 48;
  s.settings.max_depth = 12;
  s.settings.background = Color(1.0);
  s.has_camera = true;
  s.camera.position = Vec3(0, 1.0, -4);
  s.camera.look_at = Vec3(0, 0.3, 0);
  MaterialDesc checker = matte(Color(0.6));
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), -1.0}, add_material(s, checker)));
  return s;
}

void check_energy(const SceneDesc& s, const std::string& name, const std::string& file, double brightest) {
  RenderResult r = render_scene(s, 2, true);
  float peak = 0.0f;
  for (float v : r.color.rgb) peak = std::max(peak, v);
  std::string img = save(r.color, file);
  record("glass", name, fmt::format("brightest pixel (emitter {:g})", brightest), peak,
         fmt::format("<= {:g}", brightest), img);
  record("glass", name, "NaN samples", r.stats.rays.nan_samples, "0");
  CAPTURE(name);
  CHECK(peak <= brightest * (1 + 1e-6));
  CHECK(r.stats.rays.nan_samples == 0);
  CHECK(count_non_finite(r.color) == 0);
  for (const auto& [aov, img2] : r.aovs) CHECK(count_non_finite(img2) == 0);
}

}  // namespace

TEST_CASE("glass never returns more light than the brightest emitter", "[glass]") {
  {
    SceneDesc s = sky_scene();
    place(s, add_shape(s, Sphere{Vec3(-0.8, 0.3, 0), 0.7}, add_material(s, clear(1.5))));
    place(s, add_shape(s, Sphere{Vec3(-0.8, 0.3, 0), 0.4}, add_material(s, clear(1.33))));
    place(s, add_shape(s, Sphere{Vec3(0.8, 0.3, 0), 0.7}, add_material(s, clear(1.33))));
    place(s, add_shape(s, Sphere{Vec3(0.8, 0.3, 0), 0.3}, add_material(s, clear(2.42))));
    check_energy(s, "nested: water in glass, diamond in water", "glass_nested", 1.0);
  }
  {
    SceneDesc s = sky_scene();
    place(s, add_shape(s, Sphere{Vec3(0, 0.3, 0), 1.0 + 4e-5}, add_material(s, clear(1.5))));
    place(s, add_shape(s, Sphere{Vec3(0, 0.3, 0), 1.0}, add_material(s, clear(1.0))));
    check_energy(s, "shell: radius 1 inside 1 + 4e-5", "glass_shell", 1.0);
  }
  {
    SceneDesc s = sky_scene();
    place(s, add_shape(s, Sphere{Vec3(0, 0.3, 0), 1.0}, add_material(s, clear(1.5))));
    place(s, add_shape(s, Sphere{Vec3(0.2, 0.4, -0.1), 0.3}, add_material(s, clear(1.0))));
    check_energy(s, "air bubble 1.0 in glass 1.5", "glass_bubble", 1.0);
  }
}

TEST_CASE("a light inside glass: lit through it, no NaN, bounded", "[glass]") {
  SceneDesc s = sky_scene();
  s.settings.background = Color(0.0);
  place(s, add_shape(s, Sphere{Vec3(0, 0.3, 0), 0.8}, add_material(s, clear(1.5))));
  LightDesc l;
  l.position = Vec3(0, 0.3, 0);
  place(s, add_light(s, l));
  RenderResult r = render_scene(s, 2, true);
  // The floor under the sphere is lit through the glass (shadow rays pass transmissive
  // surfaces), so it is brighter than ambient alone.
  double floor_lit = 0;
  auto srgb = to_srgb8(r.color);
  for (int x = 0; x < 64; ++x) floor_lit = std::max<double>(floor_lit, srgb[(47 * 64 + x) * 3]);
  record("glass", "light inside glass", "NaN samples", r.stats.rays.nan_samples, "0",
         save(r.color, "glass_light_inside"));
  record("glass", "light inside glass", "brightest floor pixel of the bottom row (of 255)", floor_lit, "> 40");
  CHECK(r.stats.rays.nan_samples == 0);
  CHECK(floor_lit > 40);
}

TEST_CASE("total internal reflection: no light beyond the critical angle", "[glass]") {
  // The camera inside a glass slab (y in [-1, 1]) looks up at its top face under a white sky:
  // rays steeper than the critical angle (41.8 degrees) see the sky; flatter ones are trapped
  // by total internal reflection between the faces and see nothing.
  SceneDesc s;
  s.settings.width = 1;
  s.settings.height = 48;
  s.settings.max_depth = 40;
  s.settings.background = Color(1.0);
  s.has_camera = true;
  s.camera.fov = 100;
  s.camera.position = Vec3(0, 0, 0);
  s.camera.look_at = Vec3(0, std::tan(45 * M_PI / 180), 1);  // 45 degrees up
  MaterialDesc glass = clear(1.5);
  place(s, add_shape(s, Box{Vec3(-1e4, -1, -1e4), Vec3(1e4, 1, 1e4)}, add_material(s, glass)));
  RenderResult r = render_scene(s);
  Camera cam(s.camera, 1, 48);
  int wrong = 0, counted = 0;
  const double critical = std::asin(1 / 1.5);
  for (int y = 0; y < 48; ++y) {
    Vec3 d = glm::normalize(cam.generate(0.5, y + 0.5, glm::dvec2(0.5)).direction);
    double incidence = std::acos(std::abs(d.y));
    if (std::abs(incidence - critical) < 0.02) continue;  // Schlick's rim
    ++counted;
    float v = r.color.at(0, y)[0];
    bool escapes = incidence < critical;
    if (escapes ? !(v > 0.5f) : !(v < 1e-3f)) ++wrong;
  }
  record("glass", "total internal reflection", fmt::format("rows off the analytic critical angle (of {})", counted),
         wrong, "0");
  CHECK(wrong == 0);
}
