#include "render/renderer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <variant>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "render/accum_payload.hpp"
#include "render/sample/adaptive.hpp"
#include "render/sample/camera.hpp"
#include "render/shade/features.hpp"
#include "render/accel/flatten.hpp"
#include "render/image/frame.hpp"
#include "render/image/tile_payload.hpp"
#include "render/shade/integrator.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/path/path_integrator.hpp"
#include "render/pixel_renderer.hpp"
#include "render/prepared_scene.hpp"
#include "render/progress.hpp"
#include "render/scene/resource_limits.hpp"
#include "render/shade/texture.hpp"
#include "render/geometry/tolerances.hpp"
#include "render/accel/world.hpp"

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
  SamplerKind sampler;
};

ResolvedSettings resolve(const SceneDesc& scene, const RenderOptions& o, std::vector<Warning>& warnings) {
  const Settings& s = scene.settings;
  ResolvedSettings r{o.width.value_or(s.width), o.height.value_or(s.height),
                     o.samples.value_or(s.samples), o.max_depth.value_or(s.max_depth),
                     o.seed.value_or(s.seed), o.sampler.value_or(s.sampler)};
  if (r.width < 1 || r.height < 1)
    throw RenderError(s.loc, fmt::format("image size {}x{} must be at least 1x1", r.width, r.height));
  if (r.samples < 1 || r.samples > kMaxSamplesPerPixel)
    throw RenderError(s.loc, fmt::format("samples must be from 1 to {}, got {}", kMaxSamplesPerPixel, r.samples));
  if (!(o.target_error >= 0) || !std::isfinite(o.target_error))
    throw RenderError({}, fmt::format("target error must be a finite number >= 0, got {}", o.target_error));
  if (!(o.time_limit >= 0) || !std::isfinite(o.time_limit))
    throw RenderError({}, fmt::format("time limit must be a finite number of seconds >= 0, got {}", o.time_limit));
  if (r.max_depth < 0) throw RenderError(s.loc, fmt::format("max_depth must be at least 0, got {}", r.max_depth));
  if (r.max_depth > tol::kMaxDepth) {
    // The bounce loop is iterative, so this bounds time, not memory: between two perfect
    // mirrors every level is one more ray for each pixel that sees them.
    warnings.push_back({o.max_depth ? SourceRef{} : s.loc,
                        fmt::format("max_depth {} is capped at {} (deeper bounces only add render time)",
                                    r.max_depth, tol::kMaxDepth)});
    r.max_depth = tol::kMaxDepth;
  }
  std::size_t pixels = static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height);
  if (pixels > o.max_pixels)
    throw RenderError(s.loc, fmt::format("image of {}x{} = {} pixels exceeds the limit of {} pixels",
                                         r.width, r.height, pixels, o.max_pixels));
  // The color image, its per-pixel statistics, each AOV, and the rows packed for writing.
  constexpr std::size_t kBytesPerPixel = 3 * sizeof(float) + 2 * sizeof(float) + 6;
  constexpr std::size_t kBytesPerAovPixel = 3 * sizeof(float) + sizeof(float) + 1 + 6;
  std::size_t bytes = pixels * (kBytesPerPixel + o.aovs.size() * kBytesPerAovPixel);
  if (!memory_fits(o.max_memory, bytes))
    throw RenderError(s.loc, fmt::format("a {}x{} image{} needs {}, past the memory limit of {} (raise it with "
                                         "--max-memory)",
                                         r.width, r.height, o.aovs.empty() ? "" : " and its AOVs",
                                         size_in_words(bytes), size_in_words(o.max_memory)));
  return r;
}

