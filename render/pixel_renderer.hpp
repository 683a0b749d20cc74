// One pixel's work: N stratified camera samples through the integrator, averaged (box
// filter), with NaN guarding, Welford statistics of the sample luminance, and the AOVs from
// the pixel centre's first hit.
#pragma once

#include <cstdint>

#include "render/camera.hpp"
#include "render/frame.hpp"
#include "render/integrator.hpp"
#include "render/stats.hpp"

namespace rts::render {

class PixelRenderer {
 public:
  PixelRenderer(const Camera& camera, const Integrator& integrator, int samples, uint64_t seed)
      : camera_(camera), integrator_(integrator), samples_(static_cast<uint32_t>(samples)), seed_(seed) {}

  void render(int x, int y, Frame& frame, RayCounters& counters) const;

 private:
  void render_aovs(int x, int y, Frame& frame, RayCounters& counters) const;

  const Camera& camera_;
  const Integrator& integrator_;
  uint32_t samples_;
  uint64_t seed_;
};

}  // namespace rts::render
