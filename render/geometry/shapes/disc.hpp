// Disc (annulus when inner_radius > 0): center, normal, radius. Also used for cylinder caps.
#pragma once

#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/params.hpp"
#include <cmath>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/surface_hit.hpp"

namespace rts::render {

// The `disc` block: see docs/shapes.md#disc.
template <>
struct ShapeTraits<Disc> {
  static constexpr PropertyInfo kProperties[] = {
      {"center", "vector", "`<0, 0, 0>`", "The centre."},
      {"normal", "vector, non-zero", "`<0, 1, 0>`", "The disc's normal."},
      {"radius", "number > 0", "*required*", "Outer radius."},
      {"inner_radius", "number ≥ 0", "`0`", "Radius of the hole; less than `radius`."},
  };
  static constexpr ShapeInfo kInfo{.name = "disc", .properties = kProperties, .closure = Closure::Open};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Disc build(ParamSet& ps) {
    Disc g;
    g.center = ps.vec3("center", g.center);
    g.normal = unit_vector(direction(ps, "normal", ps.vec3("normal", g.normal)));
    g.radius = positive(ps, "radius", ps.require_number("radius"));
    g.inner_radius = non_negative(ps, "inner_radius", ps.number("inner_radius", g.inner_radius));
    require(ps, "inner_radius", g.inner_radius < g.radius, "< radius", g.inner_radius);
    return g;
  }
};

// Some unit vector perpendicular to unit `n`.
inline Vec3 any_perpendicular(const Vec3& n) {
  Vec3 ref = std::abs(n.x) < tol::kReferenceAxisCosine ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  return glm::normalize(glm::cross(n, ref));
}

// Extent of a disc of `radius` perpendicular to unit `axis`, per world axis.
inline Vec3 disc_extent(const Vec3& axis, double radius) {
  return radius * glm::sqrt(glm::max(Vec3(0.0), Vec3(1.0) - axis * axis));
}

inline AABB bounds(const Disc& d) {
  double len = glm::length(d.normal);
  Vec3 n = len > tol::kTinyLength ? d.normal / len : Vec3(0, 1, 0);
  Vec3 e = disc_extent(n, std::abs(d.radius));
  return AABB{d.center - e, d.center + e};
}

// Hit of the plane through `center` with unit normal `n`, inside radii [inner, outer].
inline bool intersect_disc(const Vec3& center, const Vec3& n, double inner, double outer,
                           const Ray& ray, const Interval& ray_t, double& t_out) {
  double denom = glm::dot(n, ray.direction);
  if (nearly_parallel(denom, 1.0, 1.0, ray)) return false;   // n is unit length
  double t = glm::dot(center - ray.origin, n) / denom;
  if (!ray_t.surrounds(t)) return false;
  Vec3 r = ray.at(t) - center;
  double d2 = glm::dot(r, r);
  if (d2 > outer * outer || d2 < inner * inner) return false;
  t_out = t;
  return true;
}

inline bool intersect(const Disc& d, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double len = glm::length(d.normal);
  if (!(len > tol::kTinyLength) || !(d.radius > 0.0)) return false;
  Vec3 n = d.normal / len;
  double t;
  if (!intersect_disc(d.center, n, std::max(0.0, d.inner_radius), d.radius, ray, ray_t, t))
    return false;
  hit.t = t;
  hit.point = ray.at(t);
  hit.error = ray_point_error(ray, t);
  hit.normal = n;
  hit.shading_normal = n;
  hit.has_uv = false;
  return true;
}

}  // namespace rts::render
