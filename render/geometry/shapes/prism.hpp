// Prism (POV-Ray's `prism { linear_sweep linear_spline h1, h2, N, <x0, z0>, ... }`, and its
// quadratic_spline, cubic_spline, bezier_spline and conic_sweep): an outline in the x-z plane
// extruded along y between the two heights (or, conic, scaled by the height from the apex at
// the origin), closed by flat caps there unless open. As in POV-Ray the point list may hold
// several sub-outlines, each closed by a point that repeats its first point (a straight-edged
// last one is closed if it is not; an unclosed spline one is an error), and the inside is
// counted even-odd.
//
// Along a ray the walls are found in the x-z plane: an edge is crossed when its two ends lie
// strictly on different sides of the ray's line there, a vertex on the line counting as on the
// negative side (the crossing-number rule), so a ray through a vertex is counted once or twice
// as the polygon passes or turns there, and a ray along a wall never. The point on the edge is
// interpolated from the two side values, so it lies on the edge whatever the rounding. A spline
// curve's side of the line is a cubic in its parameter, whose sign changes are its crossings.
// The caps follow from the same crossings: the outline's parity where the ray enters the slab
// of heights (walls crossed before it) says whether that cap is crossed, and that parity plus
// the walls crossed inside the slab says whether the other one is, so crossings always come in
// pairs. (Conic walls lean, so there the caps are tested directly: prism_conic_walk.)
// The ray is re-centred on the shape first (coefficients of the shape's size however far away
// it starts). No allocation per ray.
#pragma once

#include <algorithm>
#include <cmath>
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

// Even-odd: is (x, z) inside the edges? Crossings of the line z = const left of x, with the
// same half-open rule as the walls' (an end on the line counts as below it).
inline bool prism_point_inside(const std::vector<PrismEdge>& edges, double x, double z) {
  bool in = false;
  for (const PrismEdge& e : edges) {
    bool a = e.z0 > z, b = e.z1 > z;
    if (a == b) continue;
    double u = (z - e.z0) / (e.z1 - e.z0);
    double xi = e.x0 + u * (e.x1 - e.x0);
    if (xi < x) in = !in;
  }
  return in;
}

// The cubic c(w) - v (w in [0, 1]) with its degree reduced: the sign changes poly_roots finds.
// Returns how many roots, ascending. A segment's ends are evaluated as the polynomial says:
// at w = 0 exactly its first point, at w = 1 its last to a rounding, so a line through a joint
// within ~1e-16 of the outline's size might count it on both sides or neither.
inline int prism_curve_roots(const double* c, double v, double* out) {
  double e[4] = {c[0] - v, c[1], c[2], c[3]};
  int deg = 3;
  while (deg > 0 && e[deg] == 0.0) --deg;
  if (deg == 0) return 0;  // the line runs along a straight piece: never a crossing
  return poly_roots(e, deg, 0.0, 1.0, out);
}

// Even-odd for a spline outline: crossings of the line z = const left of x.
inline bool prism_curves_inside(const std::vector<SplineSegment>& curves, double x, double z) {
  bool in = false;
  for (const SplineSegment& g : curves) {
    if (z < g.y_lo || z > g.y_hi) continue;
    double ws[3];
    int n = prism_curve_roots(g.y, z, ws);
    for (int i = 0; i < n; ++i)
      if (spline_eval(g.x, ws[i]) < x) in = !in;
  }
  return in;
}

// The spline outline's curves with POV-Ray's sub-outline rule; "" or what is wrong. Quadratic:
// each sub-outline is a control point, then points until one repeats its first curve point
// (the point after the control). Cubic: the same and one more control point after it. Bezier:
// 4 points a segment; a segment whose first point differs from the previous one's last starts
// a new sub-outline, and the previous one must end where it started. POV-Ray ignores an
// unclosed spline prism (with a warning); rts says so.
// tol::kPrismSamePoint (POV-Ray's absolute EPSILON) for outlines of unit size and larger, a
// proportion of the outline's size below it: a prism modelled at 1e-13 units had every point
// "the same" as the next, and its outline fell apart.
inline double same_point_tolerance(const std::vector<Vec3>& points) {
  double size = 0.0;
  for (const Vec3& q : points) size = std::max({size, std::abs(q.x), std::abs(q.y)});
  return tol::kPrismSamePoint * std::min(1.0, size);
}

