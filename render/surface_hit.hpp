// What a primitive's intersect() reports: all vectors in the primitive's object space.
#pragma once

#include <glm/glm.hpp>

#include "render/scene.hpp"

namespace rts::render {

struct SurfaceHit {
  double t = 0.0;            // ray parameter (the same in object and world space)
  Vec3 point{0.0};           // object-space hit point
  Vec3 normal{0, 1, 0};      // geometric normal, outward, not necessarily unit length
  Vec3 shading_normal{0, 1, 0};  // interpolated normal (== normal unless smooth)
  glm::dvec2 uv{0.0};
  bool has_uv = false;
  double error = 0.0;        // bound on |point - exact point| per component (object space)
};

}  // namespace rts::render
