#include "render/image/stats.hpp"

#include <cmath>

#include <fmt/format.h>

namespace rts::render {

double PixelStatistics::standard_error(int x, int y, int c) const {
  std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3 + c;
  if (i >= variance.size() || variance[i] < 0.0f) return -1.0;
  return std::sqrt(static_cast<double>(variance[i]));
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
  s += fmt::format("; {} sampler", error.sampler);
  if (error.min_spp != error.max_spp)
    s += fmt::format(", {:.1f} spp on average ({}..{})", error.mean_spp, error.min_spp, error.max_spp);
  if (error.known)
    s += fmt::format(", est. error: rmse {:.3g}, rel. mse {:.3g} ({} batches)", error.rmse, error.rel_mse,
                     error.batches);
  else
    s += ", est. error n/a (1 sample per pixel)";
  if (integrator != "whitted") s += fmt::format("; {} integrator", integrator);
  if (rays.nan_samples > 0) s += fmt::format("; {} NaN samples replaced by black", rays.nan_samples);
  return s;
}

}  // namespace rts::render