inline std::string prism_spline_curves(PrismData& p) {
  const std::vector<Vec3>& q = p.points;
  const int n = static_cast<int>(q.size());
  const double eps = same_point_tolerance(q);
  auto same = [eps](const Vec3& a, const Vec3& b) { return std::abs(a.x - b.x) < eps && std::abs(a.y - b.y) < eps; };
  p.curves.clear();
  if (p.spline == SplineKind::Bezier) {
    int loop_start = 0;
    for (int i = 4; i < n; i += 4) {
      if (same(q[i], q[i - 1])) continue;
      if (!same(q[i - 1], q[loop_start]))
        return fmt::format("the bezier outline from point {} does not end where it starts (point {} differs from point {})",
                           loop_start + 1, i, loop_start + 1);
      loop_start = i;
    }
    if (!same(q[n - 1], q[loop_start]))
      return fmt::format("the bezier outline from point {} does not end where it starts (point {} differs from point {})",
                         loop_start + 1, n, loop_start + 1);
    p.curves = spline_segments(SplineKind::Bezier, q);
    return "";
  }
  const bool cubic = p.spline == SplineKind::Cubic;
  const int last = cubic ? 3 : 2;  // a segment uses points i .. i + last
  const std::vector<SplineSegment> all = spline_segments(p.spline, q);  // segment i starts at point i
  Vec3 first = q[1];
  int first_index = 1;
  bool closed = false;
  for (int i = 0; i < n - 1; ++i) {
    if (i + last >= n) {  // points left over that make no segment: the outline from first is open
      closed = false;
      break;
    }
    p.curves.push_back(all[i]);
    closed = same(q[i + 2], first);
    if (closed) {
      i += last;
      if (i + 2 < n) {
        first = q[i + 2];
        first_index = i + 2;
      }
    }
  }
  if (!closed)
    return fmt::format("the {} outline from point {} does not close (a later point must repeat point {}{})",
                       spline_kind_name(p.spline), first_index + 1, first_index + 1,
                       cubic ? ", followed by one control point" : "");
  return "";
}

}  // namespace detail

