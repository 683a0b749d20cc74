// Group 4, tiny and huge: a sphere of radius 1e-3 at distance 1e4 covers the analytic pixel
// count; a planet of radius 1e6 seen from 1 unit above its surface has the analytic horizon
// and no acne (every lit pixel within 8/255 of the analytic Lambert shading).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "render/sample/camera.hpp"
#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {
const Color kBackground(0.0, 0.0, 1.0);
bool is_background(const Image& img, int x, int y) {
  return img.at(x, y)[2] == 1.0f && img.at(x, y)[0] == 0.0f && img.at(x, y)[1] == 0.0f;
}
// Distance from `c` to the ray's line, in long double (the analytic reference).
long double line_distance(const Ray& ray, Vec3 c) {
  long double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
  long double len = std::sqrt(dx * dx + dy * dy + dz * dz);
  dx /= len, dy /= len, dz /= len;
  long double fx = (long double)c.x - ray.origin.x, fy = (long double)c.y - ray.origin.y,
              fz = (long double)c.z - ray.origin.z;
  long double t = fx * dx + fy * dy + fz * dz;
  long double px = fx - t * dx, py = fy - t * dy, pz = fz - t * dz;
  return std::sqrt(px * px + py * py + pz * pz);
}
}  // namespace

TEST_CASE("a sphere of radius 1e-3 at distance 1e4 covers the analytic pixel count", "[tiny_huge]") {
  const int size = 64;
  const double r = 1e-3, dist = 1e4;
  SceneDesc s;
  s.settings.width = size;
  s.settings.height = size;
  s.settings.background = kBackground;
  s.has_camera = true;
  s.camera.position = Vec3(0, 0, -dist);
  s.camera.look_at = Vec3(0.0);
  // The sphere spans ~70% of the view.
  s.camera.fov = 2.0 * std::atan(1.4 * r / dist) * 180.0 / M_PI;
  Vec3 centre(0.11 * r, -0.07 * r, 0.0);
  place(s, add_shape(s, Sphere{centre, r}, add_material(s, matte(Color(0.8)))));
  RenderResult res = render_scene(s);
  Camera cam(s.camera, size, size);
  int expected = 0, got = 0, ambiguous = 0, mismatches = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      long double d = line_distance(cam.generate(x + 0.5, y + 0.5, glm::dvec2(0.5)), centre);
      bool hit = !is_background(res.color, x, y);
      got += hit;
      if (std::abs(d - r) < 1e-9L * r) {
        ++ambiguous;
        continue;
      }
      expected += d < r;
      if ((d < r) != hit) ++mismatches;
    }
  record("tiny_huge", "sphere r=1e-3 at 1e4", fmt::format("pixels covered (analytic {})", expected), got,
         fmt::format("{} (+{} tangent)", expected, ambiguous), save(res.color, "tiny_sphere"));
  record("tiny_huge", "sphere r=1e-3 at 1e4", "pixels off the analytic disc", mismatches, "0");
  CHECK(mismatches == 0);
  CHECK(expected > 1000);
}

TEST_CASE("a planet of radius 1e6 seen from 1 unit above: exact horizon, no acne", "[tiny_huge]") {
  const int w = 96, h = 48;
  const double R = 1e6;
  SceneDesc s;
  s.settings.width = w;
  s.settings.height = h;
  s.settings.background = kBackground;
  s.has_camera = true;
  s.camera.fov = 60;
  s.camera.position = Vec3(0, R + 1.0, 0);
  // The horizon dips by acos(R / (R + 1)) ~ 0.081 degrees: look just below it.
  s.camera.look_at = s.camera.position + Vec3(0, -0.0015, 1);
  Vec3 centre(0.0);
  MaterialDesc ground = matte(Color(0.5, 0.6, 0.4));
  ground.ambient = 0.0;
  place(s, add_shape(s, Sphere{centre, R}, add_material(s, ground)));
  LightDesc sun;
  sun.kind = LightKind::Directional;
  sun.direction = glm::normalize(Vec3(0.3, -1, 0.5));
  place(s, add_light(s, sun));
  RenderResult res = render_scene(s);
  Camera cam(s.camera, w, h);
  auto srgb = to_srgb8(res.color);
  int horizon_errors = 0, acne = 0, lit = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Ray ray = cam.generate(x + 0.5, y + 0.5, glm::dvec2(0.5));
      long double d = line_distance(ray, centre);
      if (std::abs(d - R) < 1e-9L * R) continue;
      bool expect_hit = d < R && glm::dot(ray.direction, centre - ray.origin) > 0;
      bool hit = !is_background(res.color, x, y);
      if (expect_hit != hit) ++horizon_errors;
      if (!expect_hit || !hit) continue;
      // Analytic Lambert shading at the hit (nearly the camera's foot point's normal).
      Vec3 dir = glm::normalize(ray.direction);
      Vec3 f = ray.origin - centre;
      double b = glm::dot(f, dir), c = (glm::length(f) - R) * (glm::length(f) + R);
      double t = c / (-b + std::sqrt(std::max(0.0, b * b - c)));
      Vec3 n = glm::normalize(ray.origin + t * dir - centre);
      double shade = 0.7 * std::max(0.0, glm::dot(n, -sun.direction));
      ++lit;
      for (int k = 0; k < 3; ++k) {
        double lin = shade * (k == 0 ? 0.5 : k == 1 ? 0.6 : 0.4);
        int expect = static_cast<int>(std::lround(linear_to_srgb(static_cast<float>(lin)) * 255.0f));
        if (std::abs(expect - int(srgb[(static_cast<std::size_t>(y) * w + x) * 3 + k])) > 8) {
          ++acne;
          break;
        }
      }
    }
  std::string img = save(res.color, "planet");
  record("tiny_huge", "planet r=1e6 from 1 unit above", "pixels off the analytic horizon", horizon_errors, "0", img);
  record("tiny_huge", "planet r=1e6 from 1 unit above", fmt::format("acne pixels (of {} lit)", lit), acne, "0");
  CHECK(horizon_errors == 0);
  CHECK(acne == 0);
  CHECK(lit > w * h / 4);
}
