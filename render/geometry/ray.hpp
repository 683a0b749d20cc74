// Rays, and spawning secondary rays off a surface without hitting it again.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/scene/scene.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

// The direction need not be unit length: object-space rays keep the world ray's parameter t,
// so their direction carries the inverse transform's scale.
struct Ray {
  Vec3 origin{0.0};
  Vec3 direction{0, 0, 1};
  Vec3 at(double t) const { return origin + t * direction; }
};

// Whether |v|^2 is computed without overflow or underflow (|v| between about 1e-150 and
// 1e150), where glm::length and glm::normalize are exact to their rounding.
inline bool squares_in_range(const Vec3& v) {
  const double len2 = glm::dot(v, v);
  return len2 > 1e-300 && len2 < 1e300;
}

// |v| without overflowing or underflowing its squares (glm::length is infinite past about
// 1e154): outside that range scaled by the largest component first; inside it glm::length's
// own bits. 0, infinity and NaN come back as they are.
inline double scaled_length(const Vec3& v) {
  if (squares_in_range(v)) return glm::length(v);
  const double m = max_abs_component(v);
  if (!(m > 0.0) || !std::isfinite(m)) return m;
  return m * glm::length(v / m);
}

// v / |v| for any finite non-zero v, however long or short (glm::normalize gives zero or NaN
// outside the range above: a camera 1e200 units from its look_at saw nothing), with
// glm::normalize's own bits inside it.
inline Vec3 unit_vector(const Vec3& v) {
  return squares_in_range(v) ? glm::normalize(v) : glm::normalize(v / max_abs_component(v));
}

// Higham's gamma(n) = n u / (1 - n u), u = 2^-53: the relative error bound of a result of n
// rounded double operations (pbrt-v4 section 6.8).
constexpr double error_gamma(int n) {
  constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
  return n * u / (1.0 - n * u);
}

// Whether `ray` runs parallel to a plane of normal n within tol::kParallelCosine: |denom| <=
// kParallelCosine |n| |d|, with denom = dot(n, d), |n| = n_len and n_len2 = |n|^2. Compared
// squared first, without a square root per test (profile finding, path-traced Cornell box: the
// quad test's two square roots were its hottest instructions); only where the squares say
// parallel, or overflow or underflow, does the exact form decide. Quads, planes and discs.
inline bool nearly_parallel(double denom, double n_len2, double n_len, const Ray& ray) {
  constexpr double kParallel2 = tol::kParallelCosine * tol::kParallelCosine;
  return !(denom * denom > kParallel2 * n_len2 * glm::dot(ray.direction, ray.direction)) &&
         std::abs(denom) <= tol::kParallelCosine * n_len * glm::length(ray.direction);
}

// The absolute error bound (per component) of p = o + t d computed in doubles, for shapes
// that do not re-derive the hit point from their own parameters; t's own rounding counts as
// a few more operations.
inline double ray_point_error(const Ray& ray, double t) {
  return error_gamma(tol::kRayPointOps) *
         (max_abs_component(ray.origin) + std::abs(t) * max_abs_component(ray.direction));
}

// Moves `point` off the surface with unit geometric normal `normal` towards the side that
// `direction` leaves into, by the point's own rounding error bound `error` (pbrt-v4's
// OffsetRayOrigin: the distance along the normal of the box of possible true points, with a
// safety factor for the intersection routines' own rounding). The offset is relative to the
// hit's own magnitude, not to the scene: 1e7 from the origin it is ~1e-7 units, not 1e-2.
inline Vec3 offset_ray_origin(const Vec3& point, const Vec3& normal, const Vec3& direction, double error) {
  double n1 = std::abs(normal.x) + std::abs(normal.y) + std::abs(normal.z);
  double offset = std::max(tol::kOffsetErrorScale * error * n1, tol::kMinRayOffset);
  return glm::dot(normal, direction) >= 0.0 ? point + offset * normal : point - offset * normal;
}

}  // namespace rts::render