namespace detail {

// Edges (POV-Ray's sub-polygon rule), their outward sides, heights and bounds from p.points;
// for a spline outline its curves instead (an unclosed one has none).
inline void prism_outline_setup(PrismData& p) {
  p.y_min = std::min(p.height1, p.height2);
  p.y_max = std::max(p.height1, p.height2);
  if (p.spline != SplineKind::Linear) {
    p.edges.clear();
    if (!detail::prism_spline_curves(p).empty()) p.curves.clear();
    p.x_min = p.z_min = Interval::kInfinity;
    p.x_max = p.z_max = -Interval::kInfinity;
    for (const SplineSegment& g : p.curves) {
      p.x_min = std::min(p.x_min, g.x_lo);
      p.x_max = std::max(p.x_max, g.x_hi);
      p.z_min = std::min(p.z_min, g.y_lo);
      p.z_max = std::max(p.z_max, g.y_hi);
    }
    if (p.curves.empty()) p.x_min = p.x_max = p.z_min = p.z_max = 0.0;
    // Which side of each curve is outside: a point just off its middle, tested even-odd.
    p.curve_outward.assign(p.curves.size(), 1.0);
    for (std::size_t j = 0; j < p.curves.size(); ++j) {
      const SplineSegment& g = p.curves[j];
      double dx = spline_slope(g.x, 0.5), dz = spline_slope(g.y, 0.5), len = std::sqrt(dx * dx + dz * dz);
      if (!(len > 0.0)) continue;
      double size = std::max(p.x_max - p.x_min, p.z_max - p.z_min);
      double off = 1e-6 * size;
      double mx = spline_eval(g.x, 0.5) + off * dz / len, mz = spline_eval(g.y, 0.5) - off * dx / len;
      p.curve_outward[j] = detail::prism_curves_inside(p.curves, mx, mz) ? -1.0 : 1.0;
    }
    return;
  }
  p.curves.clear();
  p.curve_outward.clear();
  const std::vector<Vec3>& q = p.points;
  const int n = static_cast<int>(q.size());
  p.edges.clear();
  const double eps = same_point_tolerance(q);
  auto same = [eps](const Vec3& a, const Vec3& b) { return std::abs(a.x - b.x) < eps && std::abs(a.y - b.y) < eps; };
  auto add = [&](const Vec3& a, const Vec3& b) { p.edges.push_back(PrismEdge{a.x, a.y, b.x, b.y, 1.0}); };
  int first = 0;
  for (int i = 1; i < n; ++i) {
    if (i == first) continue;  // a new sub-polygon starts here
    add(q[i - 1], q[i]);
    if (same(q[i], q[first])) first = i + 1;  // closed: the next point starts another
  }
  if (first < n - 1) add(q[n - 1], q[first]);  // the last sub-polygon, closed as POV-Ray does
  p.x_min = p.z_min = Interval::kInfinity;
  p.x_max = p.z_max = -Interval::kInfinity;
  for (const PrismEdge& e : p.edges) {
    p.x_min = std::min({p.x_min, e.x0, e.x1});
    p.x_max = std::max({p.x_max, e.x0, e.x1});
    p.z_min = std::min({p.z_min, e.z0, e.z1});
    p.z_max = std::max({p.z_max, e.z0, e.z1});
  }
  if (p.edges.empty()) p.x_min = p.x_max = p.z_min = p.z_max = 0.0;
  p.y_min = std::min(p.height1, p.height2);
  p.y_max = std::max(p.height1, p.height2);
  // Which side of each edge is outside: a point just off its middle, tested even-odd.
  for (PrismEdge& e : p.edges) {
    double dx = e.x1 - e.x0, dz = e.z1 - e.z0, len = std::sqrt(dx * dx + dz * dz);
    if (!(len > 0.0)) continue;
    double off = 1e-6 * len;
    double mx = 0.5 * (e.x0 + e.x1) + off * dz / len, mz = 0.5 * (e.z0 + e.z1) - off * dx / len;
    e.outward = detail::prism_point_inside(p.edges, mx, mz) ? -1.0 : 1.0;
  }
}

// conic_sweep: the walls are walked as curves whatever the spline (straight edges as straight
// curves), and the bounds are the outline's scaled by both heights.
inline void prism_conic_setup(PrismData& p) {
  if (p.spline == SplineKind::Linear) {
    p.curves.clear();
    p.curve_outward.clear();
    for (const PrismEdge& e : p.edges) {
      SplineSegment g{{e.x0, e.x1 - e.x0, 0.0, 0.0}, {e.z0, e.z1 - e.z0, 0.0, 0.0}, std::min(e.x0, e.x1),
                      std::max(e.x0, e.x1), std::min(e.z0, e.z1), std::max(e.z0, e.z1)};
      p.curves.push_back(g);
      p.curve_outward.push_back(e.outward);
    }
  }
  auto scaled = [&](double& lo, double& hi) {
    double a = lo * p.y_min, b = lo * p.y_max, c = hi * p.y_min, d = hi * p.y_max;
    lo = std::min({a, b, c, d});
    hi = std::max({a, b, c, d});
  };
  scaled(p.x_min, p.x_max);
  scaled(p.z_min, p.z_max);
}

}  // namespace detail

// The outline's edges or curves and the bounds: see prism_outline_setup, prism_conic_setup.
inline void prism_setup(PrismData& p) {
  detail::prism_outline_setup(p);
  if (p.conic) detail::prism_conic_setup(p);
}

// Even-odd inside the solid (caps included whether open or not).
inline bool prism_inside(const PrismData& p, const Vec3& pt) {
  if (!(pt.y >= p.y_min && pt.y <= p.y_max)) return false;
  if (p.conic) return pt.y != 0.0 && detail::prism_curves_inside(p.curves, pt.x / pt.y, pt.z / pt.y);
  return p.spline != SplineKind::Linear ? detail::prism_curves_inside(p.curves, pt.x, pt.z)
                                        : detail::prism_point_inside(p.edges, pt.x, pt.z);
}

