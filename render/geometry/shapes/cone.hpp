// Truncated cone between `from` (radius_from) and `to` (radius_to), with optional end caps.
// A cylinder is the cone with equal radii (cylinder.hpp). Quadric in the axis frame:
// |perp(p)|^2 = r(s)^2 with r(s) = r0 + k s along the axis, s in [0, L].
#pragma once

#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/params.hpp"
#include <cmath>

#include "render/geometry/shapes/disc.hpp"

namespace rts::render {

// The `cone` block: see docs/shapes.md#cone.
template <>
struct ShapeTraits<Cone> {
  static constexpr PropertyInfo kProperties[] = {
      {"from", "vector", "*required*", "Centre of the `radius_from` end."},
      {"to", "vector", "*required*", "Centre of the `radius_to` end; must differ from `from`."},
      {"radius_from", "number ≥ 0", "*required*", "Radius at `from`."},
      {"radius_to", "number ≥ 0", "`0`", "Radius at `to` (0: a point). Not both radii 0."},
      {"capped", "bool", "`true`", "`false` leaves the ends open."},
  };
  static constexpr ShapeInfo kInfo{.name = "cone", .properties = kProperties, .closure = Closure::WhenCapped};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Cone build(ParamSet& ps) {
    Cone g;
    g.from = ps.require_vec3("from");
    g.to = ps.require_vec3("to");
    distinct(ps, "to", "from", g.to - g.from);
    g.radius_from = non_negative(ps, "radius_from", ps.require_number("radius_from"));
    g.radius_to = non_negative(ps, "radius_to", ps.number("radius_to", g.radius_to));
    if (g.radius_from == 0 && g.radius_to == 0) ps.fail_block("cone needs a non-zero radius_from or radius_to");
    g.capped = ps.boolean("capped", g.capped);
    return g;
  }
};

inline AABB cone_bounds(const Vec3& from, const Vec3& to, double r0, double r1) {
  Vec3 axis = to - from;
  double len = glm::length(axis);
  Vec3 ua = len > tol::kTinyLength ? axis / len : Vec3(0, 1, 0);
  Vec3 e0 = disc_extent(ua, std::abs(r0)), e1 = disc_extent(ua, std::abs(r1));
  AABB b{from - e0, from + e0};
  b.extend(AABB{to - e1, to + e1});
  return b;
}

inline AABB bounds(const Cone& c) { return cone_bounds(c.from, c.to, c.radius_from, c.radius_to); }

inline bool intersect_cone(const Vec3& from, const Vec3& to, double r0, double r1, bool capped,
                           const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  Vec3 axis = to - from;
  double len = glm::length(axis);
  if (!(len > tol::kTinyLength) || r0 < 0.0 || r1 < 0.0 || (r0 <= 0.0 && r1 <= 0.0)) return false;
  Vec3 ua = axis / len;
  double k = (r1 - r0) / len;  // radius change per unit of axis
  Vec3 oc = ray.origin - from;
  double so = glm::dot(oc, ua), sd = glm::dot(ray.direction, ua);
  Vec3 ocp = oc - so * ua, dp = ray.direction - sd * ua;
  double rad_o = r0 + k * so;  // the cone's radius at the origin's axial position
  double a = glm::dot(dp, dp) - (k * sd) * (k * sd);
  double h = glm::dot(ocp, dp) - rad_o * k * sd;
  double c = glm::dot(ocp, ocp) - rad_o * rad_o;

  bool found = false;
  double best = ray_t.max;
  int best_part = 0;  // 0 side, 1 cap at from, 2 cap at to
  auto try_side = [&](double t) {
    if (!ray_t.surrounds(t) || t >= best) return;
    double s = so + t * sd;
    if (s < 0.0 || s > len) return;
    if (r0 + k * s < 0.0) return;  // the mirrored nappe of the double cone
    best = t;
    best_part = 0;
    found = true;
  };
  double dscale = glm::dot(ray.direction, ray.direction);
  if (std::abs(a) > tol::kParallelCosine * dscale) {
    double disc = h * h - a * c;
    if (disc >= 0.0) {
      double sq = std::sqrt(disc);
      double q = h >= 0.0 ? -(h + sq) : -(h - sq);
      if (q != 0.0) {
        try_side(q / a);
        try_side(c / q);
      } else {
        try_side(0.0);
      }
    }
  } else if (std::abs(h) > 0.0) {
    try_side(-c / (2.0 * h));  // ray parallel to the cone's slope: one root
  }
  if (capped) {
    double t;
    Interval cap_t(ray_t.min, best);
    if (r0 > 0.0 && intersect_disc(from, ua, 0.0, r0, ray, cap_t, t)) {
      best = t; best_part = 1; found = true; cap_t.max = t;
    }
    if (r1 > 0.0 && intersect_disc(to, ua, 0.0, r1, ray, cap_t, t)) {
      best = t; best_part = 2; found = true;
    }
  }
  if (!found) return false;
  hit.t = best;
  hit.point = ray.at(best);
  hit.error = ray_point_error(ray, best);
  Vec3 n;
  if (best_part == 1) {
    n = -ua;
  } else if (best_part == 2) {
    n = ua;
  } else {
    Vec3 rel = hit.point - from;
    Vec3 radial = rel - glm::dot(rel, ua) * ua;
    double rl = glm::length(radial);
    Vec3 e = rl > tol::kTinyLength ? radial / rl : any_perpendicular(ua);  // on the axis (tip)
    n = glm::normalize(e - k * ua);
  }
  hit.normal = n;
  hit.shading_normal = n;
  hit.has_uv = false;
  return true;
}

inline bool intersect(const Cone& c, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  return intersect_cone(c.from, c.to, c.radius_from, c.radius_to, c.capped, ray, ray_t, hit);
}

}  // namespace rts::render
