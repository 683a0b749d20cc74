// Prism (POV-Ray's `prism { linear_sweep linear_spline h1, h2, N, <x0, z0>, ... }`): polygons
// in the x-z plane extruded along y between the two heights, closed by flat caps there unless
// open. As in POV-Ray the point list may hold several sub-polygons, each closed by a point that
// repeats its first point (the last one is closed if it is not), and the inside is counted
// even-odd. Only linear_spline and linear_sweep so far.
//
// Along a ray the walls are found in the x-z plane: an edge is crossed when its two ends lie
// strictly on different sides of the ray's line there, a vertex on the line counting as on the
// negative side (the crossing-number rule), so a ray through a vertex is counted once or twice
// as the polygon passes or turns there, and a ray along a wall never. The point on the edge is
// interpolated from the two side values, so it lies on the edge whatever the rounding. The caps
// follow from the same crossings: the polygon's parity where the ray enters the slab of heights
// (walls crossed before it) says whether that cap is crossed, and that parity plus the walls
// crossed inside the slab says whether the other one is, so crossings always come in pairs.
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
#include "render/geometry/shapes/shape_info.hpp"
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

}  // namespace detail

// Edges (POV-Ray's sub-polygon rule), their outward sides, heights and bounds from p.points.
inline void prism_setup(Prism& p) {
  const std::vector<Vec3>& q = p.points;
  const int n = static_cast<int>(q.size());
  p.edges.clear();
  auto same = [](const Vec3& a, const Vec3& b) {
    return std::abs(a.x - b.x) < tol::kPrismSamePoint && std::abs(a.y - b.y) < tol::kPrismSamePoint;
  };
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

// Even-odd inside the solid (caps included whether open or not).
inline bool prism_inside(const Prism& p, const Vec3& pt) {
  return pt.y >= p.y_min && pt.y <= p.y_max && detail::prism_point_inside(p.edges, pt.x, pt.z);
}

// The `prism` block: see docs/shapes.md#prism.
template <>
struct ShapeTraits<Prism> {
  static constexpr PropertyInfo kProperties[] = {
      {"points", "list of `[x, z]`, at least 3", "*required*",
       "The polygon in the x-z plane, joined by straight segments; a point repeating its sub-polygon's first "
       "point closes it and the next starts another (inside: even-odd)."},
      {"height1", "number", "`0`", "The height (y) of one cap."},
      {"height2", "number", "`1`", "The height (y) of the other cap; must differ from `height1`."},
      {"open", "bool", "`false`", "`true` leaves out the two caps (then not a CSG operand)."},
      {"sweep", "string", "`\"linear\"`", "`\"linear\"`: the polygon is extruded unchanged (POV-Ray's linear_sweep)."},
      {"spline", "string", "`\"linear\"`", "`\"linear\"`: straight edges (POV-Ray's linear_spline)."},
  };
  static constexpr ShapeInfo kInfo{.name = "prism", .properties = kProperties, .closure = Closure::WhenCapped};
  static Prism build(ParamSet& ps) {
    Prism g;
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
    const int n = static_cast<int>(g.points.size());
    if (n < 3) throw SceneError(loc_of(ps, "points"), fmt::format("prism needs at least 3 points, got {}", n));
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
    if (sweep == "conic")
      throw SceneError(loc_of(ps, "sweep"),
                       "prism sweep \"conic\" (POV-Ray's conic_sweep) is not supported yet; only \"linear\" is");
    if (sweep != "linear")
      throw SceneError(loc_of(ps, "sweep"),
                       fmt::format("prism sweep \"{}\" is not one of \"linear\" (supported) or \"conic\"", sweep));
    std::string spline = ps.string("spline", "linear");
    if (spline != "linear")
      throw SceneError(loc_of(ps, "spline"),
                       fmt::format("prism spline \"{}\" is not supported: only \"linear\" (POV-Ray's linear_spline) "
                                   "is; quadratic, cubic and bezier splines are not",
                                   spline));
    prism_setup(g);
    return g;
  }
};

inline AABB bounds(const Prism& p) {
  return AABB{Vec3(p.x_min, p.y_min, p.z_min), Vec3(p.x_max, p.y_max, p.z_max)};
}

enum class PrismPart : uint8_t { Wall, Bottom, Top };

struct PrismCrossing {
  double t;
  PrismPart part;
  int edge;  // for a wall
};

// The crossings of the prism's surfaces along the whole line beyond t_after: the first max_out,
// ascending; returns how many. A closed prism, whole line: in and out alternately.
inline int prism_crossings(const Prism& p, const Ray& ray, PrismCrossing* out, int max_out,
                           double t_after = -Interval::kInfinity) {
  if (p.edges.empty()) return 0;
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
  if (a > 1e-200) {
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
    parity_a = detail::prism_point_inside(p.edges, p0.x, p0.z);
  }
  if (!p.open && d.y != 0.0) {
    if (parity_a) emit(sa, cap_a, -1);
    if (parity_a != walls_odd) emit(sb, cap_b, -1);
  }
  return count;
}

inline void prism_hit_at(const Prism& p, const Ray& ray, const PrismCrossing& c, SurfaceHit& hit) {
  Vec3 pt = ray.at(c.t);
  double err = 4.0 * ray_point_error(ray, c.t);
  Vec3 n;
  if (c.part == PrismPart::Wall) {
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

inline bool intersect(const Prism& p, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  PrismCrossing c[1];
  int n = prism_crossings(p, ray, c, 1, ray_t.min);
  if (n == 0 || !ray_t.surrounds(c[0].t)) return false;
  prism_hit_at(p, ray, c[0], hit);
  return true;
}

}  // namespace rts::render