// The `prism` block: see docs/shapes.md#prism.
template <>
struct ShapeTraits<Prism> {
  static constexpr PropertyInfo kProperties[] = {
      {"points", "list of `[x, z]`, at least 3", "*required*",
       "The outline in the x-z plane, joined as `spline` says; a point repeating its sub-polygon's first "
       "point closes it and the next starts another (inside: even-odd)."},
      {"height1", "number", "`0`", "The height (y) of one cap."},
      {"height2", "number", "`1`", "The height (y) of the other cap; must differ from `height1`."},
      {"open", "bool", "`false`", "`true` leaves out the two caps (then not a CSG operand)."},
      {"sweep", "string", "`\"linear\"`",
       "`\"linear\"`: the outline is extruded unchanged (POV-Ray's linear_sweep); `\"conic\"`: the outline is scaled "
       "by the height, from a point at the origin (POV-Ray's conic_sweep: the outline as given at y = 1)."},
      {"spline", "string", "`\"linear\"`",
       "`\"linear\"`: straight edges (POV-Ray's linear_spline); `\"quadratic\"`, `\"cubic\"`, `\"bezier\"`: POV-Ray's "
       "quadratic_spline, cubic_spline, bezier_spline through the same points (each sub-outline must close)."},
  };
  static constexpr ShapeInfo kInfo{.name = "prism", .properties = kProperties, .closure = Closure::WhenCapped};
  static Prism build(ParamSet& ps) {
    PrismData g;
    const ParamValue* v = ps.value("points");
    if (!v) ps.fail_block("prism needs property 'points'");
    if (const auto* rows = std::get_if<RowsParam>(v)) {
      for (std::size_t i = 0; i < rows->rows.size(); ++i) {
        const RowsParam::Row& r = rows->rows[i];
        if (!r.vectors.empty() || r.numbers.size() != 2)
          throw SceneError(loc_of(ps, "points"), fmt::format("prism point {} must be a pair [x, z]", i + 1));
        g.points.emplace_back(r.numbers[0], r.numbers[1], 0.0);
      }
    } else if (const auto* empty = std::get_if<std::vector<double>>(v); !(empty && empty->empty())) {
      throw SceneError(loc_of(ps, "points"), fmt::format("property 'points' of prism expects a list of pairs [x, z], "
                                                         "got a {}",
                                                         param_type_name(*v)));
    }
    std::string spline = ps.string("spline", "linear");
    if (!spline_kind_from_name(spline, g.spline))
      throw SceneError(loc_of(ps, "spline"),
                       fmt::format("prism spline \"{}\" is not one of \"linear\", \"quadratic\", \"cubic\", \"bezier\"",
                                   spline));
    const int n = static_cast<int>(g.points.size());
    if (n < 3) throw SceneError(loc_of(ps, "points"), fmt::format("prism needs at least 3 points, got {}", n));
    // POV-Ray's minimums: a closed outline needs a control point, 3 points and the closing one
    // (quadratic), and one more control point (cubic).
    if (g.spline == SplineKind::Quadratic && n < 5)
      throw SceneError(loc_of(ps, "points"),
                       fmt::format("a prism with a quadratic spline needs at least 5 points (a control point, then a "
                                   "closed outline), got {}", n));
    if (g.spline == SplineKind::Cubic && n < 6)
      throw SceneError(loc_of(ps, "points"),
                       fmt::format("a prism with a cubic spline needs at least 6 points (a control point, a closed "
                                   "outline, a control point), got {}", n));
    if (std::string need = spline_count_problem(g.spline, n, 3); g.spline == SplineKind::Bezier && !need.empty())
      throw SceneError(loc_of(ps, "points"), fmt::format("a prism with a bezier spline needs {}, got {}", need, n));
    if (n > kMaxPrismPoints)
      throw SceneError(loc_of(ps, "points"),
                       fmt::format("prism has {} points, more than the {} one prism may hold", n, kMaxPrismPoints));
    for (int i = 0; i < n; ++i)
      if (!std::isfinite(g.points[i].x) || !std::isfinite(g.points[i].y))
        throw SceneError(loc_of(ps, "points"), fmt::format("prism point {} is not finite", i + 1));
    g.height1 = ps.number("height1", g.height1);
    g.height2 = ps.number("height2", g.height2);
    if (!std::isfinite(g.height1)) throw SceneError(loc_of(ps, "height1"), "prism height1 is not finite");
    if (!std::isfinite(g.height2)) throw SceneError(loc_of(ps, "height2"), "prism height2 is not finite");
    if (g.height1 == g.height2)
      throw SceneError(loc_of(ps, ps.has("height2") ? "height2" : "height1"),
                       fmt::format("prism height1 and height2 must differ (both are {})", g.height1));
    g.open = ps.boolean("open", g.open);
    std::string sweep = ps.string("sweep", "linear");
    if (sweep != "linear" && sweep != "conic")
      throw SceneError(loc_of(ps, "sweep"),
                       fmt::format("prism sweep \"{}\" is not one of \"linear\" or \"conic\"", sweep));
    g.conic = sweep == "conic";
    if (g.spline != SplineKind::Linear) {
      PrismData probe = g;
      if (std::string problem = detail::prism_spline_curves(probe); !problem.empty())
        throw SceneError(loc_of(ps, "points"), "prism: " + problem);
    }
    prism_setup(g);
    return Prism(std::move(g));
  }
};

