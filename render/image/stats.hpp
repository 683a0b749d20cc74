// What a render measured: rays per kind, guarded NaN samples, time per phase, per-pixel
// error statistics and the image's estimated error.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rts::render {

struct RayCounters {
  uint64_t camera = 0;
  uint64_t shadow = 0;
  uint64_t reflection = 0;
  uint64_t refraction = 0;
  uint64_t nan_samples = 0;   // samples whose radiance was NaN/inf, replaced by black

  uint64_t total() const { return camera + shadow + reflection + refraction; }
  RayCounters& operator+=(const RayCounters& o) {
    camera += o.camera; shadow += o.shadow; reflection += o.reflection;
    refraction += o.refraction; nan_samples += o.nan_samples;
    return *this;
  }
};

// Per pixel: the estimated variance of its value (from the spread of its batch means, see
// PixelRenderer) and how many samples it took (adaptive sampling varies that).
struct PixelStatistics {
  int width = 0, height = 0;
  int samples = 0;                 // samples per pixel asked for (the cap when adaptive)
  std::vector<float> variance;     // 3 per pixel (linear RGB), row-major; < 0: unknown
  std::vector<uint32_t> taken;     // samples taken per pixel

  // Standard error of one pixel's channel c; negative when unknown.
  double standard_error(int x, int y, int c) const;
};

// The denominator offset of relative MSE, (x - ref)^2 / (ref^2 + eps): 0.01 as in the
// denoising literature (Rousselle et al. 2011), so black pixels do not dominate.
constexpr double kRelMseEpsilon = 0.01;

// The render's own estimate of its error against the converged image, in linear RGB.
struct ErrorEstimate {
  bool known = false;          // false: "n/a" (one sample per pixel: no spread to measure)
  double rmse = 0;             // sqrt(mean over pixels and channels of the pixel variance)
  double rel_mse = 0;          // mean of variance / (value^2 + kRelMseEpsilon)
  std::string method;          // how it was computed, for reports
  std::string sampler;         // "random", "stratified", "sobol"
  int batches = 0;             // independent interleaved batches per pixel
  double mean_spp = 0;         // samples per pixel actually taken, on average
  uint32_t min_spp = 0, max_spp = 0;
  double target_error = 0;     // --target-error (0: none)
  double time_limit = 0;       // --time-limit in seconds (0: none)
  bool stopped_by_time = false;  // the time limit ended the render before its samples were taken
  bool target_reached = false;   // adaptive: the estimate reached target_error
  int passes = 0;              // rendering passes (1 unless progressive or adaptive)
};

// A named amount (a primitive kind and its count, a part of memory and its bytes).
using NamedCounts = std::vector<std::pair<std::string, uint64_t>>;

struct RenderStats {
  int width = 0, height = 0, samples = 0, max_depth = 0, threads = 0;
  std::size_t instances = 0, planes = 0, lights = 0;
  RayCounters rays;
  // Area lights: shadow samples per shading point (the largest over the area lights; 0: none),
  // and whether one of them was written without `samples` (kAutoAreaSamplesPerPixel per pixel).
  int area_light_samples = 0;
  bool area_samples_auto = false;
  // What the scene uses and what rendering left out (render/shade/features.hpp names).
  bool specialized = true;     // false under --no-specialize
  std::string integrator = "whitted";  // "whitted" or "path"
  std::vector<std::string> path_used, path_left_out;  // path mode: its features (PathIntegrator::describe)
  std::vector<std::string> features_used, features_left_out;
  NamedCounts primitives;      // placed primitives by kind (meshes: their triangles counted apart)
  uint64_t triangles = 0;      // in placed meshes, each distinct mesh once
  uint64_t bvh_nodes = 0;      // top level plus each distinct mesh BVH
  NamedCounts memory;          // bytes by part: instances, shapes, bvh, meshes, textures, images
  double parse_seconds = -1;   // the main file's parse, filled in by the CLI (< 0: not measured)
  double eval_seconds = -1;    // parse + evaluate, filled in by the CLI (< 0: not measured)
  double build_seconds = 0;    // flatten + textures + BVHs
  double render_seconds = 0;
  double write_seconds = 0;    // filled in by whoever writes the images
  PixelStatistics pixels;
  ErrorEstimate error;

