// Lathe (POV-Ray's `lathe { linear_spline N, <r0, h0>, ..., <rN-1, hN-1> }`): the profile's
// straight segments turned about the y axis, each a cone frustum (a cylinder when its radii
// agree, a flat ring when its heights do). Only POV-Ray's linear_spline (its default) so far.
// As in POV-Ray the solid is what the profile encloses, counted even-odd; it is closed (a CSG
// operand) when the profile is: its last point is its first, or both ends lie on the axis.
//
// Along a ray each frustum is x^2 + z^2 = r(y)^2 with r linear in y: a quadratic in the ray
// parameter, formed about the middle of the ray's stretch inside the segment's band of
// heights (coefficients of the shape's size however far away the ray starts), its roots
// isolated by poly_roots and polished by Newton steps at the ray's own point. A segment owns
// its first end and not its last, so a ray through a joint's circle is counted once.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/keep_crossings.hpp"
#include "render/geometry/shapes/poly_roots.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/scene/params.hpp"

namespace rts::render {

// Bounds, closure and the profile's orientation (the normal's sign) from l.points.
inline void lathe_setup(Lathe& l) {
  const std::vector<Vec3>& p = l.points;
  l.radius = 0.0;
  l.h_min = Interval::kInfinity;
  l.h_max = -Interval::kInfinity;
  for (const Vec3& q : p) {
    l.radius = std::max(l.radius, q.x);
    l.h_min = std::min(l.h_min, q.y);
    l.h_max = std::max(l.h_max, q.y);
  }
  const Vec3 &first = p.front(), &last = p.back();
  l.closed = (first.x == last.x && first.y == last.y) || (first.x == 0.0 && last.x == 0.0);
  // Twice the signed area of the profile closed along the axis (r as x, h as y): positive
  // when counter-clockwise, where (dh, -dr) of each segment points out of the enclosed region.
  double area = 0.0;
  auto edge = [&](double r0, double h0, double r1, double h1) { area += r0 * h1 - r1 * h0; };
  for (std::size_t i = 0; i + 1 < p.size(); ++i) edge(p[i].x, p[i].y, p[i + 1].x, p[i + 1].y);
  edge(last.x, last.y, 0.0, last.y);
  edge(0.0, last.y, 0.0, first.y);
  edge(0.0, first.y, first.x, first.y);
  l.orientation = area < 0.0 ? -1.0 : 1.0;
}

// The `lathe` block: see docs/shapes.md#lathe.
template <>
struct ShapeTraits<Lathe> {
  static constexpr PropertyInfo kProperties[] = {
      {"points", "list of `[r, h]`, at least 2", "*required*",
       "The profile: radius r at height h, joined by straight segments (POV-Ray's linear_spline)."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "lathe", .properties = kProperties, .closure = Closure::WhenCapped, .has_uv = true};
  static Lathe build(ParamSet& ps) {
    Lathe g;
    const ParamValue* v = ps.value("points");
    if (!v) ps.fail_block("lathe needs property 'points'");
    if (const auto* rows = std::get_if<RowsParam>(v)) {
      for (std::size_t i = 0; i < rows->rows.size(); ++i) {
        const RowsParam::Row& r = rows->rows[i];
        if (!r.vectors.empty() || r.numbers.size() != 2)
          throw SceneError(loc_of(ps, "points"), fmt::format("lathe point {} must be a pair [r, h]", i + 1));
        g.points.emplace_back(r.numbers[0], r.numbers[1], 0.0);
      }
    } else if (const auto* list = std::get_if<std::vector<Vec3>>(v)) {
      g.points = *list;  // <r, h, 0>
    } else if (const auto* empty = std::get_if<std::vector<double>>(v); !(empty && empty->empty())) {
      throw SceneError(loc_of(ps, "points"), fmt::format("property 'points' of lathe expects a list of pairs [r, h], "
                                                         "got a {}",
                                                         param_type_name(*v)));
    }
    const int n = static_cast<int>(g.points.size());
    if (n < 2) throw SceneError(loc_of(ps, "points"), fmt::format("lathe needs at least 2 points, got {}", n));
    if (n > kMaxLathePoints)
      throw SceneError(loc_of(ps, "points"),
                       fmt::format("lathe has {} points, more than the {} one lathe may hold", n, kMaxLathePoints));
    for (int i = 0; i < n; ++i) {
      const Vec3& q = g.points[i];
      if (!std::isfinite(q.x) || !std::isfinite(q.y))
        throw SceneError(loc_of(ps, "points"), fmt::format("lathe point {} is not finite", i + 1));
      if (q.x < 0.0)
        throw SceneError(loc_of(ps, "points"),
                         fmt::format("lathe point {} [{}, {}]: the radius must be >= 0", i + 1, q.x, q.y));
    }
    lathe_setup(g);
    return g;
  }
};

inline AABB bounds(const Lathe& l) {
  const double r = l.radius * (1.0 + 1e-9);
  return AABB{Vec3(-r, l.h_min, -r), Vec3(r, l.h_max, r)};
}

struct LatheCrossing {
  double t;
  int segment;
};

// The crossings of the profile's surfaces along the whole line beyond t_after: the first
// max_out, ascending; returns how many. Closed profile, whole line: in and out alternately.
inline int lathe_crossings(const Lathe& l, const Ray& ray, LatheCrossing* out, int max_out,
                           double t_after = -Interval::kInfinity) {
  const int np = static_cast<int>(l.points.size());
  if (np < 2) return 0;
  const double len = glm::length(ray.direction);
  if (!(len > 0.0) || !std::isfinite(len)) return 0;
  const Vec3 d = ray.direction / len;
  const Vec3 centre(0.0, 0.5 * (l.h_min + l.h_max), 0.0);
  const double sc = -glm::dot(ray.origin - centre, d);
  const Vec3 p0 = ray.origin + sc * d;
  const double R = l.radius * (1.0 + 1e-7) + 1e-300;
  const double half_h = 0.5 * (l.h_max - l.h_min);
  {
    Vec3 rel = p0 - centre;
    if (glm::dot(rel, rel) > (R * R + half_h * half_h) * (1.0 + 1e-9)) return 0;
  }
  const double a = d.x * d.x + d.z * d.z;
  const double b = p0.x * d.x + p0.z * d.z, rho0 = p0.x * p0.x + p0.z * p0.z;
  double lo = -Interval::kInfinity, hi = Interval::kInfinity;
  if (a > 0.0) {
    double disc = b * b - a * (rho0 - R * R);
    if (disc < 0.0) return 0;
    double q = -(b + std::copysign(std::sqrt(disc), b));
    double r1 = q / a, r2 = q != 0.0 ? (rho0 - R * R) / q : -r1;
    lo = std::min(r1, r2);
    hi = std::max(r1, r2);
  } else if (rho0 > R * R) {
    return 0;
  }
  int count = 0;
  auto emit = [&](double off, int seg) {
    double t = (sc + off) / len;
    if (t > t_after) detail::keep_first_crossings(out, count, max_out, LatheCrossing{t, seg});
  };
  for (int j = 0; j + 1 < np; ++j) {
    const Vec3 &A = l.points[j], &B = l.points[j + 1];
    if (A.y == B.y) {
      // A flat ring at height h between the two radii (its first end's circle included).
      if (d.y == 0.0 || A.x == B.x) continue;
      double off = (A.y - p0.y) / d.y;
      if (!(off >= lo && off <= hi)) continue;
      Vec3 q = p0 + off * d;
      double rho = std::sqrt(q.x * q.x + q.z * q.z);
      double rmin = std::min(A.x, B.x), rmax = std::max(A.x, B.x);
      bool owns = A.x < B.x ? (rho >= rmin && rho < rmax) : (rho > rmin && rho <= rmax);
      if (owns) emit(off, j);
      continue;
    }
    // The stretch of the ray inside the segment's band of heights and the cylinder.
    const double hlo = std::min(A.y, B.y), hhi = std::max(A.y, B.y);
    double plo = lo, phi = hi;
    if (d.y != 0.0) {
      double e0 = (hlo - p0.y) / d.y, e1 = (hhi - p0.y) / d.y;
      if (e0 > e1) std::swap(e0, e1);
      plo = std::max(plo, e0);
      phi = std::min(phi, e1);
    } else if (p0.y < hlo || p0.y > hhi) {
      continue;
    }
    if (!(plo <= phi) || !std::isfinite(plo) || !std::isfinite(phi)) continue;
    const double k = (B.x - A.x) / (B.y - A.y);  // dr/dy
    const double m = 0.5 * (plo + phi);
    const Vec3 pm = p0 + m * d;
    const double rm = A.x + (pm.y - A.y) * k;
    // G(m + x) = |xz(m + x)|^2 - r(y(m + x))^2 = e0 + e1 x + e2 x^2.
    double e[3] = {pm.x * pm.x + pm.z * pm.z - rm * rm, 2.0 * (pm.x * d.x + pm.z * d.z) - 2.0 * rm * k * d.y,
                   a - k * k * d.y * d.y};
    int deg = 2;
    while (deg > 0 && e[deg] == 0.0) --deg;
    if (deg == 0) continue;
    // A little beyond the stretch, so a root on its end is found; ownership decides below.
    const double pad = 1e-9 * (phi - plo) + 1e-300;
    double roots[2];
    int nr = poly_roots(e, deg, plo - m - pad, phi - m + pad, roots);
    for (int i = 0; i < nr; ++i) {
      double t = (sc + m + roots[i]) / len;
      auto g_at = [&](double tt, double* dg) {
        Vec3 p = ray.at(tt);
        double r = A.x + (p.y - A.y) * k;
        if (dg)
          *dg = 2.0 * (p.x * ray.direction.x + p.z * ray.direction.z) - 2.0 * r * k * ray.direction.y;
        return p.x * p.x + p.z * p.z - r * r;
      };
      for (int step = 0; step < 2; ++step) {
        double dg;
        double g = g_at(t, &dg);
        if (g == 0.0 || dg == 0.0 || !std::isfinite(g) || !std::isfinite(dg)) break;
        double next = t - g / dg;
        if (!(std::abs(g_at(next, nullptr)) < std::abs(g))) break;
        if (std::abs(next - t) * len > 1e-6 * (phi - plo) + 1e-12 * (l.radius + half_h)) break;
        t = next;
      }
      // Owned part of the segment: from A (included) to B (excluded), by height.
      double y = ray.at(t).y;
      double w = (y - A.y) / (B.y - A.y);
      if (!(w >= 0.0 && w < 1.0)) continue;
      if (count < max_out || t < out[count - 1].t)
        if (t > t_after) detail::keep_first_crossings(out, count, max_out, LatheCrossing{t, j});
    }
  }
  return count;
}

inline void lathe_hit_at(const Lathe& l, const Ray& ray, const LatheCrossing& c, SurfaceHit& hit) {
  const Vec3 &A = l.points[c.segment], &B = l.points[c.segment + 1];
  Vec3 p = ray.at(c.t);
  double err = 4.0 * ray_point_error(ray, c.t);
  const double size = l.radius + std::max(std::abs(l.h_min), std::abs(l.h_max));
  double rho = std::sqrt(p.x * p.x + p.z * p.z);
  Vec3 radial = rho > 0.0 ? Vec3(p.x / rho, 0.0, p.z / rho) : Vec3(1, 0, 0);
  double dr = B.x - A.x, dh = B.y - A.y;
  // (dh, -dr) in (r, y), turned about y; outward for a counter-clockwise profile.
  Vec3 n = glm::normalize(Vec3(dh * radial.x, -dr, dh * radial.z)) * l.orientation;
  double w = 0.0;
  if (dh == 0.0) {
    p.y = A.y;
    w = dr != 0.0 ? (rho - A.x) / dr : 0.0;
  } else {
    double k = dr / dh;
    double r = A.x + (p.y - A.y) * k;
    double g = p.x * p.x + p.z * p.z - r * r;
    double grad = 2.0 * std::sqrt(rho * rho + r * r * k * k);
    double mag = rho * rho + r * r;
    double off = grad > 0.0 ? (std::abs(g) + error_gamma(12) * mag) / grad : error_gamma(12) * size;
    err += 2.0 * std::min(off, 1e-3 * size + error_gamma(16) * size);
    w = (p.y - A.y) / dh;
  }
  hit.t = c.t;
  hit.point = p;
  hit.error = err;
  hit.normal = n;
  hit.shading_normal = n;
  double u = std::atan2(p.z, p.x) / (2.0 * std::numbers::pi);
  if (u < 0.0) u += 1.0;
  hit.uv = {u, (c.segment + std::clamp(w, 0.0, 1.0)) / static_cast<double>(l.points.size() - 1)};
  hit.has_uv = true;
}

inline bool intersect(const Lathe& l, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  LatheCrossing c[1];
  int n = lathe_crossings(l, ray, c, 1, ray_t.min);
  if (n == 0 || !ray_t.surrounds(c[0].t)) return false;
  lathe_hit_at(l, ray, c[0], hit);
  return true;
}

}  // namespace rts::render
