// Surface of revolution (POV-Ray's `sor { N, <r0, h0>, ..., <rN-1, hN-1> [open] }`): about the
// y axis, radius^2 = P_j(y) on each of the N - 3 segments between the points 1 .. N-2, P_j the
// cubic through (h_j, r_j^2) and (h_j+1, r_j+1^2) whose slopes come from the neighbouring points
// (POV-Ray's fit: d(r^2)/dh = 2 r_j (r_j+1 - r_j-1) / (h_j+1 - h_j-1)); points 0 and N-1 only
// set the end slopes. Unless `open`, discs at the lowest and highest point close the solid
// { h_1 <= y <= h_N-2, x^2 + z^2 <= P(y) } (a CSG operand).
//
// Along a ray the surface is F(s) = x(s)^2 + z(s)^2 - P_j(y(s)) = 0, a cubic in s on each
// segment's slab. The ray is clipped to the bounding cylinder and the slab of heights, then
// walked piece by piece in ray order; each piece's cubic is formed about the piece's middle
// (coefficients of the shape's own size however far away the ray starts, never formed at the
// ray's origin where they cancel) and its roots isolated by the derivative's roots with the
// sign at each knot shared by the two pieces that meet there, so a crossing at a knot is
// counted once and the crossings alternate in and out. The caps are where the clipped span
// starts or ends inside (F < 0 at a slab end). Each root is then polished by Newton steps on
// F at the ray's own point.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/poly_roots.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/scene/params.hpp"

