#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
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

}  // namespace

RenderResult render(const SceneDesc& scene, const RenderOptions& options) {
  auto build_start = Clock::now();
  ResolvedSettings rs = resolve(scene, options);
  RenderResult result;
  Frame frame;
  allocate_frame(result, rs.width, rs.height, parse_aovs(options.aovs), scene.settings.loc, frame);

  FlatScene flat = flatten_scene(scene);
  World world(scene, flat);
  std::vector<CompiledLight> lights = compile_lights(flat.lights);
  std::vector<CompiledTexture> textures = compile_textures(scene);
  Camera camera(scene.has_camera ? scene.camera : CameraDesc{}, rs.width, rs.height);
  Integrator integrator(world, lights, scene.materials, textures, scene.settings, rs.max_depth);
  PixelRenderer pixels(camera, integrator, rs.samples, rs.seed);

  RenderStats& stats = result.stats;
  stats.width = rs.width;
  stats.height = rs.height;
  stats.samples = rs.samples;
  stats.max_depth = rs.max_depth;
  stats.threads = options.threads > 0 ? std::min(options.threads, kMaxThreads)
                                      : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  stats.instances = world.instance_count() - world.plane_count();
  stats.planes = world.plane_count();
  stats.lights = lights.size();
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
  // global_control lets --threads exceed TBB's default worker limit (the core count).
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(stats.threads));
  tbb::task_arena arena(stats.threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& r) {
      for (int t = r.begin(); t != r.end(); ++t) render_tile(t);
    });
  });
  progress.finish();
  finish_depth(result, frame);
  stats.render_seconds = seconds_since(render_start);
  return result;
}

}  // namespace rts::render
