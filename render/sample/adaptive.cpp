#include "render/sample/adaptive.hpp"

#include <algorithm>
#include <numeric>

namespace rts::render {

std::vector<uint32_t> plan_adaptive_round(const AdaptiveInput& in) {
  const int w = in.width, h = in.height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const std::vector<double>& var = *in.variance;
  const std::vector<uint32_t>& taken = *in.taken;
  std::vector<uint32_t> add(n, 0);
  if (n == 0) return add;

  // Per-sample variance, box-filtered over 3x3 pixels.
  std::vector<double> sigma2(n), smooth(n);
  for (std::size_t i = 0; i < n; ++i) sigma2[i] = std::max(0.0, var[i]) * taken[i];
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0;
      int count = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
          sum += sigma2[static_cast<std::size_t>(yy) * w + xx];
          ++count;
        }
      // At least half the pixel's own estimate: a thin noisy edge is not averaged away.
      std::size_t i = static_cast<std::size_t>(y) * w + x;
      smooth[i] = std::max(sum / count, sigma2[i] * 0.5);
    }

  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < n; ++i)
    if (taken[i] + in.step <= in.cap) candidates.push_back(i);
  if (candidates.empty()) return add;
  auto score = [&](std::size_t i) { return smooth[i] / (static_cast<double>(taken[i]) * taken[i]); };
  std::stable_sort(candidates.begin(), candidates.end(),
                   [&](std::size_t a, std::size_t b) { return score(a) > score(b); });

  double mse_sum = 0;  // the image's MSE times the pixel count
  for (std::size_t i = 0; i < n; ++i) mse_sum += std::max(0.0, var[i]);
  const double goal = in.target_mse * static_cast<double>(n);
  const std::size_t most = std::max<std::size_t>(1, candidates.size() / 2);
  // The prediction below is optimistic (the estimate falls more slowly than sigma^2 / n), so
  // stopping where it reaches the goal refined a handful of pixels per round: 4,784 rounds for
  // a 96x72 image, each ranking every pixel, 94% of the render's time (perf). At least an
  // eighth of the refinable pixels per round keeps the rounds to a few dozen.
  const std::size_t least = std::max<std::size_t>(1, candidates.size() / kAdaptiveLeastShare);
  for (std::size_t k = 0; k < most; ++k) {
    std::size_t i = candidates[k];
    uint32_t more = std::min(taken[i], in.cap - taken[i]);
    more -= more % in.step;
    if (more == 0) more = in.step;
    add[i] = more;
    mse_sum -= smooth[i] / taken[i] - smooth[i] / (taken[i] + more);
    if (mse_sum <= goal && k + 1 >= least) break;
  }
  return add;
}

}  // namespace rts::render
