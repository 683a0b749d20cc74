// Cylinder between `from` and `to` with `radius`, optionally capped: the cone with equal radii.
#pragma once

#include "render/geometry/shapes/cone.hpp"

namespace rts::render {

inline AABB bounds(const Cylinder& c) { return cone_bounds(c.from, c.to, c.radius, c.radius); }

inline bool intersect(const Cylinder& c, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  if (!(c.radius > 0.0)) return false;
  return intersect_cone(c.from, c.to, c.radius, c.radius, c.capped, ray, ray_t, hit);
}

}  // namespace rts::render
