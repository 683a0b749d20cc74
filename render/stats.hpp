// What a render measured: rays per kind, guarded NaN samples, time per phase, per-pixel
// error statistics and the image's estimated error.
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

struct RenderStats {
  int width = 0, height = 0, samples = 0, max_depth = 0, threads = 0;
  std::size_t instances = 0, planes = 0, lights = 0;
  RayCounters rays;
  double eval_seconds = -1;    // parse + evaluate, filled in by the CLI (< 0: not measured)
  double build_seconds = 0;    // flatten + textures + BVHs
  double render_seconds = 0;
  double write_seconds = 0;    // filled in by whoever writes the images
  PixelStatistics pixels;
  ErrorEstimate error;

  double rays_per_second() const {
    return render_seconds > 0 ? static_cast<double>(rays.total()) / render_seconds : 0.0;
  }
  // "640x480, 4 spp, 2 threads: eval 0.003s, build 0.010s, render 1.200s, write 0.030s;
  //  3.10M rays (...per kind...), 2.58M rays/s; sobol sampler, est. error: rmse 0.0042,
  //  rel. mse 0.00031 (2 batches)"
  std::string summary() const;
};

}  // namespace rts::render
