// One pixel's work: camera samples through the integrator, accumulated per batch (box filter),
// with NaN guarding; then the pixel's value, its estimated error and the AOVs from the pixel
// centre's first hit.
#pragma once

#include <array>
#include <cstdint>

#include "render/sample/camera.hpp"
#include "render/image/frame.hpp"
#include "render/shade/integrator.hpp"
#include "render/sample/sampler.hpp"
#include "render/image/stats.hpp"

namespace rts::render {

// At most this many interleaved batches per pixel: 4 batches give 3 degrees of freedom per
// pixel, enough to steer adaptive sampling; more would cut each batch's stratification.
constexpr int kMaxBatches = 4;

// A pixel's running sums, per batch: sample s belongs to batch s % batches.
struct PixelAccum {
  std::array<std::array<double, 3>, kMaxBatches> sum{};
  std::array<uint32_t, kMaxBatches> count{};
  uint32_t taken = 0;  // samples so far (the next sample's index)
};

struct PixelEstimate {
  Rgb value{0.0};         // mean of all samples
  Rgb variance{-1.0};     // estimated variance of `value`; negative when unknown (< 2 batches)
};

// The pixel's value and the variance of that value from the spread of its batch means:
// sum_k n_k (m_k - m)^2 / (N (K - 1)), unbiased for independent batches of any sizes whose
// variance falls as 1/n_k.
PixelEstimate estimate_pixel(const PixelAccum& acc, int batches);

// The same from the spread of batches [first, first + count) alone, scaled to the variance of
// the mean of all samples (n_subset / N: every batch draws the same distribution). Adaptive
// sampling plans from batches 0 and 1 and reports from 2 and 3, so the pixels it stops because
// their planning estimate happened to be low do not report that low estimate: the reported
// one comes from samples the stopping rule never saw.
PixelEstimate estimate_pixel_batches(const PixelAccum& acc, int batches, int first, int count);

class PixelRenderer {
 public:
  // `centre_single`: a pixel's only sample goes through its centre (1 spp, no error estimate).
  // `report_first`: the first batch whose spread the stored error estimate uses (0: all;
  // adaptive sampling reports from the batches its planner does not see).
  PixelRenderer(const Camera& camera, const Integrator& integrator, SamplePattern pattern, int batches,
                bool centre_single, int report_first = 0)
      : camera_(camera), integrator_(integrator), pattern_(pattern),
        batches_(static_cast<uint32_t>(batches)), centre_single_(centre_single), report_first_(report_first) {}

  // Adds `count` more samples of pixel (x, y) to `acc`.
  void add_samples(int x, int y, uint32_t count, PixelAccum& acc, RayCounters& counters) const;
  // Writes the pixel's value, error and AOVs into the frame.
  void store(int x, int y, const PixelAccum& acc, Frame& frame, RayCounters& counters) const;
  int batches() const { return static_cast<int>(batches_); }

 private:
  void render_aovs(int x, int y, Frame& frame, RayCounters& counters) const;

  const Camera& camera_;
  const Integrator& integrator_;
  SamplePattern pattern_;
  uint32_t batches_;
  bool centre_single_;
  int report_first_;
};

}  // namespace rts::render