inline AABB bounds(const PrismData& p) {
  return AABB{Vec3(p.x_min, p.y_min, p.z_min), Vec3(p.x_max, p.y_max, p.z_max)};
}

enum class PrismPart : uint8_t { Wall, Bottom, Top };

struct PrismCrossing {
  double t;
  PrismPart part;
  int edge;        // for a wall: its edge, or its curve for a spline outline
  double w = 0.0;  // for a spline wall: where on its curve
};

namespace detail {

// prism_crossings for conic_sweep: the wall of the outline's point (x, z) is the line from the
// apex (the origin) through (x, 1, z), so the ray (p0 + s d, re-centred on the shape) crosses
// the wall of curve point w where (x(w), 1, z(w)) . (p0 x d) = 0, a cubic in w; the crossing's s
// follows from the x (or z) component and counts when its height is between the caps. A cap at
// height h is crossed where the ray's point there, scaled by 1/h, is inside the outline (a cap
// at height 0 is the apex alone).
inline int prism_conic_walk(const PrismData& p, const Vec3& d, const Vec3& p0, double sc, double len, PrismCrossing* out,
                            int max_out, double t_after) {
  int count = 0;
  auto emit = [&](double s, PrismPart part, int edge, double w) {
    double t = (sc + s) / len;
    if (t > t_after) keep_first_crossings(out, count, max_out, PrismCrossing{t, part, edge, w});
  };
  const Vec3 m = glm::cross(p0, d);
  const int nc = static_cast<int>(p.curves.size());
  for (int j = 0; j < nc; ++j) {
    const SplineSegment& g = p.curves[j];
    double c[4];
    for (int k = 0; k < 4; ++k) c[k] = g.x[k] * m.x + g.y[k] * m.z;
    double ws[3];
    int nr = prism_curve_roots(c, -m.y, ws);
    for (int i = 0; i < nr; ++i) {
      const double x = spline_eval(g.x, ws[i]), z = spline_eval(g.y, ws[i]);
      // p0 + s d = y (x, 1, z): from whichever of x, z the ray's direction pins down better.
      const double hx = d.x - x * d.y, hz = d.z - z * d.y;
      double s;
      if (std::abs(hx) >= std::abs(hz)) {
        if (hx == 0.0) continue;
        s = (x * p0.y - p0.x) / hx;
      } else {
        s = (z * p0.y - p0.z) / hz;
      }
      const double y = p0.y + s * d.y;
      if (y >= p.y_min && (y < p.y_max || (p.open && y == p.y_max))) emit(s, PrismPart::Wall, j, ws[i]);
    }
  }
  if (!p.open && d.y != 0.0) {
    for (PrismPart part : {PrismPart::Bottom, PrismPart::Top}) {
      const double h = part == PrismPart::Top ? p.y_max : p.y_min;
      if (h == 0.0) continue;
      const double s = (h - p0.y) / d.y;
      const Vec3 q = p0 + s * d;
      if (prism_curves_inside(p.curves, q.x / h, q.z / h)) emit(s, part, -1, 0.0);
    }
  }
  return count;
}

}  // namespace detail