  // What the shadow rays cost: per pixel, and their share of every ray traced.
  double shadow_rays_per_pixel() const {
    double pixels = static_cast<double>(width) * height;
    return pixels > 0 ? static_cast<double>(rays.shadow) / pixels : 0.0;
  }
  double shadow_ray_share() const {
    return rays.total() > 0 ? static_cast<double>(rays.shadow) / static_cast<double>(rays.total()) : 0.0;
  }
  double rays_per_second() const {
    return render_seconds > 0 ? static_cast<double>(rays.total()) / render_seconds : 0.0;
  }
  // "640x480, 4 spp, 2 threads: eval 0.003s, build 0.010s, render 1.200s, write 0.030s;
  //  3.10M rays (...per kind...), 2.58M rays/s; sobol sampler, est. error: rmse 0.0042,
  //  rel. mse 0.00031 (2 batches)"
  std::string summary() const;

  // Every figure, by dotted name, for the JSON report (render/stats_json.hpp, schema in
  // docs/stats-json.md) and `--stats`. A new figure is one line here: `f("section.name", member)`
  // (numbers, bools, strings, string lists and NamedCounts are understood). Names of one
  // section stay together.
  template <class F>
  void visit(F&& f) const {
    f("image.width", width);
    f("image.height", height);
    f("image.samples", samples);
    f("image.max_depth", max_depth);
    f("image.threads", threads);
    f("scene.instances", instances);
    f("scene.planes", planes);
    f("scene.lights", lights);
    f("scene.area_light_samples", area_light_samples);
    f("scene.area_samples_auto", area_samples_auto);
    f("scene.triangles", triangles);
    f("scene.bvh_nodes", bvh_nodes);
    f("scene.primitives", primitives);
    f("features.specialized", specialized);
    f("features.used", features_used);
    f("features.left_out", features_left_out);
    f("integrator.kind", integrator);
    f("integrator.path_used", path_used);
    f("integrator.path_left_out", path_left_out);
    f("rays.camera", rays.camera);
    f("rays.shadow", rays.shadow);
    f("rays.reflection", rays.reflection);
    f("rays.refraction", rays.refraction);
    f("rays.total", rays.total());
    f("rays.shadow_per_pixel", shadow_rays_per_pixel());
    f("rays.shadow_share", shadow_ray_share());
    f("rays.per_second", rays_per_second());
    f("samples.nan", rays.nan_samples);
    f("memory_bytes", memory);
    f("seconds.parse", parse_seconds);
    f("seconds.evaluate", eval_seconds >= 0 && parse_seconds >= 0 ? eval_seconds - parse_seconds : eval_seconds);
    f("seconds.build", build_seconds);
    f("seconds.render", render_seconds);
    f("seconds.write", write_seconds);
    f("error.known", error.known);
    // Unknown estimates (one sample per pixel) are written as null: NaN is not finite.
    constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
    f("error.rmse", error.known ? error.rmse : kUnknown);
    f("error.rel_mse", error.known ? error.rel_mse : kUnknown);
    f("error.method", error.method);
    f("error.batches", error.batches);
    f("sampling.sampler", error.sampler);
    f("sampling.mean_spp", error.mean_spp);
    f("sampling.min_spp", error.min_spp);
    f("sampling.max_spp", error.max_spp);
    f("sampling.passes", error.passes);
    f("sampling.target_error", error.target_error);
    f("sampling.time_limit", error.time_limit);
    f("sampling.target_reached", error.target_reached);
    f("sampling.stopped_by_time", error.stopped_by_time);
  }
};

}  // namespace rts::render
