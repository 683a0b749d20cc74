// Lathe (POV-Ray's `lathe { linear_spline N, <r0, h0>, ..., <rN-1, hN-1> }`, and its
// quadratic_spline, cubic_spline and bezier_spline): the profile turned about the y axis. As in
// POV-Ray the solid is what the profile encloses, counted even-odd; it is closed (a CSG operand)
// when the profile is: the curve's last point is its first, or both ends lie on the axis.
//
// Linear: each straight segment is a cone frustum (a cylinder when its radii agree, a flat ring
// when its heights do). Along a ray it is x^2 + z^2 = r(y)^2 with r linear in y: a quadratic in
// the ray parameter, formed about the middle of the ray's stretch inside the segment's band of
// heights (coefficients of the shape's size however far away the ray starts), its roots
// isolated by poly_roots and polished by Newton steps at the ray's own point. A segment owns
// its first end and not its last, so a ray through a joint's circle is counted once.
//
// Splines (spline_segments.hpp): each segment is r(t), h(t), cubics in t in [0, 1]. The ray,
// re-centred on the point of its line nearest the lathe's centre, meets height h(t) at
// s = (h(t) - y0) / dy, so x(s)^2 + z(s)^2 - r(t)^2 = 0 times dy^2 is a sextic in t whose
// roots in [0, 1] are the crossings (POV-Ray's own equation). A nearly horizontal ray divides by
// a tiny dy there, so it is solved as horizontal instead (h(t) = y0, a cubic, then the circle of
// radius r(t)). Either way each crossing is then polished by Newton steps on the pair of
// equations (height and radius) at the ray's own point, and the segment owns t in [0, 1).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/keep_crossings.hpp"
#include "render/geometry/shapes/poly_roots.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/shapes/spline_segments.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/geometry/tolerances.hpp"
#include "render/scene/params.hpp"