// The crossings of the prism's surfaces along the whole line beyond t_after: the first max_out,
// ascending; returns how many. A closed prism, whole line: in and out alternately.
inline int prism_crossings(const PrismData& p, const Ray& ray, PrismCrossing* out, int max_out,
                           double t_after = -Interval::kInfinity) {
  if (p.edges.empty() && p.curves.empty()) return 0;
  const double len = glm::length(ray.direction);
  if (!(len > 0.0) || !std::isfinite(len)) return 0;
  const Vec3 d = ray.direction / len;
  const Vec3 centre(0.5 * (p.x_min + p.x_max), 0.5 * (p.y_min + p.y_max), 0.5 * (p.z_min + p.z_max));
  const double sc = -glm::dot(ray.origin - centre, d);
  const Vec3 p0 = ray.origin + sc * d;  // s = 0 here; t = (sc + s) / len
  {
    // The line misses the bounding box's circumscribed sphere (padded): nothing to find.
    const Vec3 half(0.5 * (p.x_max - p.x_min), 0.5 * (p.y_max - p.y_min), 0.5 * (p.z_max - p.z_min));
    const Vec3 rel = p0 - centre;
    if (glm::dot(rel, rel) > glm::dot(half, half) * (1.0 + 1e-9) + 1e-300) return 0;
  }
  if (p.conic) return detail::prism_conic_walk(p, d, p0, sc, len, out, max_out, t_after);
  // The slab of heights along the line: [sa, sb] (all of it for a horizontal ray inside it).
  double sa = -Interval::kInfinity, sb = Interval::kInfinity;
  PrismPart cap_a = PrismPart::Bottom, cap_b = PrismPart::Top;
  if (d.y != 0.0) {
    sa = (p.y_min - p0.y) / d.y;
    sb = (p.y_max - p0.y) / d.y;
    if (sa > sb) {
      std::swap(sa, sb);
      std::swap(cap_a, cap_b);
    }
  } else if (p0.y < p.y_min || p0.y > p.y_max) {
    return 0;
  }
  int count = 0;
  auto emit = [&](double s, PrismPart part, int edge) {
    double t = (sc + s) / len;
    if (t > t_after) detail::keep_first_crossings(out, count, max_out, PrismCrossing{t, part, edge});
  };
  const double a = d.x * d.x + d.z * d.z;
  bool parity_a = false;  // inside the polygon where the line enters the slab
  bool walls_odd = false;  // an odd number of walls crossed inside the slab
  if (a > 1e-200 && !p.curves.empty()) {
    // A curve's side of the ray's line in x-z is a cubic in w: its sign changes are crossings.
    const int nc = static_cast<int>(p.curves.size());
    for (int j = 0; j < nc; ++j) {
      const SplineSegment& g = p.curves[j];
      // The line misses the curve's box: all four corners on one side.
      auto side_of = [&](double x, double z) { return d.x * (z - p0.z) - d.z * (x - p0.x); };
      double c0 = side_of(g.x_lo, g.y_lo), c1 = side_of(g.x_hi, g.y_lo), c2 = side_of(g.x_lo, g.y_hi),
             c3 = side_of(g.x_hi, g.y_hi);
      if ((c0 > 0.0 && c1 > 0.0 && c2 > 0.0 && c3 > 0.0) || (c0 < 0.0 && c1 < 0.0 && c2 < 0.0 && c3 < 0.0)) continue;
      double sc3[4];
      for (int k = 0; k < 4; ++k) sc3[k] = d.x * g.y[k] - d.z * g.x[k];
      double ws[3];
      int nr = detail::prism_curve_roots(sc3, d.x * p0.z - d.z * p0.x, ws);
      for (int i = 0; i < nr; ++i) {
        const double x = spline_eval(g.x, ws[i]), z = spline_eval(g.y, ws[i]);
        const double s = ((x - p0.x) * d.x + (z - p0.z) * d.z) / a;
        if (s < sa) {
          parity_a = !parity_a;
        } else if (s < sb || (p.open && s == sb)) {
          walls_odd = !walls_odd;
          double t = (sc + s) / len;
          if (t > t_after) detail::keep_first_crossings(out, count, max_out, PrismCrossing{t, PrismPart::Wall, j, ws[i]});
        }
      }
    }
  } else if (a > 1e-200) {
    const int ne = static_cast<int>(p.edges.size());
    for (int j = 0; j < ne; ++j) {
      const PrismEdge& e = p.edges[j];
      // Sides of the ends from the ray's line in x-z: the same bits for a vertex in both its edges.
      const double side0 = d.x * (e.z0 - p0.z) - d.z * (e.x0 - p0.x);
      const double side1 = d.x * (e.z1 - p0.z) - d.z * (e.x1 - p0.x);
      if ((side0 > 0.0) == (side1 > 0.0)) continue;
      const double u = side0 / (side0 - side1);
      const double x = e.x0 + u * (e.x1 - e.x0), z = e.z0 + u * (e.z1 - e.z0);
      const double s = ((x - p0.x) * d.x + (z - p0.z) * d.z) / a;
      if (s < sa) {
        parity_a = !parity_a;
      } else if (s < sb || (p.open && s == sb)) {
        walls_odd = !walls_odd;
        emit(s, PrismPart::Wall, j);
      }
    }
  } else {
    // Vertical: no wall is crossed; the caps are when the line's x-z point is inside.
    parity_a = p.spline != SplineKind::Linear ? detail::prism_curves_inside(p.curves, p0.x, p0.z)
                                              : detail::prism_point_inside(p.edges, p0.x, p0.z);
  }
  if (!p.open && d.y != 0.0) {
    if (parity_a) emit(sa, cap_a, -1);
    if (parity_a != walls_odd) emit(sb, cap_b, -1);
  }
  return count;
}

