#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <thread>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/camera.hpp"
#include "render/flatten.hpp"
#include "render/frame.hpp"
#include "render/integrator.hpp"
#include "render/lights.hpp"
#include "render/pixel_renderer.hpp"
#include "render/progress.hpp"
#include "render/texture.hpp"
#include "render/world.hpp"

namespace rts::render {
namespace {

constexpr int kTileSize = 16;
// More threads than this only adds scheduling overhead on any machine we expect.
constexpr int kMaxThreads = 256;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct ResolvedSettings {
  int width, height, samples, max_depth;
  uint64_t seed;
};

ResolvedSettings resolve(const SceneDesc& scene, const RenderOptions& o) {
  const Settings& s = scene.settings;
  ResolvedSettings r{o.width.value_or(s.width), o.height.value_or(s.height),
                     o.samples.value_or(s.samples), o.max_depth.value_or(s.max_depth),
                     o.seed.value_or(s.seed)};
  if (r.width < 1 || r.height < 1)
    throw RenderError(s.loc, fmt::format("image size {}x{} must be at least 1x1", r.width, r.height));
  if (r.samples < 1) throw RenderError(s.loc, fmt::format("samples must be at least 1, got {}", r.samples));
  if (r.max_depth < 0) throw RenderError(s.loc, fmt::format("max_depth must be at least 0, got {}", r.max_depth));
  std::size_t pixels = static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height);
  if (pixels > o.max_pixels)
    throw RenderError(s.loc, fmt::format("image of {}x{} = {} pixels exceeds the limit of {} pixels",
                                         r.width, r.height, pixels, o.max_pixels));
  return r;
}

int thread_count(const RenderOptions& options) {
  if (options.threads > 0) return std::min(options.threads, kMaxThreads);
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Everything built from the scene before tracing: acceleration structures, lights, textures.
struct Prepared {
  FlatScene flat;
  std::unique_ptr<World> world;
  std::vector<CompiledLight> lights;
  std::vector<CompiledTexture> textures;
};

Prepared prepare(const SceneDesc& scene) {
  Prepared p;
  p.flat = flatten_scene(scene);
  p.world = std::make_unique<World>(scene, p.flat);
  p.lights = compile_lights(p.flat.lights);
  p.textures = compile_textures(scene);
  return p;
}

}  // namespace

RenderResult render(const SceneDesc& scene, const RenderOptions& options) {
  auto build_start = Clock::now();
  ResolvedSettings rs = resolve(scene, options);
  RenderResult result;
  Frame frame;
  allocate_frame(result, rs.width, rs.height, parse_aovs(options.aovs), scene.settings.loc, frame);
  frame.normal_miss = options.normal_miss;

  // All parallel work (BVH builds, tiles) runs in one arena of --threads workers;
  // global_control lets that number exceed TBB's default limit (the core count).
  const int threads = thread_count(options);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads));
  tbb::task_arena arena(threads);
  Prepared prep = arena.execute([&] { return prepare(scene); });
  const World& world = *prep.world;
  Camera camera(scene.has_camera ? scene.camera : CameraDesc{}, rs.width, rs.height);
  Integrator integrator(world, prep.lights, scene.materials, prep.textures, scene.settings, rs.max_depth);
  PixelRenderer pixels(camera, integrator, rs.samples, rs.seed);

  RenderStats& stats = result.stats;
  stats.width = rs.width;
  stats.height = rs.height;
  stats.samples = rs.samples;
  stats.max_depth = rs.max_depth;
  stats.threads = threads;
  stats.instances = world.instance_count() - world.plane_count();
  stats.planes = world.plane_count();
  stats.lights = prep.lights.size();
  stats.pixels.width = rs.width;
  stats.pixels.height = rs.height;
  stats.pixels.samples = rs.samples;
  stats.build_seconds = seconds_since(build_start);

  // Square tiles, handed out dynamically: each pixel's result depends only on its own
  // coordinates, so the image is the same whichever thread renders which tile.
  const int tiles_x = (rs.width + kTileSize - 1) / kTileSize;
  const int tiles_y = (rs.height + kTileSize - 1) / kTileSize;
  const int tile_count = tiles_x * tiles_y;
  Progress progress(static_cast<std::size_t>(tile_count), options.progress);
  std::mutex stats_mutex;
  auto render_tile = [&](int tile) {
    RayCounters counters;
    int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    int x1 = std::min(x0 + kTileSize, rs.width), y1 = std::min(y0 + kTileSize, rs.height);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) pixels.render(x, y, frame, counters);
    {
      std::lock_guard lock(stats_mutex);
      stats.rays += counters;
    }
    progress.tick();
  };

  auto render_start = Clock::now();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& r) {
      for (int t = r.begin(); t != r.end(); ++t) render_tile(t);
    });
  });
  progress.finish();
  finish_depth(result, frame, options.depth_range, options.depth_miss);
  stats.render_seconds = seconds_since(render_start);
  return result;
}

}  // namespace rts::render
