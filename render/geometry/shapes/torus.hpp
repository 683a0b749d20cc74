// Torus in the x-z plane around the y axis, centred at the origin (POV-Ray's orientation):
// `major` is the radius of the ring through the tube's centre, `minor` the tube's radius.
// UVs: u around y from +x (as the sphere's), v around the tube from its outer equator.
//
// Ray-torus is a quartic. Its coefficients are formed about the ray's point closest to the
// centre with a unit direction, so they stay of the torus's own size however far away the ray
// starts; the roots are isolated by poly_roots (no closed form to lose digits to), then
// polished by Newton steps on the tube's signed distance |(rho - R, y)| - r, whose slope along
// the ray is the cosine of incidence, not a product of radii: thin tori (minor/major 1e-4)
// keep their full precision.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/poly_roots.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/params.hpp"
#include "render/geometry/surface_hit.hpp"

namespace rts::render {

// The `torus` block: see docs/shapes.md#torus.
template <>
struct ShapeTraits<Torus> {
  static constexpr PropertyInfo kProperties[] = {
      {"major", "number > 0", "*required*", "Radius of the ring through the tube's centre (in the x–z plane)."},
      {"minor", "number > 0, ≤ `major`", "*required*", "Radius of the tube."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "torus", .properties = kProperties, .closure = Closure::Closed, .has_uv = true};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Torus build(ParamSet& ps) {
    Torus g;
    g.major = positive(ps, "major", ps.require_number("major"));
    g.minor = positive(ps, "minor", ps.require_number("minor"));
    if (!(g.minor <= g.major))
      throw SceneError(loc_of(ps, "minor"),
                       fmt::format("torus minor radius {} must be <= major radius {} (a self-intersecting spindle "
                                   "torus is not supported)",
                                   g.minor, g.major));
    return g;
  }
};

inline AABB bounds(const Torus& t) {
  double a = std::abs(t.major) + std::abs(t.minor), r = std::abs(t.minor);
  return AABB{Vec3(-a, -r, -a), Vec3(a, r, a)};
}

// Signed distance from p to the torus surface (negative inside), and its gradient.
inline double torus_distance(const Torus& tor, const Vec3& p, Vec3* grad = nullptr) {
  double rho = std::sqrt(p.x * p.x + p.z * p.z);
  double qx = rho - tor.major, qy = p.y;
  double q = std::hypot(qx, qy);
  if (grad) {
    if (q > 0.0) {
      double cx = rho > 0.0 ? p.x / rho : 1.0, cz = rho > 0.0 ? p.z / rho : 0.0;
      *grad = Vec3(qx / q * cx, qy / q, qx / q * cz);
    } else {
      *grad = Vec3(0, 1, 0);  // on the tube's centre circle (never on the surface)
    }
  }
  return q - tor.minor;
}

// Every crossing of the torus surface along the whole line origin + t direction, ascending;
// returns 0, 2 or 4 (tangent double roots are not crossings).
inline int torus_crossings(const Torus& tor, const Ray& ray, double* t_out) {
  const double R = tor.major, r = tor.minor;
  if (!(r > 0.0) || !(R >= r)) return 0;
  // The quartic's constant term is R^4 (overflowing past R ~ 1e77, underflowing below 1e-77):
  // a torus far from unit size is solved scaled by a power of two near 1 / R (exact), its
  // parameters scaled back. Inside tol::kUnscaledLength* nothing is scaled: the old bits.
  if (!(R > tol::kUnscaledLengthMin && R < tol::kUnscaledLengthMax) && std::isfinite(R)) {
    const double scale = std::ldexp(1.0, -std::ilogb(R));
    const int n = torus_crossings(Torus{R * scale, r * scale}, Ray{ray.origin * scale, ray.direction}, t_out);
    for (int i = 0; i < n; ++i) t_out[i] /= scale;
    return n;
  }
  double len = glm::length(ray.direction);
  if (!(len > 0.0) || !std::isfinite(len)) return 0;
  Vec3 d = ray.direction / len;
  double s0 = -glm::dot(ray.origin, d);          // unit-speed parameter of the closest point
  Vec3 p0 = ray.origin + s0 * d;
  double outer = R + r;
  double p0_2 = glm::dot(p0, p0);
  if (p0_2 > outer * outer * (1.0 + 1e-12)) return 0;  // misses the bounding sphere
  double half = std::sqrt(std::max(outer * outer - p0_2, 0.0)) * (1.0 + 1e-9) + 1e-12 * outer;
  // |p|^2 = s^2 + |p0|^2 (p0 is perpendicular to d), so with k = |p0|^2 + R^2 - r^2:
  // f(s) = (s^2 + k)^2 - 4 R^2 ((p0x + s dx)^2 + (p0z + s dz)^2).
  double k = p0_2 + R * R - r * r;
  double a2 = d.x * d.x + d.z * d.z, a1 = 2.0 * (p0.x * d.x + p0.z * d.z), a0 = p0.x * p0.x + p0.z * p0.z;
  double four_r2 = 4.0 * R * R;
  double c[5] = {k * k - four_r2 * a0, -four_r2 * a1, 2.0 * k - four_r2 * a2, 0.0, 1.0};
  double s[4];
  int n = poly_roots(c, 4, -half, half, s);
  // Sign changes come in pairs (outside at both ends); an odd count means a root hid in
  // rounding at a tangent: drop the crossing pair it belongs to by keeping an even count.
  if (n % 2 == 1) --n;
  for (int i = 0; i < n; ++i) {
    double t = (s0 + s[i]) / len;
    // Polish on the signed distance, staying between the neighbouring roots.
    double lo = i > 0 ? (s0 + s[i - 1]) / len : -Interval::kInfinity;
    double hi = i + 1 < n ? (s0 + s[i + 1]) / len : Interval::kInfinity;
    for (int step = 0; step < 2; ++step) {
      Vec3 g;
      double h = torus_distance(tor, ray.at(t), &g);
      double slope = glm::dot(g, ray.direction);
      if (slope == 0.0 || !std::isfinite(h)) break;
      double next = t - h / slope;
      if (!(next > lo && next < hi) || std::abs(next - t) > 0.5 * r / len) break;
      t = next;
    }
    t_out[i] = t;
  }
  // At most four: an insertion sort (std::sort's general paths made GCC 12 warn of indices
  // past the caller's four-element arrays, -Warray-bounds, which it cannot bound).
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && t_out[j] < t_out[j - 1]; --j) std::swap(t_out[j], t_out[j - 1]);
  return n;
}

inline glm::dvec2 torus_uv(const Torus& tor, const Vec3& p) {
  double rho = std::sqrt(p.x * p.x + p.z * p.z);
  double u = 0.5 + std::atan2(p.z, p.x) / (2.0 * std::numbers::pi);
  double v = std::atan2(p.y, rho - tor.major) / (2.0 * std::numbers::pi);
  return {u, v < 0.0 ? v + 1.0 : v};
}

// The hit at crossing t (one of torus_crossings'): the point re-projected onto the tube, so
// its error is relative to the torus's size, not to how far the ray travelled.
inline void torus_hit_at(const Torus& tor, const Ray& ray, double t, SurfaceHit& hit) {
  Vec3 p = ray.at(t);
  double rho = std::sqrt(p.x * p.x + p.z * p.z);
  Vec3 ring = rho > 0.0 ? Vec3(p.x / rho, 0.0, p.z / rho) * tor.major : Vec3(tor.major, 0, 0);
  Vec3 rel = p - ring;
  double rel_len = glm::length(rel);
  Vec3 n = rel_len > 0.0 ? rel / rel_len : Vec3(0, 1, 0);
  hit.t = t;
  hit.point = ring + tor.minor * n;
  hit.error = error_gamma(12) * (std::abs(tor.major) + std::abs(tor.minor));
  hit.normal = n;
  hit.shading_normal = n;
  hit.uv = torus_uv(tor, hit.point);
  hit.has_uv = true;
}

inline bool intersect(const Torus& tor, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double ts[4];
  int n = torus_crossings(tor, ray, ts);
  for (int i = 0; i < n; ++i)
    if (ray_t.surrounds(ts[i])) {
      torus_hit_at(tor, ray, ts[i], hit);
      return true;
    }
  return false;
}

}  // namespace rts::render
