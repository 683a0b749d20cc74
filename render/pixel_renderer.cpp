#include "render/pixel_renderer.hpp"

#include <cmath>

#include "render/sampler.hpp"

namespace rts::render {
namespace {
// Rec. 709 luminance weights, for the per-pixel statistics.
constexpr double kLumR = 0.2126, kLumG = 0.7152, kLumB = 0.0722;

void store(float* px, const Vec3& v) {
  px[0] = static_cast<float>(v.x);
  px[1] = static_cast<float>(v.y);
  px[2] = static_cast<float>(v.z);
}
}  // namespace

void PixelRenderer::render(int x, int y, Frame& frame, RayCounters& counters) const {
  Rgb sum(0.0);
  double mean = 0.0, m2 = 0.0;  // Welford accumulators of the sample luminance
  for (uint32_t s = 0; s < samples_; ++s) {
    Sampler sampler(static_cast<uint32_t>(x), static_cast<uint32_t>(y), s, seed_);
    // One sample goes through the pixel centre; more are stratified over the pixel.
    glm::dvec2 jitter = samples_ == 1 ? glm::dvec2(0.5) : sampler.next2();
    glm::dvec2 offset = stratified_2d(s, samples_, jitter, sampler.pixel_bits());
    glm::dvec2 lens = sampler.next2();
    Rgb c = integrator_.trace(camera_.generate(x + offset.x, y + offset.y, lens), sampler, counters);
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
      ++counters.nan_samples;  // never let one bad sample poison the pixel
      c = Rgb(0.0);
    }
    sum += c;
    double lum = kLumR * c.x + kLumG * c.y + kLumB * c.z;
    double delta = lum - mean;
    mean += delta / (s + 1);
    m2 += delta * (lum - mean);
  }
  std::size_t i = frame.index(x, y);
  store(frame.color->at(x, y), sum / static_cast<double>(samples_));
  (*frame.mean)[i] = static_cast<float>(mean);
  (*frame.variance)[i] = samples_ > 1 ? static_cast<float>(m2 / (samples_ - 1)) : 0.0f;
  if (frame.aovs.any()) render_aovs(x, y, frame, counters);
}

void PixelRenderer::render_aovs(int x, int y, Frame& frame, RayCounters& counters) const {
  ++counters.camera;
  FirstHit fh = integrator_.first_hit(camera_.generate(x + 0.5, y + 0.5, glm::dvec2(0.5)));
  if (frame.normal) store(frame.normal->at(x, y), fh.hit ? (fh.normal + 1.0) * 0.5 : Vec3(frame.normal_miss));
  if (frame.albedo) store(frame.albedo->at(x, y), fh.albedo);
  const float depth = static_cast<float>(fh.depth);
  if (frame.aovs.depth && fh.hit && std::isfinite(depth)) {
    frame.depth[frame.index(x, y)] = depth;
    frame.depth_bounded[frame.index(x, y)] = fh.bounded ? 1 : 0;
  }
}

}  // namespace rts::render
