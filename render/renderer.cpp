#include "render/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <new>
#include <thread>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/camera.hpp"
#include "render/flatten.hpp"
#include "render/integrator.hpp"
#include "render/lights.hpp"
#include "render/progress.hpp"
#include "render/sampler.hpp"
#include "render/texture.hpp"
#include "render/world.hpp"

namespace rts::render {
namespace {

constexpr int kTileSize = 16;
// Rec. 709 luminance weights, for the per-pixel statistics.
constexpr double kLumR = 0.2126, kLumG = 0.7152, kLumB = 0.0722;

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

struct AovFlags {
  bool normal = false, depth = false, albedo = false;
  bool any() const { return normal || depth || albedo; }
};

AovFlags parse_aovs(const std::vector<std::string>& names, SourceRef where) {
  AovFlags f;
  for (const std::string& n : names) {
    if (n == "normal") f.normal = true;
    else if (n == "depth") f.depth = true;
    else if (n == "albedo") f.albedo = true;
    else throw RenderError(where, fmt::format("unknown AOV '{}' (expected normal, depth or albedo)", n));
  }
  return f;
}

}  // namespace

RenderResult render(const SceneDesc& scene, const RenderOptions& options) {
  auto build_start = Clock::now();
  ResolvedSettings rs = resolve(scene, options);
  AovFlags aov = parse_aovs(options.aovs, {});
  const std::size_t pixel_count = static_cast<std::size_t>(rs.width) * rs.height;

  RenderResult result;
  std::vector<float> depth_raw;
  try {
    result.color = Image(rs.width, rs.height);
    result.stats.pixels.mean.assign(pixel_count, 0.0f);
    result.stats.pixels.variance.assign(pixel_count, 0.0f);
    if (aov.normal) result.aovs["normal"] = Image(rs.width, rs.height);
    if (aov.albedo) result.aovs["albedo"] = Image(rs.width, rs.height);
    if (aov.depth) {
      result.aovs["depth"] = Image(rs.width, rs.height);
      depth_raw.assign(pixel_count, -1.0f);
    }
  } catch (const std::bad_alloc&) {
    throw RenderError(scene.settings.loc,
                      fmt::format("out of memory for a {}x{} image", rs.width, rs.height));
  }

  FlatScene flat = flatten_scene(scene);
  World world(scene, flat);
  std::vector<CompiledLight> lights = compile_lights(flat.lights);
  std::vector<CompiledTexture> textures = compile_textures(scene);
  Camera camera(scene.has_camera ? scene.camera : CameraDesc{}, rs.width, rs.height);
  Integrator integrator(world, lights, scene.materials, textures, scene.settings, rs.max_depth);

  RenderStats& stats = result.stats;
  stats.width = rs.width;
  stats.height = rs.height;
  stats.samples = rs.samples;
  stats.max_depth = rs.max_depth;
  stats.threads = options.threads > 0 ? options.threads
                                      : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  stats.instances = world.instance_count() - world.plane_count();
  stats.planes = world.plane_count();
  stats.lights = lights.size();
  stats.pixels.width = rs.width;
  stats.pixels.height = rs.height;
  stats.pixels.samples = rs.samples;
  stats.build_seconds = seconds_since(build_start);

  const int tiles_x = (rs.width + kTileSize - 1) / kTileSize;
  const int tiles_y = (rs.height + kTileSize - 1) / kTileSize;
  const int tile_count = tiles_x * tiles_y;
  Progress progress(static_cast<std::size_t>(tile_count), options.progress);
  std::mutex stats_mutex;
  const uint32_t spp = static_cast<uint32_t>(rs.samples);
  // Look up AOV images once before the parallel loop: std::map's operator[] is not safe to
  // call concurrently.
  Image* normal_img = aov.normal ? &result.aovs["normal"] : nullptr;
  Image* albedo_img = aov.albedo ? &result.aovs["albedo"] : nullptr;

  auto render_tile = [&](int tile) {
    RayCounters counters;
    int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    int x1 = std::min(x0 + kTileSize, rs.width), y1 = std::min(y0 + kTileSize, rs.height);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        Rgb sum(0.0);
        double mean = 0.0, m2 = 0.0;  // Welford accumulators of sample luminance
        for (uint32_t s = 0; s < spp; ++s) {
          Sampler sampler(static_cast<uint32_t>(x), static_cast<uint32_t>(y), s, rs.seed);
          glm::dvec2 jitter = spp == 1 ? glm::dvec2(0.5) : sampler.next2();
          glm::dvec2 offset = stratified_2d(s, spp, jitter, sampler.pixel_bits());
          glm::dvec2 lens = sampler.next2();
          Ray ray = camera.generate(x + offset.x, y + offset.y, lens);
          Rgb c = integrator.trace(ray, sampler, counters);
          if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
            ++counters.nan_samples;  // never let one bad sample poison the pixel
            c = Rgb(0.0);
          }
          sum += c;
          double lum = kLumR * c.x + kLumG * c.y + kLumB * c.z;
          double delta = lum - mean;
          mean += delta / (s + 1);
          m2 += delta * (lum - mean);
        }
        std::size_t i = static_cast<std::size_t>(y) * rs.width + x;
        Rgb avg = sum / static_cast<double>(spp);
        float* px = result.color.at(x, y);
        px[0] = static_cast<float>(avg.x);
        px[1] = static_cast<float>(avg.y);
        px[2] = static_cast<float>(avg.z);
        stats.pixels.mean[i] = static_cast<float>(mean);
        stats.pixels.variance[i] = spp > 1 ? static_cast<float>(m2 / (spp - 1)) : 0.0f;
        if (aov.any()) {
          ++counters.camera;
          FirstHit fh = integrator.first_hit(camera.generate(x + 0.5, y + 0.5, glm::dvec2(0.5)));
          if (aov.normal) {
            float* n = normal_img->at(x, y);
            Vec3 v = fh.hit ? (fh.normal + 1.0) * 0.5 : Vec3(0.0);
            n[0] = static_cast<float>(v.x); n[1] = static_cast<float>(v.y); n[2] = static_cast<float>(v.z);
          }
          if (aov.albedo) {
            float* a = albedo_img->at(x, y);
            a[0] = static_cast<float>(fh.albedo.x); a[1] = static_cast<float>(fh.albedo.y);
            a[2] = static_cast<float>(fh.albedo.z);
          }
          if (aov.depth && fh.hit && std::isfinite(fh.depth)) depth_raw[i] = static_cast<float>(fh.depth);
        }
      }
    }
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

  if (aov.depth) {
    float max_depth = 0.0f;
    for (float d : depth_raw) max_depth = std::max(max_depth, d);
    Image& img = result.aovs["depth"];
    for (std::size_t i = 0; i < pixel_count; ++i) {
      float v = depth_raw[i] >= 0.0f && max_depth > 0.0f ? depth_raw[i] / max_depth : 0.0f;
      img.rgb[i * 3] = img.rgb[i * 3 + 1] = img.rgb[i * 3 + 2] = v;
    }
  }
  stats.render_seconds = seconds_since(render_start);
  return result;
}

}  // namespace rts::render
