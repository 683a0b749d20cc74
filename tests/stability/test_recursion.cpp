// Group 8, deep recursion: two facing perfect mirrors at max_depth 10,000 and 1e9. The bounce
// loop is iterative, so nothing overflows a worker thread's stack (issue 8 failure 1: it
// crashed at ~5,000 bounces on 2 threads); 10,000 bounces are honoured and 1e9 is capped at
// tol::kMaxDepth with a warning, so time stays bounded.
#include <chrono>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "render/geometry/tolerances.hpp"
#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {

SceneDesc mirrors(int max_depth) {
  SceneDesc s;
  s.settings.width = 16;
  s.settings.height = 12;
  s.settings.max_depth = max_depth;
  s.settings.background = Color(0.2, 0.3, 0.5);
  s.settings.loc = SourceRef{"mirrors.rts", 1, 1};
  s.has_camera = true;
  s.camera.position = Vec3(0, 0, 0);
  s.camera.look_at = Vec3(0.05, 0.02, 1);
  s.camera.fov = 20;
  MaterialDesc mirror = matte(Color(0.1));
  mirror.reflect = Color(1.0);  // nothing decays: every bounce is traced
  MaterialId m = add_material(s, mirror);
  place(s, add_shape(s, Box{Vec3(-1e4, -1e4, 1), Vec3(1e4, 1e4, 1.1)}, m));
  place(s, add_shape(s, Box{Vec3(-1e4, -1e4, -1.1), Vec3(1e4, 1e4, -1)}, m));
  LightDesc l;
  l.position = Vec3(0, 0.5, 0);
  place(s, add_light(s, l));
  return s;
}

}  // namespace

TEST_CASE("10,000 bounces between two mirrors render, every bounce traced", "[recursion]") {
  auto start = std::chrono::steady_clock::now();
  RenderResult r = render_scene(mirrors(10000));
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  double per_path = static_cast<double>(r.stats.rays.reflection) / r.stats.rays.camera;
  record("recursion", "two mirrors, max_depth 10000", "reflection rays per camera ray", per_path, "10000",
         save(r.color, "recursion_mirrors"));
  record("recursion", "two mirrors, max_depth 10000", "render seconds (2 threads)", seconds, "bounded");
  record("recursion", "two mirrors, max_depth 10000", "NaN samples", r.stats.rays.nan_samples, "0");
  CHECK(per_path == Approx(10000.0));
  CHECK(r.warnings.empty());
  CHECK(r.stats.rays.nan_samples == 0);
}

TEST_CASE("max_depth 1e9 is capped with a located warning and ends", "[recursion]") {
  RenderResult r = render_scene(mirrors(1'000'000'000));
  REQUIRE(r.warnings.size() == 1);
  CHECK(std::string(r.warnings[0].where.file) == "mirrors.rts");
  CHECK(r.warnings[0].message.find("capped at 10000") != std::string::npos);
  CHECK(r.stats.max_depth == tol::kMaxDepth);
  double per_path = static_cast<double>(r.stats.rays.reflection) / r.stats.rays.camera;
  record("recursion", "two mirrors, max_depth 1e9", "reflection rays per camera ray (capped)", per_path, "10000");
  CHECK(per_path == Approx(10000.0));
}
