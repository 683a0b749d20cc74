// Warps from the unit square to directions and points, with their densities, and the
// orthonormal frame around a shading normal: the path tracer's sampling building blocks.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

namespace rts::render::path {

using Vec3 = glm::dvec3;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInvPi = 1.0 / std::numbers::pi;

// A right-handed orthonormal basis (t, b, n) around unit n (Duff et al. 2017, branchless).
struct Frame {
  Vec3 t, b, n;
  explicit Frame(const Vec3& normal) : n(normal) {
    double sign = std::copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double c = n.x * n.y * a;
    t = Vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = Vec3(c, sign + n.y * n.y * a, -n.y);
  }
  Vec3 to_local(const Vec3& v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
  Vec3 to_world(const Vec3& v) const { return v.x * t + v.y * b + v.z * n; }
};

// Cosine-weighted hemisphere about +z (Malley: a concentric disc point lifted), pdf cos/pi.
inline Vec3 cosine_hemisphere(glm::dvec2 u) {
  double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
  double x = r * std::cos(phi), y = r * std::sin(phi);
  return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))};
}

// Uniform direction on the unit sphere, pdf 1 / (4 pi).
inline Vec3 uniform_sphere(glm::dvec2 u) {
  double z = 1.0 - 2.0 * u.x, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Uniform barycentrics (b1, b2) on a triangle (the square-root map).
inline glm::dvec2 uniform_triangle(glm::dvec2 u) {
  double s = std::sqrt(u.x);
  return {1.0 - s, u.y * s};
}

// The power heuristic with beta = 2 (Veach 1997) for a sample drawn from the strategy of
// density `pdf_a` and the competing strategy's density `pdf_b` (both solid angle).
inline double power_heuristic(double pdf_a, double pdf_b) {
  double a = pdf_a * pdf_a, b = pdf_b * pdf_b;
  if (!(a > 0.0)) return 0.0;
  if (std::isinf(a)) return 1.0;
  return a / (a + b);
}

}  // namespace rts::render::path
