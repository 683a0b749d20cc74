// Group 11, the path tracer (issue 19): a room with an emissive quad, glass, a mirror and an
// albedo-1 wall, rendered at scales 1e-6..1e6 and moved 1e5, 1e7 and 1e9 away; grazing views; degenerate
// emitters (zero-area quad, zero-radius sphere, emission 1e30); a closed albedo-1 box. No
// NaN or infinite pixel, no NaN sample, and the scaled images' means agree with the
// unit-scale one within 5 standard errors (their own estimates; a false failure about once
// in 1.7 million comparisons).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>

#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {

MaterialDesc lambert(Color albedo) {
  MaterialDesc m = matte(albedo);
  m.diffuse = 1.0;
  m.specular = 0.0;
  return m;
}

SceneDesc room(double k, Vec3 t) {
  SceneDesc s;
  s.settings.width = 32;
  s.settings.height = 24;
  s.settings.samples = 16;
  s.settings.max_depth = 6;
  s.settings.integrator = IntegratorKind::Path;
  s.settings.background = Color(0.1, 0.12, 0.15);
  s.has_camera = true;
  s.camera.position = t + k * Vec3(0, 1, -3.5);
  s.camera.look_at = t + k * Vec3(0, 0.8, 0);
  std::vector<Child> kids;
  auto put = [&](NodeId n) { kids.push_back(Child{n, Mat4(1.0), {}}); };
  put(add_shape(s, Quad{Vec3(-2, 0, -2), Vec3(4, 0, 0), Vec3(0, 0, 4)}, add_material(s, lambert(Color(0.7)))));
  put(add_shape(s, Quad{Vec3(-2, 0, 2), Vec3(4, 0, 0), Vec3(0, 3, 0)}, add_material(s, lambert(Color(1.0)))));
  put(add_shape(s, Quad{Vec3(-0.5, 2.5, -0.5), Vec3(1, 0, 0), Vec3(0, 0, 1)}, add_material(s, emissive(Color(8.0)))));
  MaterialDesc glass = lambert(Color(1.0));
  glass.diffuse = 0.0;
  glass.transmit = Color(1.0);
  glass.ior = 1.5;
  put(add_shape(s, Sphere{Vec3(-0.7, 0.5, 0), 0.5}, add_material(s, glass)));
  MaterialDesc mirror = lambert(Color(0.0));
  mirror.diffuse = 0.0;
  mirror.reflect = Color(0.9);
  put(add_shape(s, Sphere{Vec3(0.7, 0.5, 0.3), 0.5}, add_material(s, mirror)));
  place(s, add_group(s, kids), translate(t) * scale(k));
  return s;
}

// Image mean (all channels) and its standard error from the per-pixel variance estimates.
std::pair<double, double> mean_and_error(const RenderResult& r) {
  double sum = 0, var = 0;
  const std::size_t n = r.color.rgb.size();
  for (std::size_t i = 0; i < n; ++i) {
    sum += r.color.rgb[i];
    var += std::max(0.0f, r.stats.pixels.variance[i]);
  }
  return {sum / static_cast<double>(n), std::sqrt(var) / static_cast<double>(n)};
}

void check_finite(const RenderResult& r, const std::string& name, const std::string& file) {
  std::string img = save(r.color, file);
  const int non_finite = count_non_finite(r.color);
  record("path", name, "NaN/Inf pixels", non_finite, "0", img);
  record("path", name, "NaN samples", static_cast<double>(r.stats.rays.nan_samples), "0");
  CAPTURE(name);
  CHECK(non_finite == 0);
  CHECK(r.stats.rays.nan_samples == 0);
}

}  // namespace

TEST_CASE("path tracing at scales 1e-6..1e6 and 1e5..1e9 away: finite, same brightness", "[path]") {
  // Moved 1e7 and 1e9 (until 2026-12-01): shadow rays towards the lamp stopped at 1e-9 of its
  // distance short of it, measured from the shading point, while their origin had moved about
  // 1e-14 of its distance from the world origin towards it: the lamp shadowed the floor it lit.
  const RenderResult unit = render_scene(room(1.0, Vec3(0.0)));
  const auto [m0, e0] = mean_and_error(unit);
  check_finite(unit, "unit scale", "path_unit");
  REQUIRE(m0 > 0.05);
  struct Case {
    const char* name;
    double k;
    Vec3 t;
  };
  for (const Case& c : {Case{"scale 1e-6", 1e-6, Vec3(0.0)}, Case{"scale 1e6", 1e6, Vec3(0.0)},
                        Case{"moved 1e5", 1.0, Vec3(1e5, -1e5, 1e5)}, Case{"moved 1e7", 1.0, Vec3(-1e7, 1e7, 1e7)},
                        Case{"moved 1e9", 1.0, Vec3(1e9, 1e9, -1e9)}}) {
    SceneDesc s = room(c.k, c.t);
    s.settings.seed = 7;  // an independent render, so the z-test below compares two estimates
    const RenderResult r = render_scene(s);
    std::string file = fmt::format("path_{}", c.name);
    for (char& ch : file)
      if (ch == ' ' || ch == '-') ch = '_';
    check_finite(r, c.name, file);
    const auto [m, e] = mean_and_error(r);
    const double z = (m - m0) / std::sqrt(e * e + e0 * e0);
    record("path", c.name, "image mean vs unit scale (z)", z, "|z| < 5");
    CAPTURE(c.name, m, m0, e, e0);
    CHECK(std::abs(z) < 5.0);
  }
}

TEST_CASE("path tracing: grazing views, degenerate emitters, emission 1e30 and albedo 1", "[path]") {
  SECTION("camera grazing a lit floor") {
    SceneDesc s = room(1.0, Vec3(0.0));
    s.camera.position = Vec3(0, 1e-7, -1.9);
    s.camera.look_at = Vec3(0, 1e-7, 2);
    check_finite(render_scene(s), "grazing camera", "path_grazing");
  }
  SECTION("zero-area quad, zero-radius sphere and emission 1e30") {
    SceneDesc s = room(1.0, Vec3(0.0));
    place(s, add_shape(s, Quad{Vec3(1, 1, 1), Vec3(0.5, 0, 0), Vec3(1.0, 0, 0)}, add_material(s, emissive(Color(5.0)))));
    place(s, add_shape(s, Sphere{Vec3(-1, 2, 1), 0.0}, add_material(s, emissive(Color(5.0)))));
    place(s, add_shape(s, Sphere{Vec3(1.5, 2, 1.5), 0.05}, add_material(s, emissive(Color(1e30)))));
    const RenderResult r = render_scene(s);
    check_finite(r, "degenerate emitters", "path_degenerate");
  }
  SECTION("a closed albedo-1 box lit from inside") {
    SceneDesc s;
    s.settings.width = 16;
    s.settings.height = 16;
    s.settings.samples = 8;
    s.settings.max_depth = 200;
    s.settings.integrator = IntegratorKind::Path;
    s.has_camera = true;
    s.camera.position = Vec3(0, 0, -0.5);
    s.camera.look_at = Vec3(0, 0, 1);
    place(s, add_shape(s, Box{Vec3(-1), Vec3(1)}, add_material(s, lambert(Color(1.0)))));
    place(s, add_shape(s, Sphere{Vec3(0, 0.5, 0), 0.1}, add_material(s, emissive(Color(1.0)))));
    const RenderResult r = render_scene(s);
    check_finite(r, "albedo-1 box", "path_albedo_one");
    // Every bounce keeps all the light: no path can carry more than (max_depth + 1) times the
    // emitted radiance.
    for (float v : r.color.rgb) CHECK(v <= 201.0f);
  }
}
