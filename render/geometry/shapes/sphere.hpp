// Sphere: center + radius. Spherical UVs (sphere_uv: u around y from +x, v from the south
// pole up) are computed by the caller for the hit it keeps.
#pragma once

#include <cmath>
#include <numbers>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/params.hpp"
#include "render/geometry/surface_hit.hpp"

namespace rts::render {

// The `sphere` block: see docs/shapes.md#sphere.
template <>
struct ShapeTraits<Sphere> {
  static constexpr PropertyInfo kProperties[] = {
      {"center", "vector", "`<0, 0, 0>`", "The centre."},
      {"radius", "number > 0", "*required*", "The radius."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "sphere", .properties = kProperties, .closure = Closure::Closed, .has_uv = true};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Sphere build(ParamSet& ps) {
    Sphere g;
    g.center = ps.vec3("center", g.center);
    g.radius = positive(ps, "radius", ps.require_number("radius"));
    return g;
  }
};

inline AABB bounds(const Sphere& s) {
  double r = std::abs(s.radius);
  return AABB{s.center - Vec3(r), s.center + Vec3(r)};
}

inline glm::dvec2 sphere_uv(const Vec3& unit_normal) {
  double u = 0.5 + std::atan2(unit_normal.z, unit_normal.x) / (2.0 * std::numbers::pi);
  double v = 0.5 + std::asin(std::clamp(unit_normal.y, -1.0, 1.0)) / std::numbers::pi;
  return {u, v};
}

// The stable quadratic of Ray Tracing Gems ch. 7 (Haines et al.): the discriminant comes from
// the distance between the centre and the ray's closest point, not from b^2 - 4ac, which
// cancels to nothing for a small sphere far away (r = 1e-3 at 1e4: b^2 ~ 1e16 against a
// difference of ~1e-6); the roots come from q = b + sign(b) sqrt(...) (no cancellation).
// The nearest root inside ray_t (shadow rays need no more than this).
inline bool sphere_root(const Sphere& s, const Ray& ray, const Interval& ray_t, double& t) {
  if (!(s.radius > 0.0)) return false;  // zero/negative radius: nothing to hit
  Vec3 f = ray.origin - s.center;
  double a = glm::dot(ray.direction, ray.direction);
  if (!(a > 0.0)) return false;
  double b = -glm::dot(f, ray.direction);               // -b/2 of the textbook form
  Vec3 closest = f + (b / a) * ray.direction;           // centre → the ray's closest point
  double disc = a * (s.radius * s.radius - glm::dot(closest, closest));
  if (disc < 0.0) return false;  // most tests end here, without a square root
  // c as (|f|-r)(|f|+r) keeps precision for rays starting on the surface.
  double len = glm::length(f);
  double c = (len - s.radius) * (len + s.radius);
  double q = b + std::copysign(std::sqrt(disc), b);
  double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  t = t0;
  if (!ray_t.surrounds(t)) {
    t = t1;
    if (!ray_t.surrounds(t)) return false;
  }
  return true;
}

inline bool intersect(const Sphere& s, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double t;
  if (!sphere_root(s, ray, ray_t, t)) return false;
  hit.t = t;
  // Re-project the point onto the sphere (pbrt-v4): its error is then relative to the centre
  // and radius only, not to how far the ray travelled.
  Vec3 rel = ray.at(t) - s.center;
  double rel_len = glm::length(rel);
  Vec3 n = rel_len > 0.0 ? rel / rel_len : Vec3(0, 1, 0);
  hit.point = s.center + s.radius * n;
  hit.error = error_gamma(6) * (max_abs_component(s.center) + s.radius);
  hit.normal = n;
  hit.shading_normal = n;
  hit.has_uv = false;  // World fills spherical UVs for the closest hit only (sphere_uv)
  return true;
}

}  // namespace rts::render
