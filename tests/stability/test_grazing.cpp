// Group 3, grazing and tangent: a plane seen at 89.99 degrees, rays tangent to spheres,
// sliver triangles of aspect 1e4. No holes, no NaN; silhouettes match the analytic answer
// (pixel centres whose distance from the outline is below 1e-9 of the view are not counted).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "render/sample/camera.hpp"
#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {
const Color kBackground(0.0, 0.0, 1.0);

SceneDesc ortho_scene(int size, double view_width, Vec3 from, Vec3 at) {
  SceneDesc s;
  s.settings.width = size;
  s.settings.height = size;
  s.settings.background = kBackground;
  s.has_camera = true;
  s.camera.projection = Projection::Orthographic;
  s.camera.view_width = view_width;
  s.camera.position = from;
  s.camera.look_at = at;
  return s;
}
}  // namespace

TEST_CASE("a plane at 89.99 degrees: hit exactly where the analytic ray meets it", "[grazing]") {
  SceneDesc s;
  s.settings.width = 96;
  s.settings.height = 64;
  s.settings.background = kBackground;
  s.has_camera = true;
  s.camera.fov = 40;
  // Looking 0.01 degrees below the horizon from 1 unit above the plane y = 0.
  double down = std::tan(0.01 * M_PI / 180.0);
  s.camera.position = Vec3(0, 1, 0);
  s.camera.look_at = Vec3(0, 1 - down, 1);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, matte(Color(0.7)))));
  LightDesc l;
  l.kind = LightKind::Directional;
  l.direction = Vec3(0.2, -1, 0.3);
  place(s, add_light(s, l));
  RenderResult r = render_scene(s, 2, true);
  Camera cam(s.camera, 96, 64);
  int mismatches = 0, counted = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 96; ++x) {
      Ray ray = cam.generate(x + 0.5, y + 0.5, glm::dvec2(0.5));
      Vec3 d = glm::normalize(ray.direction);
      if (std::abs(d.y) < 1e-12) continue;  // the horizon itself
      ++counted;
      bool expect_hit = d.y < 0.0;
      bool background = r.color.at(x, y)[2] == 1.0f && r.color.at(x, y)[0] == 0.0f;
      if (expect_hit == background) ++mismatches;
    }
  record("grazing", "plane at 89.99 deg", fmt::format("pixels off the analytic horizon (of {})", counted), mismatches,
         "0", save(r.color, "grazing_plane"));
  record("grazing", "plane at 89.99 deg", "NaN samples", r.stats.rays.nan_samples, "0");
  CHECK(mismatches == 0);
  CHECK(r.stats.rays.nan_samples == 0);
  for (const auto& [name, img] : r.aovs) CHECK(count_non_finite(img) == 0);
}

TEST_CASE("sphere silhouettes match the analytic disc, with rays tangent to them", "[grazing]") {
  for (double scale : {1.0, 1e-5, 1e5}) {
    // Pixel centres sit at odd multiples of scale/64; with r = sqrt(15^2 + 25^2) * scale/64 the
    // rays through (+-15, +-25) and (+-25, +-15) are tangent to the sphere (up to rounding).
    const int size = 64;
    double w = 2.0 * scale;
    double r = std::sqrt(15.0 * 15.0 + 25.0 * 25.0) * scale / 64.0;
    SceneDesc s = ortho_scene(size, w, Vec3(0, 0, -10 * scale), Vec3(0.0));
    place(s, add_shape(s, Sphere{Vec3(0.0), r}, add_material(s, matte(Color(0.8)))));
    RenderResult res = render_scene(s);
    Camera cam(s.camera, size, size);
    int mismatches = 0, ambiguous = 0;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        Ray ray = cam.generate(x + 0.5, y + 0.5, glm::dvec2(0.5));
        double d = std::hypot(ray.origin.x, ray.origin.y);
        if (std::abs(d - r) < 1e-9 * scale) {
          ++ambiguous;
          continue;
        }
        bool background = res.color.at(x, y)[2] == 1.0f && res.color.at(x, y)[0] == 0.0f;
        if ((d < r) == background) ++mismatches;
      }
    std::string name = fmt::format("sphere silhouette, scale {:g}", scale);
    record("grazing", name, fmt::format("pixels off the analytic disc ({} tangent, not counted)", ambiguous),
           mismatches, "0", scale == 1.0 ? save(res.color, "grazing_sphere") : "");
    CHECK(mismatches == 0);
  }
}

TEST_CASE("slivers of aspect 1e4 tile a square without holes", "[grazing]") {
  // A square split into 2 x 400 triangles fanned from its edges: each 1e-4 wide at one end.
  SceneDesc s = ortho_scene(64, 0.06, Vec3(0.003, 0.1, -5), Vec3(0.003, 0.1, 0));
  auto m = std::make_shared<MeshData>();
  const int n = 400;
  std::vector<Vec3> pos;
  for (int i = 0; i <= n; ++i) pos.push_back(Vec3(-1.0 + 2.0 * i / n, -1.0, 0.0));  // bottom row
  for (int i = 0; i <= n; ++i) pos.push_back(Vec3(-1.0 + 2.0 * i / n, 1.0, 0.0));   // top row
  for (int i = 0; i < n; ++i) {
    uint32_t b0 = i, b1 = i + 1, t0 = n + 1 + i, t1 = n + 2 + i;
    m->indices.insert(m->indices.end(), {b0, b1, t1, b0, t1, t0});
  }
  for (const Vec3& p : pos) m->positions.emplace_back(p);
  // Each cell is 2/400 = 5e-3 wide and 2 tall; squeezed 25x in x: 2e-4 by 2, aspect 1e4.
  place(s, add_mesh(s, m, add_material(s, matte(Color(0.7)))), glm::scale(Mat4(1.0), Vec3(0.04, 1, 1)));
  LightDesc l;
  l.position = Vec3(0, 0, -10);
  place(s, add_light(s, l));
  RenderResult r = render_scene(s);
  int holes = count_color(r.color, kBackground);
  record("grazing", "slivers of aspect 1e4", "background pixels", holes, "0", save(r.color, "grazing_slivers"));
  record("grazing", "slivers of aspect 1e4", "NaN samples", r.stats.rays.nan_samples, "0");
  CHECK(holes == 0);
  CHECK(r.stats.rays.nan_samples == 0);
}
