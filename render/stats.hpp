// What a render measured: rays per kind, guarded NaN samples, time per phase, and per-pixel
// sample statistics (Welford mean and variance of luminance) for error estimates.
#pragma once

#include <cstdint>
#include <string>
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

struct RenderStats {
  int width = 0, height = 0, samples = 0, max_depth = 0, threads = 0;
  std::size_t instances = 0, planes = 0, lights = 0;
  RayCounters rays;
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
};

}  // namespace rts::render
