// The renderer's TileExchange hook (what MPI ranks and checkpoints go through): tiles rendered
// in any order, carried as bytes and stored in another order — as tiles arrive from ranks of
// different speeds — give the image, AOVs, per-pixel statistics and ray counts of a plain
// render, bit for bit.
#include <algorithm>
#include <map>
#include <random>

#include <catch2/catch.hpp>

#include "render/renderer.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

SceneDesc scene() {
  SceneDesc s;
  s.settings.width = 50;  // not a multiple of the tile size: edge tiles are partial
  s.settings.height = 37;
  s.settings.samples = 4;
  s.settings.seed = 3;
  s.has_camera = true;
  s.camera.position = Vec3(0, 1, -6);
  s.camera.look_at = Vec3(0, 0.5, 0);
  MaterialDesc floor;
  floor.color = Color(0.7, 0.6, 0.5);
  floor.reflect = Color(0.3);
  floor.roughness = 0.2;
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, floor)));
  MaterialDesc red;
  red.color = Color(0.9, 0.1, 0.1);
  red.specular = 0.5;
  place(s, add_shape(s, Sphere{Vec3(0, 1, 0), 1.0}, add_material(s, red)));
  LightDesc area;
  area.kind = LightKind::Area;
  area.position = Vec3(0, 6, -2);
  area.u = Vec3(2, 0, 0);
  area.v = Vec3(0, 0, 2);
  area.samples = 2;
  place(s, add_light(s, area));
  return s;
}

// Renders every tile in one shuffled order, then stores them in another.
class ShuffledExchange : public TileExchange {
 public:
  explicit ShuffledExchange(unsigned seed) : rng_(seed) {}
  void run(const Round& round, const RenderTile& render_tile, const StoreTile& store_tile) override {
    std::vector<int> order(static_cast<std::size_t>(round.tile_count));
    for (int i = 0; i < round.tile_count; ++i) order[static_cast<std::size_t>(i)] = i;
    std::shuffle(order.begin(), order.end(), rng_);
    std::map<int, std::vector<unsigned char>> done;
    for (int t : order) {
      std::vector<unsigned char> input;
      if (round.prepare && !(*round.prepare)(t, input)) continue;
      // Through a copy, as over the wire: nothing may point into the root's memory.
      render_tile(t, std::vector<unsigned char>(input), done[t]);
    }
    std::shuffle(order.begin(), order.end(), rng_);
    for (int t : order)
      if (done.count(t)) store_tile(t, done[t]);
    tiles = round.tile_count;
    ++rounds;
  }
  bool another_round(bool more) override { return more; }
  bool root() const override { return true; }
  int tiles = 0, rounds = 0;

 private:
  std::mt19937 rng_;
};

}  // namespace

TEST_CASE("tiles exchanged in shuffled order give the plain render's bytes", "[render]") {
  const SceneDesc s = scene();
  RenderOptions plain;
  plain.threads = 2;
  plain.aovs = {"normal", "depth", "albedo", "error"};
  const RenderResult a = render(s, plain);
  for (unsigned seed : {1u, 2u}) {
    ShuffledExchange ex(seed);
    RenderOptions o = plain;
    o.exchange = &ex;
    const RenderResult b = render(s, o);
    CHECK(ex.tiles == 4 * 3);  // 50×37 in 16×16 tiles
    CHECK(a.color.rgb == b.color.rgb);
    CHECK(a.stats.pixels.variance == b.stats.pixels.variance);
    CHECK(a.stats.pixels.taken == b.stats.pixels.taken);
    REQUIRE(a.aovs.size() == b.aovs.size());
    for (const auto& [name, image] : a.aovs) CHECK(image.rgb == b.aovs.at(name).rgb);
    CHECK(a.stats.rays.camera == b.stats.rays.camera);
    CHECK(a.stats.rays.shadow == b.stats.rays.shadow);
    CHECK(a.stats.rays.reflection == b.stats.rays.reflection);
    CHECK(a.stats.error.rmse == b.stats.error.rmse);
  }
}

TEST_CASE("adaptive sampling in exchanged rounds gives the plain render's bytes and decisions", "[render]") {
  SceneDesc s = scene();
  s.settings.samples = 64;  // the per-pixel cap
  RenderOptions plain;
  plain.threads = 2;
  plain.target_error = 0.002;
  plain.aovs = {"error"};
  const RenderResult a = render(s, plain);
  INFO("passes " << a.stats.error.passes << " rmse " << a.stats.error.rmse << " reached " << a.stats.error.target_reached);
  REQUIRE(a.stats.error.passes > 2);  // the adaptive rounds did run
  for (unsigned seed : {1u, 2u}) {
    ShuffledExchange ex(seed);
    RenderOptions o = plain;
    o.exchange = &ex;
    const RenderResult b = render(s, o);
    CHECK(ex.rounds == a.stats.error.passes);
    CHECK(a.color.rgb == b.color.rgb);
    CHECK(a.stats.pixels.taken == b.stats.pixels.taken);  // the same adaptive decisions
    CHECK(a.stats.pixels.variance == b.stats.pixels.variance);
    CHECK(a.aovs.at("error").rgb == b.aovs.at("error").rgb);
    CHECK(a.stats.rays.camera == b.stats.rays.camera);
    CHECK(a.stats.rays.shadow == b.stats.rays.shadow);
    CHECK(a.stats.error.rmse == b.stats.error.rmse);
    CHECK(a.stats.error.target_reached == b.stats.error.target_reached);
  }
}

TEST_CASE("progressive passes in exchanged rounds give the plain render's bytes", "[render]") {
  // A time limit far beyond the render's time: every pass runs, as in one process.
  RenderOptions plain;
  plain.threads = 1;
  plain.time_limit = 1000;
  const RenderResult a = render(scene(), plain);
  ShuffledExchange ex(5);
  RenderOptions o = plain;
  o.exchange = &ex;
  const RenderResult b = render(scene(), o);
  CHECK(ex.rounds == a.stats.error.passes);
  CHECK(a.color.rgb == b.color.rgb);
  CHECK(a.stats.pixels.taken == b.stats.pixels.taken);
}
