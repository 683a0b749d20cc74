#include "render/stats.hpp"

#include <cmath>

#include <fmt/format.h>

namespace rts::render {

double PixelStatistics::standard_error(int x, int y) const {
  if (samples < 2) return -1.0;
  std::size_t i = static_cast<std::size_t>(y) * width + x;
  return std::sqrt(static_cast<double>(variance[i]) / samples);
}

double PixelStatistics::mean_standard_error() const {
  if (samples < 2 || variance.empty()) return -1.0;
  double sum = 0;
  for (float v : variance) sum += std::sqrt(static_cast<double>(v) / samples);
  return sum / static_cast<double>(variance.size());
}

namespace {
std::string si(double v) {
  if (v >= 1e9) return fmt::format("{:.2f}G", v / 1e9);
  if (v >= 1e6) return fmt::format("{:.2f}M", v / 1e6);
  if (v >= 1e3) return fmt::format("{:.1f}k", v / 1e3);
  return fmt::format("{:.0f}", v);
}
}  // namespace

std::string RenderStats::summary() const {
  std::string s = fmt::format(
      "{}x{}, {} spp, {} thread{}: {}build {:.3f}s, render {:.3f}s, write {:.3f}s; {} rays "
      "({} camera, {} shadow, {} reflection, {} refraction), {} rays/s",
      width, height, samples, threads, threads == 1 ? "" : "s",
      eval_seconds >= 0 ? fmt::format("eval {:.3f}s, ", eval_seconds) : "", build_seconds, render_seconds,
      write_seconds, si(static_cast<double>(rays.total())), si(static_cast<double>(rays.camera)),
      si(static_cast<double>(rays.shadow)), si(static_cast<double>(rays.reflection)),
      si(static_cast<double>(rays.refraction)), si(rays_per_second()));
  double err = pixels.mean_standard_error();
  if (err >= 0)
    s += fmt::format("; error ±{:.4f} (mean std. error of pixel luminance)", err);
  else
    s += "; error n/a (1 spp)";
  if (rays.nan_samples > 0) s += fmt::format("; {} NaN samples replaced by black", rays.nan_samples);
  return s;
}

}  // namespace rts::render