int thread_count(const RenderOptions& options) {
  if (options.threads > 0) return std::min(options.threads, kMaxThreads);
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// What --stats reports about the scene as built: features, primitives, BVH, memory by part.
void describe(const PreparedScene& prep, const FeatureSet& features, const Frame& frame, const RenderResult& result,
              RenderStats& stats) {
  const World& world = prep.world();
  for (std::string_view f : features.used()) stats.features_used.emplace_back(f);
  for (std::string_view f : features.left_out()) stats.features_left_out.emplace_back(f);
  uint64_t by_kind[kShapeKindCount] = {};
  uint64_t csg_blocks = 0, group_placements = 0;
  for (std::size_t i = 0; i < world.instance_count(); ++i) {
    PrimKind kind = world.instance(i).kind;
    // CSG leaves and the shapes of instanced groups (once per group) count as their kinds.
    if (kind < kShapeKindCount) ++by_kind[kind];
    else if (kind == kGroupKind) ++group_placements;
    else ++csg_blocks;
  }
  for (std::size_t k = 0; k < kShapeKindCount; ++k)
    if (by_kind[k] > 0) stats.primitives.emplace_back(shape_name(k), by_kind[k]);
  if (csg_blocks > 0) stats.primitives.emplace_back("csg", csg_blocks);
  if (group_placements > 0) stats.primitives.emplace_back("group", group_placements);
  stats.triangles = world.triangle_count();
  stats.bvh_nodes = world.bvh_nodes();
  WorldMemory m = world.memory();
  std::size_t texture_bytes = 0;
  for (const CompiledTexture& t : prep.textures()) texture_bytes += t.image_bytes();
  std::size_t image_bytes = result.color.rgb.size() * sizeof(float);
  for (const auto& [name, image] : result.aovs) image_bytes += image.rgb.size() * sizeof(float);
  if (frame.variance) image_bytes += frame.variance->size() * sizeof(float);
  if (frame.taken) image_bytes += frame.taken->size() * sizeof(uint32_t);
  image_bytes += frame.depth.size() * sizeof(frame.depth[0]) + frame.depth_bounded.size();
  stats.memory = {{"instances", m.instances + m.transforms}, {"shapes", m.shapes}, {"bvh", m.bvh},
                  {"meshes", m.meshes}, {"textures", texture_bytes}, {"lights", prep.lights().size() * sizeof(CompiledLight)},
                  {"images", image_bytes}};
}

// Independent interleaved batches per pixel (see PixelRenderer): two halves (as Dammertz et
// al. 2010 and Cycles) keep each batch's stratification as fine as possible; four from 32 spp
// give steadier per-pixel estimates (3 degrees of freedom instead of 1). Sobol, the default,
// always takes two: four split the pixel's sequence into quarters, which cost the path-traced
// Cornell box at 64 spp 1.73x the MSE of two halves and the soft-shadow race scene 1.39x,
// while the image's estimate, a mean over every pixel, stays within 10% of the true error with
// two (docs/convergence.md). The stratified sampler keeps four from 32 spp, where a quarter
// of 64 or 256 samples is a square grid and a half is not (N-rooks), and random sampling has no
// stratification to lose. Adaptive sampling takes four when it may reach 16 spp: its planner
// sees batches 0 and 1, the reported error comes from 2 and 3 (kAdaptiveReportFirst), so
// stopping a pixel whose planning estimate was low by chance does not make the reported error
// low too.
constexpr int kAdaptiveReportFirst = 2;
int batch_count(int samples, bool adaptive, SamplerKind sampler) {
  if (samples < 2) return 1;
  if (adaptive) return samples >= 16 ? 4 : 2;
  if (sampler == SamplerKind::Sobol) return 2;
  return samples >= 32 && samples % 4 == 0 ? 4 : 2;
}

// The adaptive loop's estimates: per pixel the planner's (batches 0 and 1, or all when there
// are only two), and the image MSE that the stopping rule and the report use (batches 2 and 3).
double adaptive_estimates(const std::vector<PixelAccum>& accs, int batches, std::vector<PixelEstimate>& plan,
                          std::vector<uint32_t>& taken) {
  const bool split = batches == 4;
  double mse = 0;
  for (std::size_t i = 0; i < accs.size(); ++i) {
    plan[i] = estimate_pixel_batches(accs[i], batches, 0, split ? kAdaptiveReportFirst : batches);
    const PixelEstimate reported =
        split ? estimate_pixel_batches(accs[i], batches, kAdaptiveReportFirst, batches - kAdaptiveReportFirst) : plan[i];
    taken[i] = accs[i].taken;
    mse += (reported.variance.x + reported.variance.y + reported.variance.z) / 3.0;
  }
  return mse / static_cast<double>(std::max<std::size_t>(accs.size(), 1));
}

// Samples per pixel at the end of each progressive pass: `first`, then doubling.
std::vector<uint32_t> pass_schedule(uint32_t samples, uint32_t first) {
  std::vector<uint32_t> goals;
  for (uint32_t g = first; g < samples; g *= 2) goals.push_back(g);
  goals.push_back(samples);
  return goals;
}

// The image-level figures from the per-pixel variances.
void summarise_error(const Image& color, const PixelStatistics& px, ErrorEstimate& e) {
  const std::size_t n = px.taken.size();
  double mse = 0, rel = 0, spp = 0;
  uint32_t lo = ~0u, hi = 0;
  const bool kept = px.variance.size() == 3 * n;  // none at 1 spp (allocate_frame)
  bool known = n > 0 && kept;
  for (std::size_t i = 0; i < n; ++i) {
    spp += px.taken[i];
    lo = std::min(lo, px.taken[i]);
    hi = std::max(hi, px.taken[i]);
    for (int c = 0; c < 3 && kept; ++c) {
      double v = px.variance[i * 3 + c];
      if (v < 0) {
        known = false;
        continue;
      }
      double value = color.rgb[i * 3 + c];
      mse += v;
      rel += v / (value * value + kRelMseEpsilon);
    }
  }
  const double count = 3.0 * static_cast<double>(std::max<std::size_t>(n, 1));
  e.known = known;
  e.rmse = known ? std::sqrt(mse / count) : 0.0;
  e.rel_mse = known ? rel / count : 0.0;
  e.mean_spp = n ? spp / static_cast<double>(n) : 0.0;
  e.min_spp = n ? lo : 0;
  e.max_spp = hi;
}

// Mean over channels of each pixel's variance, for adaptive planning.
std::vector<double> channel_mean_variance(const std::vector<PixelEstimate>& est) {
  std::vector<double> v(est.size());
  for (std::size_t i = 0; i < est.size(); ++i)
    v[i] = std::max(0.0, (est[i].variance.x + est[i].variance.y + est[i].variance.z) / 3.0);
  return v;
}

}  // namespace

