// Rays, and spawning secondary rays off a surface without hitting it again.
#pragma once

#include <algorithm>
#include <cmath>

#include "render/scene.hpp"
#include "render/tolerances.hpp"

namespace rts::render {

// The direction need not be unit length: object-space rays keep the world ray's parameter t,
// so their direction carries the inverse transform's scale.
struct Ray {
  Vec3 origin{0.0};
  Vec3 direction{0, 0, 1};
  Vec3 at(double t) const { return origin + t * direction; }
};

inline double max_abs_component(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

// Moves `point` off the surface with geometric normal `normal` (unit) towards the side that
// `direction` leaves into. The offset is proportional to the rounding error of the hit point.
inline Vec3 offset_ray_origin(const Vec3& point, const Vec3& normal, const Vec3& direction,
                              double travelled) {
  double scale = std::max(max_abs_component(point), travelled);
  double offset = tol::kRayOffsetAbsolute + tol::kRayOffsetRelative * scale;
  return glm::dot(normal, direction) >= 0.0 ? point + offset * normal : point - offset * normal;
}

}  // namespace rts::render
