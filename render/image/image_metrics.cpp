#include "render/image/image_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "render/image/stats.hpp"

namespace rts::render {

ImageError image_error(const Image& image, const Image& reference) {
  if (image.width != reference.width || image.height != reference.height)
    throw RenderError({}, fmt::format("image is {}x{} but the reference is {}x{}", image.width, image.height,
                                      reference.width, reference.height));
  ImageError e;
  const std::size_t n = image.rgb.size();
  if (n == 0) return e;
  double sum = 0, rel = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double r = reference.rgb[i], d = image.rgb[i] - r;
    sum += d * d;
    rel += d * d / (r * r + kRelMseEpsilon);
  }
  e.mse = sum / static_cast<double>(n);
  e.rmse = std::sqrt(e.mse);
  e.rel_mse = rel / static_cast<double>(n);
  e.psnr = e.mse > 0 ? -10.0 * std::log10(e.mse) : std::numeric_limits<double>::infinity();
  return e;
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0)) continue;
    double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly;
    ++n;
  }
  double denom = n * sxx - sx * sx;
  if (n < 2 || !(std::abs(denom) > 0)) return std::numeric_limits<double>::quiet_NaN();
  return (n * sxy - sx * sy) / denom;
}

double log_log_interpolate(std::vector<double> xs, std::vector<double> ys, double x) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::size_t> order(std::min(xs.size(), ys.size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return xs[a] < xs[b]; });
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    double x0 = xs[order[k]], x1 = xs[order[k + 1]], y0 = ys[order[k]], y1 = ys[order[k + 1]];
    if (!(x0 > 0 && x1 > 0 && y0 > 0 && y1 > 0)) continue;
    if (x < x0 || x > x1) continue;
    if (x1 == x0) return y0;
    double t = (std::log(x) - std::log(x0)) / (std::log(x1) - std::log(x0));
    return std::exp(std::log(y0) + t * (std::log(y1) - std::log(y0)));
  }
  return nan;
}

}  // namespace rts::render
