// Superellipsoid (POV-Ray's `superellipsoid { <e, n> }`): the solid
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1 inside the cube [-1, 1]^3, z its polar axis.
// e = n = 1 is the unit sphere; small exponents round a box's edges (e, n = 0.2: a rounded
// cube), e = 1 with small n a rounded cylinder.
//
// No closed form: the ray's segment inside the cube is sampled at kSuperellipsoidSteps
// points and each sign change of the radius-like function R(p) - 1 (R = f^(n/2), of slope
// about 1, so bisection halves a meaningful bracket) is bisected to the last bit. Features
// thinner than a step (exponents far beyond 2, where the surface pinches) can be missed.
#pragma once

#include <algorithm>
#include <cmath>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/scene/params.hpp"

namespace rts::render {

// The `superellipsoid` block: see docs/shapes.md#superellipsoid.
template <>
struct ShapeTraits<Superellipsoid> {
  static constexpr PropertyInfo kProperties[] = {
      {"e", "number > 0", "`1`", "East-west exponent: the roundness around the z axis (small: square)."},
      {"n", "number > 0", "`1`", "North-south exponent: the roundness along z (small: flat top and bottom)."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "superellipsoid", .properties = kProperties, .closure = Closure::Closed};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Superellipsoid build(ParamSet& ps) {
    Superellipsoid g;
    g.e = positive(ps, "e", ps.number("e", g.e));
    g.n = positive(ps, "n", ps.number("n", g.n));
    return g;
  }
};

inline AABB bounds(const Superellipsoid&) { return AABB{Vec3(-1.0), Vec3(1.0)}; }

// Samples of the segment inside the cube: 128 resolve the exponents POV-Ray scenes use
// (0.05 .. 2) at any view; each costs three pow calls.
inline constexpr int kSuperellipsoidSteps = 128;

// R(p) - 1: negative inside. R = ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2).
inline double superellipsoid_value(const Superellipsoid& s, const Vec3& p) {
  double a = std::pow(std::abs(p.x), 2.0 / s.e) + std::pow(std::abs(p.y), 2.0 / s.e);
  double f = std::pow(a, s.e / s.n) + std::pow(std::abs(p.z), 2.0 / s.n);
  return std::pow(f, 0.5 * s.n) - 1.0;
}

// Every crossing of the surface along the whole line, ascending (at most `max_out`); returns
// how many.
inline int superellipsoid_crossings(const Superellipsoid& s, const Ray& ray, double* t_out, int max_out) {
  if (!(s.e > 0.0) || !(s.n > 0.0)) return 0;
  double t0 = -Interval::kInfinity, t1 = Interval::kInfinity;
  for (int a = 0; a < 3; ++a) {
    double d = ray.direction[a], o = ray.origin[a];
    if (d == 0.0) {
      if (o < -1.0 || o > 1.0) return 0;
      continue;
    }
    double ta = (-1.0 - o) / d, tb = (1.0 - o) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t0 < t1)) return 0;
  int count = 0;
  double prev_t = t0, prev_v = superellipsoid_value(s, ray.at(t0));
  for (int i = 1; i <= kSuperellipsoidSteps && count < max_out; ++i) {
    double t = i == kSuperellipsoidSteps ? t1 : t0 + (t1 - t0) * i / kSuperellipsoidSteps;
    double v = superellipsoid_value(s, ray.at(t));
    if ((prev_v < 0.0) != (v < 0.0) && std::isfinite(v) && std::isfinite(prev_v)) {
      double a = prev_t, b = t;
      bool a_inside = prev_v < 0.0;
      for (int k = 0; k < 80 && a < b; ++k) {
        double m = 0.5 * (a + b);
        if (m <= a || m >= b) break;
        if ((superellipsoid_value(s, ray.at(m)) < 0.0) == a_inside) a = m; else b = m;
      }
      t_out[count++] = 0.5 * (a + b);
    }
    prev_t = t;
    prev_v = v;
  }
  return count;
}

// The hit at crossing t: the normal is the gradient of R, by central differences (the
// analytic one divides by zero on the axes for exponents above 2).
inline void superellipsoid_hit_at(const Superellipsoid& s, const Ray& ray, double t, SurfaceHit& hit) {
  Vec3 p = ray.at(t);
  const double h = 1e-7;
  Vec3 g(superellipsoid_value(s, p + Vec3(h, 0, 0)) - superellipsoid_value(s, p - Vec3(h, 0, 0)),
         superellipsoid_value(s, p + Vec3(0, h, 0)) - superellipsoid_value(s, p - Vec3(0, h, 0)),
         superellipsoid_value(s, p + Vec3(0, 0, h)) - superellipsoid_value(s, p - Vec3(0, 0, h)));
  double len = glm::length(g);
  Vec3 n = len > 0.0 && std::isfinite(len) ? g / len : (glm::length(p) > 0.0 ? glm::normalize(p) : Vec3(0, 0, 1));
  hit.t = t;
  hit.point = p;
  // The bisection ends at the last bit of t; the point then carries the ray's own rounding.
  hit.error = 4.0 * ray_point_error(ray, t);
  hit.normal = n;
  hit.shading_normal = n;
  hit.has_uv = false;
}

inline bool intersect(const Superellipsoid& s, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double ts[8];
  int n = superellipsoid_crossings(s, ray, ts, 8);
  for (int i = 0; i < n; ++i)
    if (ray_t.surrounds(ts[i])) {
      superellipsoid_hit_at(s, ray, ts[i], hit);
      return true;
    }
  return false;
}

}  // namespace rts::render