namespace rts::render {

// Computes the segments' cubics and the bounds from s.points (already checked).
inline void sor_setup(SorData& s) {
  const std::vector<Vec3>& p = s.points;
  const int n = static_cast<int>(p.size());
  s.segments.clear();
  double r2_max = 0.0;
  for (int i = 0; i + 3 < n; ++i) {
    SorSegment seg;
    seg.h0 = p[i + 1].y;
    seg.h1 = p[i + 2].y;
    const double dh = seg.h1 - seg.h0;
    const double y0 = p[i + 1].x * p[i + 1].x, y1 = p[i + 2].x * p[i + 2].x;
    const double m0 = 2.0 * p[i + 1].x * (p[i + 2].x - p[i].x) / (p[i + 2].y - p[i].y);
    const double m1 = 2.0 * p[i + 2].x * (p[i + 3].x - p[i + 1].x) / (p[i + 3].y - p[i + 1].y);
    // Hermite form in u = y - h0 (the same cubic as POV-Ray's global fit, without its w^3 terms).
    const double slope = (y1 - y0) / dh;
    seg.c[0] = y0;
    seg.c[1] = m0;
    seg.c[2] = (3.0 * slope - 2.0 * m0 - m1) / dh;
    seg.c[3] = (m0 + m1 - 2.0 * slope) / (dh * dh);
    // The largest r^2 on the segment: its ends and the cubic's turning points inside.
    double hi = std::max(y0, y1);
    double crit[2];
    int nc = 0;
    const double d0 = seg.c[1], d1 = 2.0 * seg.c[2], d2 = 3.0 * seg.c[3];
    if (d2 != 0.0) {
      double disc = d1 * d1 - 4.0 * d2 * d0;
      if (disc >= 0.0) {
        double sq = std::sqrt(disc);
        crit[nc++] = (-d1 - sq) / (2.0 * d2);
        crit[nc++] = (-d1 + sq) / (2.0 * d2);
      }
    } else if (d1 != 0.0) {
      crit[nc++] = -d0 / d1;
    }
    for (int k = 0; k < nc; ++k) {
      double u = std::clamp(crit[k], 0.0, dh);
      hi = std::max(hi, seg.c[0] + u * (seg.c[1] + u * (seg.c[2] + u * seg.c[3])));
    }
    seg.r2_max = hi;
    r2_max = std::max(r2_max, hi);
    s.segments.push_back(seg);
  }
  s.radius = std::sqrt(r2_max);
  s.h_min = s.segments.front().h0;
  s.h_max = s.segments.back().h1;
  s.base_r2 = std::max(0.0, s.segments.front().c[0]);
  const SorSegment& top = s.segments.back();
  const double u = top.h1 - top.h0;
  s.cap_r2 = std::max(0.0, top.c[0] + u * (top.c[1] + u * (top.c[2] + u * top.c[3])));
}

// The `sor` block: see docs/shapes.md#sor.
template <>
struct ShapeTraits<Sor> {
  static constexpr PropertyInfo kProperties[] = {
      {"points", "list of `[r, h]`, at least 4", "*required*",
       "The profile: radius r at height h. Heights increase from the second point to the one before last; the "
       "first and last points only set the end slopes."},
      {"open", "bool", "`false`", "`true` leaves out the discs closing the bottom and top (then not a CSG operand)."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "sor", .properties = kProperties, .closure = Closure::WhenCapped, .has_uv = true};
  static Sor build(ParamSet& ps) {
    SorData g;
    const ParamValue* v = ps.value("points");
    if (!v) ps.fail_block("sor needs property 'points'");
    if (const auto* rows = std::get_if<RowsParam>(v)) {
      for (std::size_t i = 0; i < rows->rows.size(); ++i) {
        const RowsParam::Row& r = rows->rows[i];
        if (!r.vectors.empty() || r.numbers.size() != 2)
          throw SceneError(loc_of(ps, "points"), fmt::format("sor point {} must be a pair [r, h]", i + 1));
        g.points.emplace_back(r.numbers[0], r.numbers[1], 0.0);
      }
    } else if (const auto* list = std::get_if<std::vector<Vec3>>(v)) {
      g.points = *list;  // <r, h, 0>
    } else if (const auto* empty = std::get_if<std::vector<double>>(v); !(empty && empty->empty())) {
      throw SceneError(loc_of(ps, "points"), fmt::format("property 'points' of sor expects a list of pairs [r, h], "
                                                         "got a {}",
                                                         param_type_name(*v)));
    }
    const int n = static_cast<int>(g.points.size());
    if (n < 4)
      throw SceneError(loc_of(ps, "points"),
                       fmt::format("sor needs at least 4 points (the first and last set the end slopes), got {}", n));
    if (n > kMaxSorPoints)
      throw SceneError(loc_of(ps, "points"), fmt::format("sor has {} points, more than the {} one sor may hold", n,
                                                         kMaxSorPoints));
    for (int i = 0; i < n; ++i) {
      const Vec3& q = g.points[i];
      if (!std::isfinite(q.x) || !std::isfinite(q.y))
        throw SceneError(loc_of(ps, "points"), fmt::format("sor point {} is not finite", i + 1));
      if (q.x < 0.0)
        throw SceneError(loc_of(ps, "points"),
                         fmt::format("sor point {} [{}, {}]: the radius must be >= 0", i + 1, q.x, q.y));
      if (i >= 2 && i <= n - 2 && !(q.y > g.points[i - 1].y))
        throw SceneError(loc_of(ps, "points"),
                         fmt::format("sor point {} [{}, {}]: the heights must increase from point 2 to point {}, but "
                                     "{} follows {}",
                                     i + 1, q.x, q.y, n - 1, q.y, g.points[i - 1].y));
    }
    // The end slopes divide by these height differences (POV-Ray refuses them too, below its
    // absolute 1e-10; here a proportion of the profile's size when that is below 1, so a sor
    // modelled at 1e-13 units is not refused).
    double size = 0.0;
    for (const auto& q : g.points) size = std::max({size, std::abs(q.x), std::abs(q.y)});
    const double min_rise = 1e-10 * std::min(1.0, size);
    if (!(std::abs(g.points[2].y - g.points[0].y) > min_rise))
      throw SceneError(loc_of(ps, "points"), "sor points 1 and 3 must differ in height (they set the bottom slope)");
    if (!(std::abs(g.points[n - 1].y - g.points[n - 3].y) > min_rise))
      throw SceneError(loc_of(ps, "points"),
                       fmt::format("sor points {} and {} must differ in height (they set the top slope)", n - 2, n));
    g.open = ps.boolean("open", g.open);
    sor_setup(g);
    return Sor(std::move(g));
  }
};

inline AABB bounds(const SorData& s) {
  const double r = s.radius * (1.0 + 1e-9);
  return AABB{Vec3(-r, s.h_min, -r), Vec3(r, s.h_max, r)};
}

enum class SorPart : uint8_t { Base, Cap, Curve };
struct SorCrossing {
  double t;
  SorPart part;
  int segment;
};
// Three per segment and the two caps.
inline constexpr int kMaxSorCrossings = 3 * kMaxSorPoints + 2;

namespace detail {

// r^2 on segment `seg` at u = y - h0, and its derivative.
inline double sor_r2(const SorSegment& seg, double u) {
  return seg.c[0] + u * (seg.c[1] + u * (seg.c[2] + u * seg.c[3]));
}
inline double sor_dr2(const SorSegment& seg, double u) { return seg.c[1] + u * (2.0 * seg.c[2] + u * 3.0 * seg.c[3]); }

// The roots of e (degree n) in [lo, hi] where it changes sign, given the signs at the ends
// (shared with the neighbouring pieces); ascending.
inline int sor_piece_roots(const double* e, int n, double lo, double hi, bool lo_neg, bool hi_neg, double* out) {
  if (n == 0) return 0;
  double ends[4];
  int ne = 0;
  ends[ne++] = lo;
  if (n >= 2) {
    double d[3];
    for (int i = 1; i <= n; ++i) d[i - 1] = i * e[i];
    double crit[2];
    int nc = poly_roots(d, n - 1, lo, hi, crit);
    for (int i = 0; i < nc; ++i) ends[ne++] = crit[i];
  }
  ends[ne++] = hi;
  int count = 0;
  bool prev = lo_neg;
  for (int i = 1; i < ne; ++i) {
    bool neg = i == ne - 1 ? hi_neg : poly_eval(e, n, ends[i]) < 0.0;
    if (neg != prev) out[count++] = std::clamp(poly_bracketed_root(e, n, ends[i - 1], ends[i], prev), ends[i - 1], ends[i]);
    prev = neg;
  }
  return count;
}

}  // namespace detail

// Every crossing of the surface (caps included unless open) along the whole line beyond
// t_after, ascending (the first max_out); returns how many. Closed, over the whole line: they
// alternate in and out, starting outside. The walk runs in ray order, so they come sorted.
inline int sor_crossings(const SorData& s, const Ray& ray, SorCrossing* out, int max_out,
                         double t_after = -Interval::kInfinity) {
  if (s.segments.empty()) return 0;
  const double len = glm::length(ray.direction);
  if (!(len > 0.0) || !std::isfinite(len)) return 0;
  const Vec3 d = ray.direction / len;
  // The unit-speed base point: the ray's point nearest the shape's centre on the axis.
  const Vec3 centre(0.0, 0.5 * (s.h_min + s.h_max), 0.0);
  const double sc = -glm::dot(ray.origin - centre, d);
  const Vec3 p0 = ray.origin + sc * d;
  const double R = s.radius * (1.0 + 1e-7) + 1e-300;
  const double half_h = 0.5 * (s.h_max - s.h_min);
  {
    Vec3 rel = p0 - centre;
    if (glm::dot(rel, rel) > (R * R + half_h * half_h) * (1.0 + 1e-9)) return 0;
  }
  // Offsets from the base point: inside the bounding cylinder and the slab of heights.
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
  double slab_lo = -Interval::kInfinity, slab_hi = Interval::kInfinity;
  if (d.y != 0.0) {
    slab_lo = (s.h_min - p0.y) / d.y;
    slab_hi = (s.h_max - p0.y) / d.y;
    if (slab_lo > slab_hi) std::swap(slab_lo, slab_hi);
  } else if (p0.y < s.h_min || p0.y > s.h_max) {
    return 0;
  }
  const bool start_on_cap = slab_lo >= lo, end_on_cap = slab_hi <= hi;
  const double S0 = std::max(lo, slab_lo), S1 = std::min(hi, slab_hi);
  if (!(S0 < S1) || !std::isfinite(S0) || !std::isfinite(S1)) return 0;

  const int nseg = static_cast<int>(s.segments.size());
  const bool up = d.y >= 0.0;
  int count = 0;
  auto emit = [&](double off, SorPart part, int seg) {
    double t = (sc + off) / len;
    if (count < max_out && t > t_after) out[count++] = SorCrossing{t, part, seg};
  };
  bool have_prev = false, prev_neg = false;
  for (int k = 0; k < nseg; ++k) {
    const int j = up ? k : nseg - 1 - k;
    const SorSegment& seg = s.segments[j];
    double plo = S0, phi = S1;
    if (d.y != 0.0) {
      double e0 = (seg.h0 - p0.y) / d.y, e1 = (seg.h1 - p0.y) / d.y;
      if (j == 0) e0 = up ? slab_lo : slab_hi;  // the slab's own ends, exactly
      if (j == nseg - 1) e1 = up ? slab_hi : slab_lo;
      if (e0 > e1) std::swap(e0, e1);
      plo = std::max(plo, e0);
      phi = std::min(phi, e1);
      if (!(plo < phi)) continue;
    } else if (!(p0.y >= seg.h0 && (p0.y < seg.h1 || (j == nseg - 1 && p0.y <= seg.h1)))) {
      continue;
    }
    // The cubic about the piece's middle: F(m + x) = e0 + e1 x + e2 x^2 + e3 x^3.
    const double m = 0.5 * (plo + phi);
    const Vec3 pm = p0 + m * d;
    const double w = pm.y - seg.h0;
    const double e[4] = {pm.x * pm.x + pm.z * pm.z - detail::sor_r2(seg, w),
                         2.0 * (pm.x * d.x + pm.z * d.z) - detail::sor_dr2(seg, w) * d.y,
                         a - (seg.c[2] + 3.0 * seg.c[3] * w) * d.y * d.y, -seg.c[3] * d.y * d.y * d.y};
    int deg = 3;
    while (deg > 0 && e[deg] == 0.0) --deg;
    const double xlo = plo - m, xhi = phi - m;
    const bool lo_neg = have_prev ? prev_neg : poly_eval(e, deg, xlo) < 0.0;
    const bool hi_neg = poly_eval(e, deg, xhi) < 0.0;
    if (!have_prev && lo_neg && start_on_cap && !s.open)
      emit(plo, up ? SorPart::Base : SorPart::Cap, j);
    double roots[3];
    int nr = detail::sor_piece_roots(e, deg, xlo, xhi, lo_neg, hi_neg, roots);
    for (int i = 0; i < nr; ++i) {
      // Newton on F at the ray's own point, kept inside the piece and only while |F| falls.
      double t = (sc + m + roots[i]) / len;
      const double tlo = (sc + plo) / len, thi = (sc + phi) / len;
      auto f_at = [&](double tt, double* df) {
        Vec3 p = ray.at(tt);
        double u = p.y - seg.h0;
        if (df) *df = 2.0 * (p.x * ray.direction.x + p.z * ray.direction.z) - detail::sor_dr2(seg, u) * ray.direction.y;
        return p.x * p.x + p.z * p.z - detail::sor_r2(seg, u);
      };
      for (int step = 0; step < 2; ++step) {
        double df;
        double f = f_at(t, &df);
        if (f == 0.0 || df == 0.0 || !std::isfinite(f) || !std::isfinite(df)) break;
        double next = t - f / df;
        if (!(next >= tlo && next <= thi) || !(std::abs(f_at(next, nullptr)) < std::abs(f))) break;
        t = next;
      }
      if (count < max_out && t > t_after) out[count++] = SorCrossing{t, SorPart::Curve, j};
    }
    have_prev = true;
    prev_neg = hi_neg;
    if (count == max_out) break;
  }
  if (have_prev && prev_neg && end_on_cap && !s.open) emit(S1, up ? SorPart::Cap : SorPart::Base, up ? nseg - 1 : 0);
  std::sort(out, out + count, [](const SorCrossing& x, const SorCrossing& y) { return x.t < y.t; });
  return count;
}

inline glm::dvec2 sor_uv(const SorData& s, const Vec3& p, SorPart part, int segment) {
  // POV-Ray's: u the angle from +x towards +z over 2 pi; v up the segments (each 1/(N-3)), the
  // base disc from -1 at its centre to 0 at its rim, the top from 2 to 1.
  double u = std::atan2(p.z, p.x) / (2.0 * std::numbers::pi);
  if (u < 0.0) u += 1.0;
  double rho = std::sqrt(p.x * p.x + p.z * p.z), v = 0.0;
  const int nseg = static_cast<int>(s.segments.size());
  if (part == SorPart::Curve) {
    const SorSegment& seg = s.segments[segment];
    v = ((p.y - seg.h0) / (seg.h1 - seg.h0) + segment) / nseg;
  } else if (part == SorPart::Base) {
    v = s.base_r2 > 0.0 ? rho / std::sqrt(s.base_r2) - 1.0 : 0.0;
  } else {
    v = s.cap_r2 > 0.0 ? 2.0 - rho / std::sqrt(s.cap_r2) : 1.0;
  }
  return {u, v};
}

inline void sor_hit_at(const SorData& s, const Ray& ray, const SorCrossing& c, SurfaceHit& hit) {
  Vec3 p = ray.at(c.t);
  Vec3 n;
  double err = 4.0 * ray_point_error(ray, c.t);
  if (c.part == SorPart::Curve) {
    const SorSegment& seg = s.segments[c.segment];
    double u = p.y - seg.h0;
    Vec3 g(2.0 * p.x, -detail::sor_dr2(seg, u), 2.0 * p.z);
    double gl = glm::length(g);
    n = gl > 0.0 && std::isfinite(gl) ? g / gl : Vec3(0, p.y > 0.5 * (s.h_min + s.h_max) ? 1 : -1, 0);
    // How far the point may be off the surface: F's value and its rounding over the gradient.
    double f = p.x * p.x + p.z * p.z - detail::sor_r2(seg, u);
    double mag = p.x * p.x + p.z * p.z + std::abs(seg.c[0]) + std::abs(u * seg.c[1]) + std::abs(u * u * seg.c[2]) +
                 std::abs(u * u * u * seg.c[3]);
    double size = s.radius + std::max(std::abs(s.h_min), std::abs(s.h_max));
    double off = gl > 0.0 ? (std::abs(f) + error_gamma(16) * mag) / gl : error_gamma(16) * size;
    err += 2.0 * std::min(off, 1e-3 * size + error_gamma(16) * size);
  } else {
    p.y = c.part == SorPart::Base ? s.h_min : s.h_max;
    n = Vec3(0, c.part == SorPart::Base ? -1 : 1, 0);
  }
  hit.t = c.t;
  hit.point = p;
  hit.error = err;
  hit.normal = n;
  hit.shading_normal = n;
  hit.uv = sor_uv(s, p, c.part, c.segment);
  hit.has_uv = true;
}

inline bool intersect(const SorData& s, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  SorCrossing cs[4];
  int n = sor_crossings(s, ray, cs, 4, ray_t.min);
  for (int i = 0; i < n; ++i)
    if (ray_t.surrounds(cs[i].t)) {
      sor_hit_at(s, ray, cs[i], hit);
      return true;
    }
  return false;
}

// The shape as the scene and the world hold it (its data boxed: scene.hpp).
inline AABB bounds(const Sor& s) { return bounds(*s); }
inline bool intersect(const Sor& s, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  return intersect(*s, ray, ray_t, hit);
}

}  // namespace rts::render