namespace rts::render {

namespace detail {

// The spline's segments, bounds (from the curve's turning points), closure and orientation.
inline void lathe_spline_setup(LatheData& l) {
  l.segments = spline_segments(l.spline, l.points);
  l.radius = 0.0;
  l.h_min = Interval::kInfinity;
  l.h_max = -Interval::kInfinity;
  for (const SplineSegment& g : l.segments) {
    // The surface is x^2 + z^2 = r(t)^2: a negative r (a bezier control point may pull it
    // there) turns out at |r|.
    l.radius = std::max({l.radius, std::abs(g.x_lo), std::abs(g.x_hi)});
    l.h_min = std::min(l.h_min, g.y_lo);
    l.h_max = std::max(l.h_max, g.y_hi);
  }
  const Vec3 first = spline_start(l.spline, l.points), last = spline_end(l.spline, l.points);
  l.closed = (first.x == last.x && first.y == last.y) || (first.x == 0.0 && last.x == 0.0);
  // The orientation as for the linear profile, from the curve sampled finely enough that its
  // signed area has the curve's sign (16 chords per segment).
  double area = 0.0;
  double pr = first.x, ph = first.y;
  for (const SplineSegment& g : l.segments) {
    for (int k = 1; k <= 16; ++k) {
      double t = k / 16.0, r = spline_eval(g.x, t), h = spline_eval(g.y, t);
      area += pr * h - r * ph;
      pr = r;
      ph = h;
    }
  }
  area += pr * last.y;          // to the axis at the last height,
  area -= first.x * first.y;    // (along the axis adds nothing) and out to the first point
  l.orientation = area < 0.0 ? -1.0 : 1.0;
}

}  // namespace detail

// Bounds, closure and the profile's orientation (the normal's sign) from l.points (and
// l.spline: its segments are made here).
inline void lathe_setup(LatheData& l) {
  if (l.spline != SplineKind::Linear) {
    detail::lathe_spline_setup(l);
    return;
  }
  l.segments.clear();
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
      {"points", "list of `[r, h]`", "*required*",
       "The profile: radius r at height h, joined as `spline` says. Linear: at least 2 points; quadratic: at "
       "least 3 (the first is a control point); cubic: at least 4 (the first and last are control points); "
       "bezier: 4 per segment (end, control, control, end)."},
      {"spline", "string", "`\"linear\"`",
       "`\"linear\"`, `\"quadratic\"`, `\"cubic\"` or `\"bezier\"`: POV-Ray's linear_spline, quadratic_spline, "
       "cubic_spline, bezier_spline, with the same points."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "lathe", .properties = kProperties, .closure = Closure::WhenCapped, .has_uv = true};
  static Lathe build(ParamSet& ps) {
    LatheData g;
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
    std::string spline = ps.string("spline", "linear");
    if (!spline_kind_from_name(spline, g.spline))
      throw SceneError(loc_of(ps, "spline"),
                       fmt::format("lathe spline \"{}\" is not one of \"linear\", \"quadratic\", \"cubic\", \"bezier\"",
                                   spline));
    const int n = static_cast<int>(g.points.size());
    if (g.spline == SplineKind::Linear && n < 2)
      throw SceneError(loc_of(ps, "points"), fmt::format("lathe needs at least 2 points, got {}", n));
    if (std::string need = spline_count_problem(g.spline, n, 2); !need.empty())
      throw SceneError(loc_of(ps, "points"), fmt::format("a lathe with a {} spline needs {}, got {}",
                                                         spline_kind_name(g.spline), need, n));
    if (n > kMaxLathePoints)
      throw SceneError(loc_of(ps, "points"),
                       fmt::format("lathe has {} points, more than the {} one lathe may hold", n, kMaxLathePoints));
    for (int i = 0; i < n; ++i) {
      const Vec3& q = g.points[i];
      if (!std::isfinite(q.x) || !std::isfinite(q.y))
        throw SceneError(loc_of(ps, "points"), fmt::format("lathe point {} is not finite", i + 1));
      // POV-Ray's rule: the points the curve passes through need r >= 0; control points that
      // only pull it (a quadratic's first, a cubic's first and last, a bezier's middle two) may not.
      bool control = (g.spline == SplineKind::Quadratic && i == 0) ||
                     (g.spline == SplineKind::Cubic && (i == 0 || i == n - 1)) ||
                     (g.spline == SplineKind::Bezier && (i % 4 == 1 || i % 4 == 2));
      if (q.x < 0.0 && !control)
        throw SceneError(loc_of(ps, "points"),
                         fmt::format("lathe point {} [{}, {}]: the radius must be >= 0", i + 1, q.x, q.y));
    }
    lathe_setup(g);
    return Lathe(std::move(g));
  }
};

inline AABB bounds(const LatheData& l) {
  const double r = l.radius * (1.0 + 1e-9);
  return AABB{Vec3(-r, l.h_min, -r), Vec3(r, l.h_max, r)};
}

struct LatheCrossing {
  double t;
  int segment;
  double w = 0.0;  // a spline's curve parameter in the segment (0 for linear)
};

namespace detail {

// The ray re-centred on the lathe (lathe_crossings works it out once): unit direction d, the
// ray's t of a distance s along d from p0 is (sc + s) / len; the line lies in the bounding
// cylinder for s in [lo, hi].
struct LatheRayFrame {
  Vec3 d, p0;
  double len, sc, a, b, rho0, lo, hi;
};

// Newton steps on the pair (h(w) = y, x^2 + z^2 = r(w)^2) in the ray's own t and the curve's
// w, from a first guess: the crossing to the last bit the ray's parametrisation allows, wherever
// the ray starts. Steps that do not shrink the residual are refused (a tangent ray, or a guess
// nearer another crossing). Returns false when the pair is singular at the guess.
inline bool lathe_spline_polish(const SplineSegment& g, const Ray& ray, double size, double& t, double& w) {
  auto residual = [&](double tt, double ww, double* f1, double* f2) {
    Vec3 p = ray.at(tt);
    double r = spline_eval(g.x, ww);
    *f1 = spline_eval(g.y, ww) - p.y;
    *f2 = p.x * p.x + p.z * p.z - r * r;
    return 2.0 * size * std::abs(*f1) + std::abs(*f2);  // both in units of size^2
  };
  double f1, f2;
  double res = residual(t, w, &f1, &f2);
  for (int step = 0; step < 8 && res > 0.0; ++step) {
    Vec3 p = ray.at(t);
    double r = spline_eval(g.x, w);
    // d f1 / d(t, w) and d f2 / d(t, w).
    double j00 = -ray.direction.y, j01 = spline_slope(g.y, w);
    double j10 = 2.0 * (p.x * ray.direction.x + p.z * ray.direction.z), j11 = -2.0 * r * spline_slope(g.x, w);
    double det = j00 * j11 - j01 * j10;
    if (det == 0.0 || !std::isfinite(det)) return step > 0;
    double nt = t + (-f1 * j11 + j01 * f2) / det;
    double nw = w + (-j00 * f2 + j10 * f1) / det;
    double n1, n2;
    double nres = residual(nt, nw, &n1, &n2);
    if (!(nres < res)) break;
    t = nt;
    w = nw;
    f1 = n1;
    f2 = n2;
    res = nres;
  }
  return true;
}

// lathe_crossings for a spline profile (see the top of this file).
inline int lathe_spline_walk(const LatheData& l, const Ray& ray, const LatheRayFrame& f, LatheCrossing* out,
                             int max_out, double t_after) {
  const Vec3 &d = f.d, &p0 = f.p0;
  const double size = l.radius + std::max(std::abs(l.h_min), std::abs(l.h_max));
  const bool flat = std::abs(d.y) < tol::kLatheFlatRay;
  int count = 0;
  auto keep = [&](const SplineSegment& g, int j, double t, double w) {
    if (!lathe_spline_polish(g, ray, size, t, w)) return;
    if (!(w >= 0.0 && w < 1.0) || !std::isfinite(t)) return;
    if (t > t_after) keep_first_crossings(out, count, max_out, LatheCrossing{t, j, w});
  };
  const int ns = static_cast<int>(l.segments.size());
  for (int j = 0; j < ns; ++j) {
    const SplineSegment& g = l.segments[j];
    // The stretch of the line inside the segment's band of heights and its own cylinder.
    const double rj = std::max(std::abs(g.x_lo), std::abs(g.x_hi)) * (1.0 + 1e-7) + 1e-300;
    double plo = f.lo, phi = f.hi;
    if (f.a > 0.0) {
      double disc = f.b * f.b - f.a * (f.rho0 - rj * rj);
      if (disc < 0.0) continue;
      double q = -(f.b + std::copysign(std::sqrt(disc), f.b));
      double r1 = q / f.a, r2 = q != 0.0 ? (f.rho0 - rj * rj) / q : -r1;
      plo = std::max(plo, std::min(r1, r2));
      phi = std::min(phi, std::max(r1, r2));
    } else if (f.rho0 > rj * rj) {
      continue;
    }
    if (d.y != 0.0) {
      double e0 = (g.y_lo - p0.y) / d.y, e1 = (g.y_hi - p0.y) / d.y;
      if (e0 > e1) std::swap(e0, e1);
      plo = std::max(plo, e0);
      phi = std::min(phi, e1);
    } else if (p0.y < g.y_lo || p0.y > g.y_hi) {
      continue;
    }
    if (!(plo <= phi) || !std::isfinite(plo) || !std::isfinite(phi)) continue;
    // H(w) = h(w) - y0: where the segment is at the height of p0.
    double H[4] = {g.y[0] - p0.y, g.y[1], g.y[2], g.y[3]};
    if (flat) {
      // Horizontal first: the heights where the profile meets y0, the circle of radius r there.
      int deg = 3;
      while (deg > 0 && H[deg] == 0.0) --deg;
      if (deg == 0) continue;  // a flat ring seen edge-on: a graze
      double ws[3];
      int nw = poly_roots(H, deg, -tol::kLatheSplineSearchPad, 1.0 + tol::kLatheSplineSearchPad, ws);
      for (int i = 0; i < nw; ++i) {
        double r = spline_eval(g.x, ws[i]);
        double c0 = f.rho0 - r * r;
        double disc = f.b * f.b - f.a * c0;
        if (disc <= 0.0 || f.a == 0.0) continue;  // misses (or touches) that circle
        double q = -(f.b + std::copysign(std::sqrt(disc), f.b));
        double s1 = q / f.a, s2 = q != 0.0 ? c0 / q : -s1;
        keep(g, j, (f.sc + s1) / f.len, ws[i]);
        keep(g, j, (f.sc + s2) / f.len, ws[i]);
      }
      continue;
    }
    // dy^2 (x(s)^2 + z(s)^2 - r(w)^2) with s = H(w) / dy: U^2 + V^2 - W^2, where
    // U = dy x0 + dx H, V = dy z0 + dz H, W = dy r (each a cubic in w).
    double U[4], V[4], W[4];
    for (int k = 0; k < 4; ++k) {
      U[k] = d.x * H[k];
      V[k] = d.z * H[k];
      W[k] = d.y * g.x[k];
    }
    U[0] += d.y * p0.x;
    V[0] += d.y * p0.z;
    double F[7] = {0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) F[i + k] += U[i] * U[k] + V[i] * V[k] - W[i] * W[k];
    int deg = 6;
    while (deg > 0 && F[deg] == 0.0) --deg;
    if (deg == 0) continue;
    double ws[6];
    int nw = poly_roots(F, deg, -tol::kLatheSplineSearchPad, 1.0 + tol::kLatheSplineSearchPad, ws);
    for (int i = 0; i < nw; ++i) {
      double s = spline_eval(H, ws[i]) / d.y;
      keep(g, j, (f.sc + s) / f.len, ws[i]);
    }
  }
  return count;
}

}  // namespace detail

// The crossings of the profile's surfaces along the whole line beyond t_after: the first
// max_out, ascending; returns how many. Closed profile, whole line: in and out alternately.
inline int lathe_crossings(const LatheData& l, const Ray& ray, LatheCrossing* out, int max_out,
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
  if (l.spline != SplineKind::Linear)
    return detail::lathe_spline_walk(l, ray, detail::LatheRayFrame{d, p0, len, sc, a, b, rho0, lo, hi}, out, max_out,
                                     t_after);
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

namespace detail {

// lathe_hit_at for a spline profile: the normal from the curve's tangent at the crossing.
inline void lathe_spline_hit_at(const LatheData& l, const Ray& ray, const LatheCrossing& c, SurfaceHit& hit) {
  const SplineSegment& g = l.segments[c.segment];
  Vec3 p = ray.at(c.t);
  const double size = l.radius + std::max(std::abs(l.h_min), std::abs(l.h_max));
  double rho = std::sqrt(p.x * p.x + p.z * p.z);
  Vec3 radial = rho > 0.0 ? Vec3(p.x / rho, 0.0, p.z / rho) : Vec3(1, 0, 0);
  double r = spline_eval(g.x, c.w);
  double dr = spline_slope(g.x, c.w), dh = spline_slope(g.y, c.w);
  if (dr == 0.0 && dh == 0.0) {
    // A cusp (coincident control points): the chord over a short step says which way it runs.
    double w1 = std::clamp(c.w + 1e-6, 0.0, 1.0), w0 = std::clamp(c.w - 1e-6, 0.0, 1.0);
    dr = spline_eval(g.x, w1) - spline_eval(g.x, w0);
    dh = spline_eval(g.y, w1) - spline_eval(g.y, w0);
  }
  // (dh, -dr) in (r, y), turned about y; outward for a counter-clockwise profile. Where r(w) < 0
  // the surface is at -r, the profile mirrored: the radial part turns round.
  double sr = r < 0.0 ? -1.0 : 1.0;
  Vec3 n = Vec3(sr * dh * radial.x, -dr, sr * dh * radial.z);
  double nl = glm::length(n);
  n = nl > 0.0 ? n / nl * l.orientation : Vec3(0, 1, 0);
  // How far the point may be from the surface: no farther than from the curve's point at w.
  double off = std::abs(rho - std::abs(r)) + std::abs(p.y - spline_eval(g.y, c.w)) + error_gamma(16) * size;
  hit.t = c.t;
  hit.point = p;
  hit.error = 4.0 * ray_point_error(ray, c.t) + 2.0 * std::min(off, 1e-3 * size);
  hit.normal = n;
  hit.shading_normal = n;
  double u = std::atan2(p.z, p.x) / (2.0 * std::numbers::pi);
  if (u < 0.0) u += 1.0;
  hit.uv = {u, (c.segment + std::clamp(c.w, 0.0, 1.0)) / static_cast<double>(l.segments.size())};
  hit.has_uv = true;
}

}  // namespace detail

inline void lathe_hit_at(const LatheData& l, const Ray& ray, const LatheCrossing& c, SurfaceHit& hit) {
  if (l.spline != SplineKind::Linear) {
    detail::lathe_spline_hit_at(l, ray, c, hit);
    return;
  }
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

inline bool intersect(const LatheData& l, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  LatheCrossing c[1];
  int n = lathe_crossings(l, ray, c, 1, ray_t.min);
  if (n == 0 || !ray_t.surrounds(c[0].t)) return false;
  lathe_hit_at(l, ray, c[0], hit);
  return true;
}

// The shape as the scene and the world hold it (its data boxed: scene.hpp).
inline AABB bounds(const Lathe& l) { return bounds(*l); }
inline bool intersect(const Lathe& l, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  return intersect(*l, ray, ray_t, hit);
}

}  // namespace rts::render