inline void prism_hit_at(const PrismData& p, const Ray& ray, const PrismCrossing& c, SurfaceHit& hit) {
  Vec3 pt = ray.at(c.t);
  double err = 4.0 * ray_point_error(ray, c.t);
  Vec3 n;
  if (c.part == PrismPart::Wall && !p.curves.empty()) {
    const SplineSegment& g = p.curves[c.edge];
    double dx = spline_slope(g.x, c.w), dz = spline_slope(g.y, c.w);
    if (dx == 0.0 && dz == 0.0) {  // a cusp: the chord over a short step
      double w1 = std::clamp(c.w + 1e-6, 0.0, 1.0), w0 = std::clamp(c.w - 1e-6, 0.0, 1.0);
      dx = spline_eval(g.x, w1) - spline_eval(g.x, w0);
      dz = spline_eval(g.y, w1) - spline_eval(g.y, w0);
    }
    if (p.conic) {
      // The wall (x(w) y, y, z(w) y): d/dw x d/dy over -y is (dz, z dx - x dz, -dx), the
      // straight prism's normal tilted by the wall's lean; turned over where y < 0 (the outline
      // there is mirrored through the apex).
      const double x = spline_eval(g.x, c.w), z = spline_eval(g.y, c.w);
      Vec3 cn(dz, z * dx - x * dz, -dx);
      cn *= p.curve_outward[c.edge] * (pt.y < 0.0 ? -1.0 : 1.0);
      double cl = glm::length(cn);
      n = cl > 0.0 ? cn / cl : Vec3(1, 0, 0);
    } else {
      double nl = std::sqrt(dx * dx + dz * dz);
      n = nl > 0.0 ? Vec3(dz / nl, 0.0, -dx / nl) * p.curve_outward[c.edge] : Vec3(1, 0, 0);
    }
    // The point is the ray's at a root polished to the last bit in w: a few ulps of the size.
    const double size = std::max({std::abs(p.x_min), std::abs(p.x_max), std::abs(p.z_min), std::abs(p.z_max)});
    err += error_gamma(64) * size;
    pt.y = std::clamp(pt.y, p.y_min, p.y_max);
  } else if (c.part == PrismPart::Wall) {
    const PrismEdge& e = p.edges[c.edge];
    n = glm::normalize(Vec3(e.z1 - e.z0, 0.0, -(e.x1 - e.x0))) * e.outward;
    // The edge's point is interpolated to within a few ulps of the shape's size.
    const double size = std::max({std::abs(p.x_min), std::abs(p.x_max), std::abs(p.z_min), std::abs(p.z_max)});
    err += error_gamma(16) * size;
    pt.y = std::clamp(pt.y, p.y_min, p.y_max);
  } else {
    const bool top = c.part == PrismPart::Top;
    pt.y = top ? p.y_max : p.y_min;  // exactly on the cap it crossed
    n = Vec3(0.0, top ? 1.0 : -1.0, 0.0);
  }
  hit.t = c.t;
  hit.point = pt;
  hit.error = err;
  hit.normal = n;
  hit.shading_normal = n;
}

inline bool intersect(const PrismData& p, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  PrismCrossing c[1];
  int n = prism_crossings(p, ray, c, 1, ray_t.min);
  if (n == 0 || !ray_t.surrounds(c[0].t)) return false;
  prism_hit_at(p, ray, c[0], hit);
  return true;
}

// The shape as the scene and the world hold it (its data boxed: scene.hpp).
inline AABB bounds(const Prism& p) { return bounds(*p); }
inline bool intersect(const Prism& p, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  return intersect(*p, ray, ray_t, hit);
}

}  // namespace rts::render
