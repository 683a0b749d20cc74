// Adaptive sampling: which pixels get more samples in the next round, from the per-pixel
// error estimates. Pure planning (no tracing), so it is deterministic and testable.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rts::render {

struct AdaptiveInput {
  int width = 0, height = 0;
  const std::vector<double>* variance = nullptr;  // per pixel: variance of its value (channel mean)
  const std::vector<uint32_t>* taken = nullptr;   // per pixel: samples so far
  uint32_t cap = 0;                               // most samples a pixel may take
  uint32_t step = 1;                              // additions are multiples of this (the batches)
  double target_mse = 0;                          // the image's MSE to reach
};

// Samples to add per pixel (0 for most). Pixels are ranked by the error one more sample
// removes, sigma^2 / n^2 (sigma^2 the per-sample variance, smoothed over 3x3 pixels so one
// lucky estimate does not starve a pixel); the best-ranked double their samples until the
// predicted image MSE reaches the target, but at most half of the refinable pixels per round
// so the allocation follows the error rather than doubling everything at once, and at least
// 1/kAdaptiveLeastShare of them so the rounds stay few. All zeros when no pixel can take more
// samples.
inline constexpr std::size_t kAdaptiveLeastShare = 8;
std::vector<uint32_t> plan_adaptive_round(const AdaptiveInput& in);

}  // namespace rts::render
