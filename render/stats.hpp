// What a render measured: rays per kind, guarded NaN samples, time per phase, and per-pixel
// sample statistics (Welford mean and variance of luminance) for error estimates.
#pragma once

#include <cstdint>
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

// Per pixel, over its samples: mean and unbiased variance of the sample luminance
// (Welford's online algorithm, so no sample is stored).
struct PixelStatistics {
  int width = 0, height = 0;
  int samples = 0;                 // samples per pixel
  std::vector<float> mean;         // row-major, top row first
  std::vector<float> variance;     // 0 when samples < 2

  // Standard error of the mean of one pixel: sqrt(variance / samples).
  double standard_error(int x, int y) const;
  // Mean over all pixels of the standard error; negative when samples < 2 (unknown).
  double mean_standard_error() const;
};

// A named amount (a primitive kind and its count, a part of memory and its bytes).
using NamedCounts = std::vector<std::pair<std::string, uint64_t>>;

struct RenderStats {
  int width = 0, height = 0, samples = 0, max_depth = 0, threads = 0;
  std::size_t instances = 0, planes = 0, lights = 0;
  RayCounters rays;
  // What the scene uses and what rendering left out (render/features.hpp names).
  bool specialized = true;     // false under --no-specialize
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

  double rays_per_second() const {
    return render_seconds > 0 ? static_cast<double>(rays.total()) / render_seconds : 0.0;
  }
  // "640x480, 4 spp, 2 threads: eval 0.003s, build 0.010s, render 1.200s, write 0.030s;
  //  3.10M rays (...per kind...), 2.58M rays/s; error ±0.0042 (mean std. error of pixel
  //  luminance)"
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
    f("scene.triangles", triangles);
    f("scene.bvh_nodes", bvh_nodes);
    f("scene.primitives", primitives);
    f("features.specialized", specialized);
    f("features.used", features_used);
    f("features.left_out", features_left_out);
    f("rays.camera", rays.camera);
    f("rays.shadow", rays.shadow);
    f("rays.reflection", rays.reflection);
    f("rays.refraction", rays.refraction);
    f("rays.total", rays.total());
    f("rays.per_second", rays_per_second());
    f("samples.nan", rays.nan_samples);
    f("memory_bytes", memory);
    f("seconds.parse", parse_seconds);
    f("seconds.evaluate", eval_seconds >= 0 && parse_seconds >= 0 ? eval_seconds - parse_seconds : eval_seconds);
    f("seconds.build", build_seconds);
    f("seconds.render", render_seconds);
    f("seconds.write", write_seconds);
    f("error.mean_standard_error", pixels.mean_standard_error());
  }
};

}  // namespace rts::render
