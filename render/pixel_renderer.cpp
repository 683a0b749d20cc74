#include "render/pixel_renderer.hpp"

#include <cmath>

#include "render/sample/sampler.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {
namespace {

void store_rgb(float* px, const Vec3& v) {
  px[0] = static_cast<float>(v.x);
  px[1] = static_cast<float>(v.y);
  px[2] = static_cast<float>(v.z);
}

}  // namespace

PixelEstimate estimate_pixel_batches(const PixelAccum& acc, int batches, int first, int count) {
  PixelEstimate e;
  if (acc.taken == 0) return e;
  const double n = acc.taken;
  Rgb total(0.0);
  for (int k = 0; k < batches; ++k) total += Rgb(acc.sum[k][0], acc.sum[k][1], acc.sum[k][2]);
  e.value = total / n;
  int filled = 0;
  double subset_n = 0;
  Rgb subset_sum(0.0);
  for (int k = first; k < first + count; ++k) {
    if (acc.count[k] == 0) continue;
    ++filled;
    subset_n += acc.count[k];
    subset_sum += Rgb(acc.sum[k][0], acc.sum[k][1], acc.sum[k][2]);
  }
  if (filled < 2) return e;
  const Rgb subset_mean = subset_sum / subset_n;
  Rgb spread(0.0);
  for (int k = first; k < first + count; ++k) {
    if (acc.count[k] == 0) continue;
    Rgb m = Rgb(acc.sum[k][0], acc.sum[k][1], acc.sum[k][2]) / static_cast<double>(acc.count[k]);
    Rgb d = m - subset_mean;
    spread += static_cast<double>(acc.count[k]) * d * d;
  }
  // Variance of the subset's mean, times n_subset / N for the mean of all samples.
  e.variance = spread / (subset_n * (filled - 1)) * (subset_n / n);
  return e;
}

PixelEstimate estimate_pixel(const PixelAccum& acc, int batches) {
  return estimate_pixel_batches(acc, batches, 0, batches);
}

void PixelRenderer::add_samples(int x, int y, uint32_t count, PixelAccum& acc, RayCounters& counters) const {
  // Sample s is index s / batches of batch s % batches; both are stepped instead of divided per
  // sample (profile finding, perf on the pattern race scene at 1 spp: the 32-bit division was a
  // sixth of this function's own time).
  uint32_t batch = acc.taken % batches_, index = acc.taken / batches_;
  for (uint32_t s = acc.taken, end = acc.taken + count; s < end; ++s) {
    Sampler sampler(pattern_, static_cast<uint32_t>(x), static_cast<uint32_t>(y), batch, index);
    glm::dvec2 offset = centre_single_ ? glm::dvec2(0.5) : sampler.next2();
    // Without depth of field the lens point is ignored: step over its two dimensions instead of
    // computing them (the Sobol pair was 13% of a 1-spp diffuse render's instructions, callgrind),
    // so every later draw still gets the same values and the image does not change.
    glm::dvec2 lens(0.5);
    if (camera_.has_depth_of_field())
      lens = sampler.next2();
    else
      sampler.skip(2);
    Rgb c;
    if (!camera_.may_miss()) [[likely]] {
      c = integrator_.trace(camera_.generate(x + offset.x, y + offset.y, lens), sampler, counters);
    } else {
      // A projection that sends no ray there (a fisheye's corners) leaves the sample black.
      Ray ray;
      c = camera_.generate(x + offset.x, y + offset.y, lens, ray) ? integrator_.trace(ray, sampler, counters)
                                                                   : Rgb(0.0);
    }
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
      ++counters.nan_samples;  // never let one bad sample poison the pixel
      c = Rgb(0.0);
    }
    // Saturated (sums over bounces may pass kMaxRadiance) so the float image stays finite.
    c = glm::min(c, Rgb(tol::kMaxRadiance));
    acc.sum[batch][0] += c.x;
    acc.sum[batch][1] += c.y;
    acc.sum[batch][2] += c.z;
    ++acc.count[batch];
    if (++batch == batches_) {
      batch = 0;
      ++index;
    }
  }
  acc.taken += count;
}

void PixelRenderer::store(int x, int y, const PixelAccum& acc, Frame& frame, RayCounters& counters) const {
  PixelEstimate e = estimate_pixel_batches(acc, static_cast<int>(batches_), report_first_,
                                           static_cast<int>(batches_) - report_first_);
  store_rgb(frame.color->at(x, y), e.value);
  std::size_t i = frame.index(x, y);
  if (frame.variance)
    for (int c = 0; c < 3; ++c) (*frame.variance)[i * 3 + c] = static_cast<float>(e.variance[c]);
  (*frame.taken)[i] = acc.taken;
  if (frame.aovs.any()) render_aovs(x, y, frame, counters);
}

void PixelRenderer::render_aovs(int x, int y, Frame& frame, RayCounters& counters) const {
  if (frame.aovs.normal || frame.aovs.albedo || frame.aovs.depth) {
    ++counters.camera;
    FirstHit fh = integrator_.first_hit(camera_.generate(x + 0.5, y + 0.5, glm::dvec2(0.5)));
    if (frame.normal) store_rgb(frame.normal->at(x, y), fh.hit ? (fh.normal + 1.0) * 0.5 : Vec3(frame.normal_miss));
    if (frame.albedo) store_rgb(frame.albedo->at(x, y), fh.albedo);
    const float depth = static_cast<float>(fh.depth);
    if (frame.aovs.depth && fh.hit && std::isfinite(depth)) {
      frame.depth[frame.index(x, y)] = depth;
      frame.depth_bounded[frame.index(x, y)] = fh.bounded ? 1 : 0;
    }
  }
}

}  // namespace rts::render
