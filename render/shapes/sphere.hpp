// Sphere: center + radius. Spherical UVs (sphere_uv: u around y from +x, v from the south
// pole up) are computed by the caller for the hit it keeps.
#pragma once

#include <cmath>
#include <numbers>

#include "render/aabb.hpp"
#include "render/ray.hpp"
#include "render/surface_hit.hpp"

namespace rts::render {

inline AABB bounds(const Sphere& s) {
  double r = std::abs(s.radius);
  return AABB{s.center - Vec3(r), s.center + Vec3(r)};
}

inline glm::dvec2 sphere_uv(const Vec3& unit_normal) {
  double u = 0.5 + std::atan2(unit_normal.z, unit_normal.x) / (2.0 * std::numbers::pi);
  double v = 0.5 + std::asin(std::clamp(unit_normal.y, -1.0, 1.0)) / std::numbers::pi;
  return {u, v};
}

inline bool intersect(const Sphere& s, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  if (!(s.radius > 0.0)) return false;  // zero/negative radius: nothing to hit
  Vec3 oc = ray.origin - s.center;
  double a = glm::dot(ray.direction, ray.direction);
  double h = glm::dot(ray.direction, oc);
  // c computed as (|oc|-r)(|oc|+r) keeps precision for rays starting on the surface.
  double len = glm::length(oc);
  double c = (len - s.radius) * (len + s.radius);
  double disc = h * h - a * c;
  if (disc < 0.0 || a <= 0.0) return false;
  double sq = std::sqrt(disc);
  // The numerically stable pair of roots (no cancellation between -h and sq).
  double q = h >= 0.0 ? -(h + sq) : -(h - sq);
  double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  double t = t0;
  if (!ray_t.surrounds(t)) {
    t = t1;
    if (!ray_t.surrounds(t)) return false;
  }
  hit.t = t;
  hit.point = ray.at(t);
  Vec3 n = (hit.point - s.center) / s.radius;
  hit.normal = n;
  hit.shading_normal = n;
  hit.has_uv = false;  // World fills spherical UVs for the closest hit only (sphere_uv)
  return true;
}

}  // namespace rts::render