namespace {

// render() for a scene prepared beforehand (`given`) or here (null): from `scene_in`, or, when
// `take` is set (the same scene), taking it (scene_in is not read once it is taken).
RenderResult render_scene(const SceneDesc& scene_in, SceneDesc* take, const PreparedScene* given,
                          const RenderOptions& options) {
  auto build_start = Clock::now();
  RenderResult result;
  ResolvedSettings rs = resolve(scene_in, options, result.warnings);
  Frame frame;
  // The batches' spread is the error estimate: none with one batch (1 spp).
  allocate_frame(result, rs.width, rs.height, parse_aovs(options.aovs),
                 batch_count(rs.samples, options.target_error > 0.0, rs.sampler) >= 2, scene_in.settings.loc, frame);
  frame.normal_miss = options.normal_miss;

  // All parallel work (BVH builds, tiles) runs in one arena of --threads workers;
  // global_control lets that number exceed TBB's default limit (the core count).
  const int threads = thread_count(options);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads));
  tbb::task_arena arena(threads);
  PhaseProgress building(options.progress, "building the scene (flattening, BVH)");
  std::optional<PreparedScene> own;
  if (!given)
    arena.execute([&] {
      if (take) own.emplace(std::move(*take), options.specialize, options.max_memory);
      else own.emplace(scene_in, options.specialize, options.max_memory);
    });
  building.done();
  const PreparedScene& prep = given ? *given : *own;
  const SceneDesc& scene = prep.scene();
  const FeatureSet features = prep.features(FeatureContext{rs.samples, rs.max_depth, !options.aovs.empty()});
  const World& world = prep.world();
  // The lights for this render's samples per pixel: area lights written without `samples`
  // spread 16 samples per pixel over them (compile_lights); a few lights, compiled per render
  // because the prepared scene may be rendered at several sample counts (rts converge).
  const std::vector<CompiledLight> lights = compile_lights(prep.flat().lights, rs.samples);
  Camera camera(scene.has_camera ? scene.camera : CameraDesc{}, rs.width, rs.height);
  Integrator integrator(world, lights, scene.materials, prep.textures(), scene.settings, rs.max_depth,
                        prep.integrator_flags(features), &prep.media());
  integrator.jitter_media(rs.samples > 1);
  // Rays start inside the media around the camera (the centre ray's origin: the eye).
  const Vec3 eye = camera.generate(0.5 * rs.width, 0.5 * rs.height, glm::dvec2(0.5)).origin;
  integrator.start_at(eye);
  // Path mode: the path tracer takes the camera samples (the Whitted integrator keeps the AOVs).
  const IntegratorKind integrator_kind = options.integrator.value_or(scene.settings.integrator);
  std::optional<path::PathIntegrator> path_tracer;
  if (integrator_kind == IntegratorKind::Path) {
    path_tracer.emplace(world, scene, lights, prep.textures(), prep.media(), rs.max_depth, result.warnings);
    path_tracer->start_at(eye);
    integrator.use_path_tracer(&*path_tracer);
  }
  const bool adaptive = options.target_error > 0 && rs.samples >= 2;
  const bool progressive = adaptive || (options.time_limit > 0 && rs.samples >= 2);
  const int batches = batch_count(rs.samples, adaptive, rs.sampler);
  const uint32_t spp = static_cast<uint32_t>(rs.samples);
  // Adaptive rendering starts with 8 samples per pixel everywhere (4 per batch of 2, or 2 per
  // batch of 4: each batch's Sobol sequence goes on where it stopped, so the first pass may be
  // small without cutting the stratification of later rounds).
  const uint32_t first_goal = adaptive ? std::min<uint32_t>(spp, 8u) : spp;
  SamplePattern pattern{rs.sampler, rs.seed,
                        (first_goal + static_cast<uint32_t>(batches) - 1) / static_cast<uint32_t>(batches)};
  // The uniform passes before any adaptive round: one per batch, then doubling. Under a time
  // limit they start at two samples per pixel (the fewest that give an error estimate), since
  // the first pass always completes (every pixel needs a value) and a first pass of 4 spp
  // overran short limits by a quarter. Each pixel takes the same samples in the same order
  // whatever the passes, so the image does not depend on them.
  const uint32_t first_pass = options.time_limit > 0 ? std::min(2u, static_cast<uint32_t>(batches))
                                                     : static_cast<uint32_t>(batches);
  const std::vector<uint32_t> first_passes =
      adaptive && !(options.time_limit > 0) ? std::vector<uint32_t>{first_goal}
                                            : pass_schedule(adaptive ? first_goal : spp, first_pass);
  PixelRenderer pixels(camera, integrator, pattern, batches, rs.samples == 1,
                       adaptive && batches == 4 ? kAdaptiveReportFirst : 0);

  RenderStats& stats = result.stats;
  stats.width = rs.width;
  stats.height = rs.height;
  stats.samples = rs.samples;
  stats.max_depth = rs.max_depth;
  stats.threads = threads;
  stats.instances = world.instance_count() - world.plane_count() - world.csg_part_count() - world.group_part_count();
  stats.planes = world.plane_count();
  stats.lights = lights.size();
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if (lights[i].kind != LightKind::Area) continue;
    stats.area_light_samples = std::max(stats.area_light_samples, lights[i].samples);
    if (prep.flat().lights[i].auto_samples) stats.area_samples_auto = true;
  }
  stats.specialized = prep.specialized();
  stats.integrator = integrator_name(integrator_kind);
  if (path_tracer) path_tracer->describe(stats.path_used, stats.path_left_out);
  describe(prep, features, frame, result, stats);
  stats.pixels.width = rs.width;
  stats.pixels.height = rs.height;
  stats.pixels.samples = rs.samples;
  stats.build_seconds = seconds_since(build_start);

  ErrorEstimate& err = stats.error;
  err.sampler = sampler_name(rs.sampler);
  err.batches = batches;
  err.target_error = options.target_error;
  err.time_limit = options.time_limit;
  err.method = batches < 2 ? "none (1 sample per pixel)"
               : adaptive && batches == 4
                   ? "spread of 2 of 4 independent interleaved batch means per pixel (the adaptive planner sees the other 2)"
                   : fmt::format("spread of {} independent interleaved batch means per pixel", batches);

  // Square tiles, handed out dynamically: each pixel's result depends only on its own
  // coordinates (and, when adaptive, on the plan made between rounds from the whole image),
  // so the image is the same whichever thread renders which tile.
  const int tiles_x = (rs.width + kTileSize - 1) / kTileSize;
  const int tiles_y = (rs.height + kTileSize - 1) / kTileSize;
  const int tile_count = tiles_x * tiles_y;
  std::mutex stats_mutex;
  auto for_each_tile = [&](auto&& per_pixel, Progress* progress, const std::atomic<bool>* stop) {
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, tile_count, 1), [&](const tbb::blocked_range<int>& r) {
        for (int tile = r.begin(); tile != r.end(); ++tile) {
          if (stop && stop->load(std::memory_order_relaxed)) continue;
          RayCounters counters;
          int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
          int x1 = std::min(x0 + kTileSize, rs.width), y1 = std::min(y0 + kTileSize, rs.height);
          for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) per_pixel(x, y, counters);
          {
            std::lock_guard lock(stats_mutex);
            stats.rays += counters;
          }
          if (progress) progress->tick();
        }
      });
    });
  };

  auto render_start = Clock::now();
  auto tile_rect = [&](int tile) {
    const int x0 = (tile % tiles_x) * kTileSize, y0 = (tile / tiles_x) * kTileSize;
    return TileRect{x0, y0, std::min(x0 + kTileSize, rs.width), std::min(y0 + kTileSize, rs.height)};
  };
  if (options.exchange && !progressive) {
    // Shared with other processes: the same per-pixel work as the one-pass branch below,
    // packed per tile (tile_payload.hpp) and gathered on the root.
    auto render_tile = [&](int tile, const std::vector<unsigned char>&, std::vector<unsigned char>& payload) {
      const TileRect r = tile_rect(tile);
      std::vector<RayCounters> row_counters(static_cast<std::size_t>(r.y1 - r.y0));
      arena.execute([&] {
        tbb::parallel_for(r.y0, r.y1, [&](int y) {
          // Counted on this thread's stack, stored once per row: rows side by side in one
          // vector, incremented per ray by different threads, would share cache lines.
          RayCounters counters;
          for (int x = r.x0; x < r.x1; ++x) {
            PixelAccum acc;
            pixels.add_samples(x, y, spp, acc, counters);
            pixels.store(x, y, acc, frame, counters);
          }
          row_counters[static_cast<std::size_t>(y - r.y0)] = counters;
        });
      });
      RayCounters total;
      for (const RayCounters& c : row_counters) total += c;  // whole numbers: any order
      pack_tile(frame, r, total, payload);
    };
    auto store_tile = [&](int tile, const std::vector<unsigned char>& payload) {
      RayCounters counters;
      unpack_tile(frame, tile_rect(tile), payload, counters);
      stats.rays += counters;
    };
    options.exchange->run({0, tile_count, nullptr}, render_tile, store_tile);
    err.passes = 1;
  } else if (options.exchange) {
    // Progressive and shared: the passes and adaptive rounds of the branch at the end, each a
    // round of tiles among the processes. The root keeps every pixel's sample sums and plans
    // each round from the whole image, exactly as one process does; a tile travels with its
    // pixels' sums and the samples each takes (accum_payload.hpp), so the image, the
    // estimates and the plan are the bytes of a one-process render for any process count. A
    // time limit is checked between tiles (one process checks between pixels).
    TileExchange& ex = *options.exchange;
    const std::size_t count = ex.root() ? static_cast<std::size_t>(rs.width) * static_cast<std::size_t>(rs.height) : 0;
    std::vector<PixelAccum> accs;
    std::vector<uint32_t> add;
    try {
      accs.resize(count);
      add.resize(count);
    } catch (const std::bad_alloc&) {
      throw RenderError(scene.settings.loc, fmt::format("out of memory for the sample sums of a {}x{} image",
                                                        rs.width, rs.height));
    }
    std::atomic<bool> out_of_time{false};
    auto check_time = [&] {
      if (options.time_limit > 0 && seconds_since(render_start) >= options.time_limit) out_of_time = true;
      return out_of_time.load();
    };
    int round = 0;
    const TileExchange::PrepareTile prepare = [&](int tile, std::vector<unsigned char>& input) {
      if (round > 0 && check_time()) return false;
      const TileRect r = tile_rect(tile);
      bool any = false;
      for (int y = r.y0; y < r.y1 && !any; ++y)
        for (int x = r.x0; x < r.x1 && !any; ++x) any = add[frame.index(x, y)] > 0;
      if (any) pack_round_input(accs, add, rs.width, r, input);
      return any;
    };
    auto render_tile = [&](int tile, const std::vector<unsigned char>& input, std::vector<unsigned char>& payload) {
      const TileRect r = tile_rect(tile);
      std::vector<PixelAccum> tile_accs;
      std::vector<uint32_t> tile_add;
      unpack_round_input(input, r, tile_accs, tile_add);
      const int w = r.x1 - r.x0;
      std::vector<RayCounters> row_counters(static_cast<std::size_t>(r.y1 - r.y0));
      arena.execute([&] {
        tbb::parallel_for(r.y0, r.y1, [&](int y) {
          RayCounters counters;  // on this thread's stack, as above
          for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t k = static_cast<std::size_t>(y - r.y0) * static_cast<std::size_t>(w) +
                                  static_cast<std::size_t>(x - r.x0);
            if (tile_add[k] > 0) pixels.add_samples(x, y, tile_add[k], tile_accs[k], counters);
          }
          row_counters[static_cast<std::size_t>(y - r.y0)] = counters;
        });
      });
      RayCounters total;
      for (const RayCounters& c : row_counters) total += c;
      pack_round_result(total, tile_accs, payload);
    };
    auto store_tile = [&](int tile, const std::vector<unsigned char>& payload) {
      RayCounters counters;
      unpack_round_result(payload, tile_rect(tile), rs.width, accs, counters);
      stats.rays += counters;
    };
    auto run_round = [&] {
      ex.run({round * tile_count, tile_count, &prepare}, render_tile, store_tile);
      ++round;
      ++err.passes;
    };
    if (!ex.root()) {
      run_round();
      while (ex.another_round(false)) run_round();
    } else {
      // The same passes and stopping rules as one process (the last branch below).
      const std::vector<uint32_t> goals = first_passes;
      for (std::size_t p = 0; p < goals.size(); ++p) {
        if (p > 0 && check_time()) break;
        for (std::size_t i = 0; i < count; ++i) add[i] = goals[p] - accs[i].taken;
        if (p > 0) ex.another_round(true);
        run_round();
      }
      if (adaptive) {
        const double target_mse = options.target_error * options.target_error;
        std::vector<PixelEstimate> est(count);
        std::vector<uint32_t> taken(count);
        while (!check_time()) {
          if (adaptive_estimates(accs, batches, est, taken) <= target_mse) {
            err.target_reached = true;
            break;
          }
          std::vector<double> var = channel_mean_variance(est);
          AdaptiveInput in{rs.width, rs.height, &var, &taken, spp, static_cast<uint32_t>(batches), target_mse};
          add = plan_adaptive_round(in);
          if (std::all_of(add.begin(), add.end(), [](uint32_t a) { return a == 0; })) break;
          ex.another_round(true);
          run_round();
        }
      }
      ex.another_round(false);
      err.stopped_by_time = out_of_time.load();
      for_each_tile(
          [&](int x, int y, RayCounters& counters) { pixels.store(x, y, accs[frame.index(x, y)], frame, counters); },
          nullptr, nullptr);
    }
  } else if (!progressive) {
    // One pass: each pixel takes all its samples at once; nothing is kept between pixels.
    Progress progress(static_cast<std::size_t>(tile_count), options.progress);
    for_each_tile(
        [&](int x, int y, RayCounters& counters) {
          PixelAccum acc;
          pixels.add_samples(x, y, spp, acc, counters);
          pixels.store(x, y, acc, frame, counters);
        },
        &progress, nullptr);
    progress.finish();
    err.passes = 1;
  } else {
    const std::size_t count = static_cast<std::size_t>(rs.width) * static_cast<std::size_t>(rs.height);
    std::vector<PixelAccum> accs;
    try {
      accs.resize(count);
    } catch (const std::bad_alloc&) {
      throw RenderError(scene.settings.loc, fmt::format("out of memory for the sample sums of a {}x{} image",
                                                        rs.width, rs.height));
    }
    std::atomic<bool> out_of_time{false};
    auto check_time = [&] {
      if (options.time_limit > 0 && seconds_since(render_start) >= options.time_limit) out_of_time = true;
      return out_of_time.load();
    };
    // Uniform passes; the first always completes so every pixel has a value.
    const std::vector<uint32_t> goals = first_passes;
    Progress progress(static_cast<std::size_t>(tile_count) * goals.size(), options.progress);
    for (std::size_t p = 0; p < goals.size(); ++p) {
      if (p > 0 && check_time()) break;
      const uint32_t goal = goals[p];
      for_each_tile(
          [&](int x, int y, RayCounters& counters) {
            if (p > 0 && check_time()) return;
            PixelAccum& acc = accs[frame.index(x, y)];
            pixels.add_samples(x, y, goal - acc.taken, acc, counters);
          },
          &progress, nullptr);
      ++err.passes;
    }
    progress.finish();
    // Adaptive rounds: refine where the estimated error is highest until the estimate
    // reaches the target, every pixel is at the cap, or time runs out.
    if (adaptive) {
      const double target_mse = options.target_error * options.target_error;
      std::vector<PixelEstimate> est(count);
      std::vector<uint32_t> taken(count);
      while (!check_time()) {
        if (adaptive_estimates(accs, batches, est, taken) <= target_mse) {
          err.target_reached = true;
          break;
        }
        std::vector<double> var = channel_mean_variance(est);
        AdaptiveInput in{rs.width, rs.height, &var, &taken, spp, static_cast<uint32_t>(batches), target_mse};
        std::vector<uint32_t> add = plan_adaptive_round(in);
        if (std::all_of(add.begin(), add.end(), [](uint32_t a) { return a == 0; })) break;
        for_each_tile(
            [&](int x, int y, RayCounters& counters) {
              std::size_t i = frame.index(x, y);
              if (add[i] == 0 || check_time()) return;
              pixels.add_samples(x, y, add[i], accs[i], counters);
            },
            nullptr, nullptr);
        ++err.passes;
      }
    }
    err.stopped_by_time = out_of_time.load();
    for_each_tile(
        [&](int x, int y, RayCounters& counters) { pixels.store(x, y, accs[frame.index(x, y)], frame, counters); },
        nullptr, nullptr);
  }
  finish_depth(result, frame, options.depth_range, options.depth_miss);
  finish_error(result, frame);
  stats.render_seconds = seconds_since(render_start);
  summarise_error(result.color, stats.pixels, err);
  // Shapes that learn something while tracing (an isosurface's real gradient) say it now.
  for (const ShapeDesc& sd : prep.watched_shapes())
    visit_shape(
        [&](const auto& g) {
          if constexpr (requires { after_render_warning(g); })
            if (std::optional<std::string> w = after_render_warning(g)) result.warnings.push_back({sd.loc, *w});
        },
        sd.geometry);
  return result;
}

}  // namespace

RenderResult render(const SceneDesc& scene, const RenderOptions& options) {
  return render_scene(scene, nullptr, nullptr, options);
}

RenderResult render(SceneDesc&& scene, const RenderOptions& options) {
  return render_scene(scene, &scene, nullptr, options);
}

RenderResult render(const PreparedScene& prepared, const RenderOptions& options) {
  return render_scene(prepared.scene(), nullptr, &prepared, options);
}

PreparedScene prepare_scene(const SceneDesc& scene, const RenderOptions& options) {
  const int threads = thread_count(options);
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  tbb::task_arena arena(threads);
  return arena.execute([&] { return PreparedScene(scene, options.specialize, options.max_memory); });
}

}  // namespace rts::render
