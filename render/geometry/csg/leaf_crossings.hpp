// Where the whole line of a ray crosses one CSG leaf's surface (render/geometry/csg/csg_tree.hpp),
// and the full hit at a chosen crossing, for each closed primitive kind.
//
// Convex solids (sphere, box, capped cylinder and cone) are crossed at most twice: their own
// intersect() finds the entry over the whole line, then the exit beyond it. One crossing alone
// is a graze along an edge or a tangent: no crossing. A plane is a half-space (inside:
// dot(normal, p) < offset, the side away from its normal, as in POV-Ray).
//
// Solids a line may cross more often (sor, lathe, prism, blob, superellipsoid, isosurface, poly,
// height field) also have leaf_crossings_from: up to kMaxLineCrossings crossings of the whole
// line, of which those from `from` on are listed (the state at `from` folded into
// inside_at_start), at most kMaxLeafCrossings; it returns true when the list stops short, and
// World::trace_csg sweeps again from there when it needs to (out of line: their buffers in the
// sweep's dispatch over every kind cost scenes of other solids).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/geometry/csg/csg_tree.hpp"
#include "render/geometry/shapes/blob.hpp"
#include "render/geometry/shapes/box.hpp"
#include "render/geometry/shapes/cone.hpp"
#include "render/geometry/shapes/cylinder.hpp"
#include "render/geometry/shapes/height_field.hpp"
#include "render/geometry/shapes/isosurface.hpp"
#include "render/geometry/shapes/lathe.hpp"
#include "render/geometry/shapes/plane.hpp"
#include "render/geometry/shapes/poly.hpp"
#include "render/geometry/shapes/prism.hpp"
#include "render/geometry/shapes/sor.hpp"
#include "render/geometry/shapes/sphere.hpp"
#include "render/geometry/shapes/superellipsoid.hpp"
#include "render/geometry/shapes/torus.hpp"

namespace rts::render {

// The most crossings of one leaf's whole line computed for one sweep.
inline constexpr int kMaxLineCrossings = 16;

// Lists the crossings t[0..n) (ascending, alternating from `inside_at_start`) at or after
// `from` in `out`, at most kMaxLeafCrossings. True when the list stops short: crossings were
// left out after its last, or the line's computation was `full` (it may have more).
inline bool keep_crossings_from(const double* t, int n, bool inside_at_start, bool full, double from,
                                CsgLeafCrossings& out) {
  int i = 0;
  while (i < n && t[i] < from) ++i;
  out.inside_at_start = inside_at_start != (i % 2 == 1);
  const int kept = std::min(n - i, kMaxLeafCrossings);
  for (int k = 0; k < kept; ++k) out.t[k] = t[i + k];
  out.count = kept;
  return kept > 0 && (i + kept < n || full);
}

template <class Convex>
void convex_crossings(const Convex& shape, const Ray& ray, CsgLeafCrossings& out) {
  out.inside_at_start = false;
  out.count = 0;
  SurfaceHit h;
  if (!intersect(shape, ray, Interval::universe(), h)) return;
  double first = h.t, last = h.t;
  // A convex surface is crossed twice; a third step only guards against an edge reported twice.
  for (int step = 0; step < 2 && intersect(shape, ray, Interval(last, Interval::kInfinity), h); ++step) last = h.t;
  if (!(last > first)) return;  // a single touch: a graze, not a crossing
  out.t[0] = first;
  out.t[1] = last;
  out.count = 2;
}

// convex_crossings's searches, given the two parameters intersect() chooses between (`near`
// before `far`, as it tries them): the first over the whole line, then up to two beyond the
// last found. The same answers, bit for bit, from one root computation instead of three full
// hits (tests/render/test_csg_prune.cpp compares the two on random rays).
inline void convex_crossings_of(double near, double far, CsgLeafCrossings& out) {
  auto search = [&](double lo, double& t) {  // intersect() over Interval(lo, +infinity)
    const Interval range(lo, Interval::kInfinity);
    if (range.surrounds(near)) t = near;
    else if (range.surrounds(far)) t = far;
    else return false;
    return true;
  };
  double first, t;
  if (!search(-Interval::kInfinity, first)) return;
  double last = first;
  for (int step = 0; step < 2 && search(last, t); ++step) last = t;
  if (!(last > first)) return;  // a single touch: a graze, not a crossing
  out.t[0] = first;
  out.t[1] = last;
  out.count = 2;
}

// The ray's crossings of a sphere: sphere_root's roots (render/geometry/shapes/sphere.hpp; the
// same operations in the same order), without the hit point and normal intersect() adds.
inline void leaf_crossings(const Sphere& s, const Ray& ray, CsgLeafCrossings& out) {
  out.inside_at_start = false;
  out.count = 0;
  if (!(s.radius > 0.0)) return;
  Vec3 f = ray.origin - s.center;
  double a = glm::dot(ray.direction, ray.direction);
  if (!(a > 0.0)) return;
  double b = -glm::dot(f, ray.direction);
  Vec3 closest = f + (b / a) * ray.direction;
  double disc = a * (s.radius * s.radius - glm::dot(closest, closest));
  if (disc < 0.0) return;
  double len = glm::length(f);
  double c = (len - s.radius) * (len + s.radius);
  double q = b + std::copysign(std::sqrt(disc), b);
  double t0 = q / a, t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  convex_crossings_of(t0, t1, out);
}

// The ray's crossings of a box: intersect(Box)'s slabs (box_slabs, render/geometry/shapes/
// box.hpp), without its hit point, normal and uv.
inline void leaf_crossings(const Box& box, const Ray& ray, CsgLeafCrossings& out) {
  out.inside_at_start = false;
  out.count = 0;
  BoxSlabs s;
  if (!box_slabs(box, ray, s)) return;
  // intersect() offers the entry only when a slab set it, the exit likewise.
  const double nan = std::numeric_limits<double>::quiet_NaN();  // never surrounded
  convex_crossings_of(s.enter_axis >= 0 ? s.t_enter : nan, s.exit_axis >= 0 ? s.t_exit : nan, out);
}
inline void leaf_crossings(const Cylinder& c, const Ray& ray, CsgLeafCrossings& out) { convex_crossings(c, ray, out); }
inline void leaf_crossings(const Cone& c, const Ray& ray, CsgLeafCrossings& out) { convex_crossings(c, ray, out); }

inline void leaf_crossings(const Plane& p, const Ray& ray, CsgLeafCrossings& out) {
  out.count = 0;
  double len = glm::length(p.normal);
  if (!(len > tol::kTinyLength)) {
    out.inside_at_start = false;
    return;
  }
  Vec3 n = p.normal / len;
  double along = glm::dot(n, ray.direction);
  SurfaceHit h;
  if (intersect(p, ray, Interval::universe(), h)) {
    out.inside_at_start = along > 0.0;  // far back along the ray, it is below the plane
    out.t[0] = h.t;
    out.count = 1;
  } else {
    out.inside_at_start = glm::dot(n, ray.origin) < p.offset / len;  // parallel: one side throughout
  }
}

[[gnu::noinline]] inline bool leaf_crossings_from(const Superellipsoid& s, const Ray& ray, double from,
                                                      CsgLeafCrossings& out) {
  double t[kMaxLineCrossings];
  const int raw = superellipsoid_crossings(s, ray, t, kMaxLineCrossings);
  return keep_crossings_from(t, raw - raw % 2, false, raw == kMaxLineCrossings, from, out);
}

inline bool leaf_hit(const Superellipsoid& s, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  superellipsoid_hit_at(s, ray, c.t[k], hit);
  return true;
}

[[gnu::noinline]] inline bool leaf_crossings_from(const Blob& b, const Ray& ray, double from,
                                                      CsgLeafCrossings& out) {
  double t[kMaxLineCrossings];
  const int raw = blob_crossings(b, ray, t, kMaxLineCrossings);
  return keep_crossings_from(t, raw - raw % 2, false, raw == kMaxLineCrossings, from, out);
}

inline bool leaf_hit(const Blob& b, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  blob_hit_at(b, ray, c.t[k], hit);
  return true;
}

// A poly of order above 4 may cross a line more often than kMaxLeafCrossings.
[[gnu::noinline]] inline bool leaf_crossings_from(const Poly& p, const Ray& ray, double from, CsgLeafCrossings& out) {
  double t[kPolyMaxOrder];
  bool inside_at_start;
  const int n = poly_crossings(p, ray, t, inside_at_start);
  return keep_crossings_from(t, n, inside_at_start, false, from, out);
}

inline bool leaf_hit(const Poly& p, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  poly_hit_at(p, ray, c.t[k], hit);
  return true;
}

// Sor, lathe and prism: their crossings come from one walk along the ray, kept in pairs (they
// alternate in and out: POV-Ray's even-odd inside); the chosen one's part (cap, curve segment,
// wall) is found by walking again (the walk is deterministic).
template <class Crossing, class Shape, class Walk>
bool walked_leaf_crossings_from(const Shape& s, const Ray& ray, double from, CsgLeafCrossings& out, Walk walk) {
  Crossing cs[kMaxLineCrossings];
  const int raw = walk(s, ray, cs, kMaxLineCrossings);
  double t[kMaxLineCrossings] = {};  // (filled up to raw; zeroed for GCC's -Wmaybe-uninitialized)
  for (int i = 0; i < raw; ++i) t[i] = cs[i].t;
  return keep_crossings_from(t, raw - raw % 2, false, raw == kMaxLineCrossings, from, out);
}

// The chosen crossing's part, found by walking again: the crossing with the same t (the walk
// is deterministic, so the same bits).
template <class Crossing, class Shape, class Walk, class HitAt>
bool walked_leaf_hit(const Shape& s, const Ray& ray, double t, SurfaceHit& hit, Walk walk, HitAt hit_at) {
  Crossing cs[kMaxLineCrossings];
  const int n = walk(s, ray, cs, kMaxLineCrossings);
  for (int i = 0; i < n; ++i)
    if (cs[i].t == t) {
      hit_at(s, ray, cs[i], hit);
      return true;
    }
  return false;
}

[[gnu::noinline]] inline bool leaf_crossings_from(const Sor& s, const Ray& ray, double from,
                                                      CsgLeafCrossings& out) {
  return walked_leaf_crossings_from<SorCrossing>(*s, ray, from, out, [](auto&&... a) { return sor_crossings(a...); });
}
inline bool leaf_hit(const Sor& s, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  return walked_leaf_hit<SorCrossing>(*s, ray, c.t[k], hit, [](auto&&... a) { return sor_crossings(a...); },
                                      [](auto&&... a) { sor_hit_at(a...); });
}

[[gnu::noinline]] inline bool leaf_crossings_from(const Lathe& l, const Ray& ray, double from,
                                                      CsgLeafCrossings& out) {
  return walked_leaf_crossings_from<LatheCrossing>(*l, ray, from, out, [](auto&&... a) { return lathe_crossings(a...); });
}
inline bool leaf_hit(const Lathe& l, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  return walked_leaf_hit<LatheCrossing>(*l, ray, c.t[k], hit, [](auto&&... a) { return lathe_crossings(a...); },
                                        [](auto&&... a) { lathe_hit_at(a...); });
}

[[gnu::noinline]] inline bool leaf_crossings_from(const Prism& p, const Ray& ray, double from,
                                                      CsgLeafCrossings& out) {
  return walked_leaf_crossings_from<PrismCrossing>(*p, ray, from, out, [](auto&&... a) { return prism_crossings(a...); });
}
inline bool leaf_hit(const Prism& p, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  return walked_leaf_hit<PrismCrossing>(*p, ray, c.t[k], hit, [](auto&&... a) { return prism_crossings(a...); },
                                        [](auto&&... a) { prism_hit_at(a...); });
}

// The whole span inside the container; the crossing kinds (function or container) are found
// again at the chosen one (a container crossing is exactly t0 or t1).
[[gnu::noinline]] inline bool leaf_crossings_from(const Isosurface& shape, const Ray& ray, double from,
                                                      CsgLeafCrossings& out) {
  const IsosurfaceData& s = *shape;
  out.inside_at_start = false;
  out.count = 0;
  double t0, t1;
  if (!iso_container_span(s, ray, t0, t1)) return false;
  double t[kMaxLineCrossings];
  bool on[kMaxLineCrossings];
  const int raw = iso_crossings(s, ray, t0, t1, t0, t1, t, on, kMaxLineCrossings);
  return keep_crossings_from(t, raw - raw % 2, false, raw == kMaxLineCrossings, from, out);
}

inline bool leaf_hit(const Isosurface& shape, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  const IsosurfaceData& s = *shape;
  double t0, t1;
  bool on_container = iso_container_span(s, ray, t0, t1) && (c.t[k] == t0 || c.t[k] == t1);
  iso_hit_at(s, ray, c.t[k], on_container, hit);
  return true;
}

// The column under the surface (render/geometry/shapes/height_field.hpp): its walls, surface
// and water plane; the kind of each crossing is found again at the chosen one.
[[gnu::noinline]] inline bool leaf_crossings_from(const HeightField& f, const Ray& ray, double from,
                                                      CsgLeafCrossings& out) {
  HeightFieldCrossing c[kMaxLineCrossings];
  bool inside = false;
  const int n = height_field_crossings(f, ray, c, kMaxLineCrossings, inside);
  double t[kMaxLineCrossings] = {};
  for (int i = 0; i < n; ++i) t[i] = c[i].t;
  return keep_crossings_from(t, n, inside, n == kMaxLineCrossings, from, out);
}

// The chosen crossing's kind, found again: the crossing with the same t.
inline bool leaf_hit(const HeightField& f, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  bool inside = false;
  HeightFieldCrossing all[kMaxLineCrossings];
  const int n = height_field_crossings(f, ray, all, kMaxLineCrossings, inside);
  for (int i = 0; i < n; ++i)
    if (all[i].t == c.t[k]) {
      height_field_crossing_hit(f, ray, all[i], hit);
      hit.t = c.t[k];
      return true;
    }
  return false;
}

// The solids listed from a start (leaf_crossings_from) over the whole line: their first
// kMaxLeafCrossings crossings, as every other leaf lists them (tests, and the sweep's dispatch,
// which calls leaf_crossings_from for them instead).
template <class Shape>
  requires requires(const Shape& g, const Ray& r, CsgLeafCrossings& c) { leaf_crossings_from(g, r, 0.0, c); }
void leaf_crossings(const Shape& shape, const Ray& ray, CsgLeafCrossings& out) {
  leaf_crossings_from(shape, ray, -Interval::kInfinity, out);
}

inline void leaf_crossings(const Torus& tor, const Ray& ray, CsgLeafCrossings& out) {
  out.inside_at_start = false;
  out.count = torus_crossings(tor, ray, out.t);
}

// The hit at crossing `k` of `c` (computed by leaf_crossings for the same ray), in the shape's
// object space: the shape's own intersect() between the neighbouring crossings.
template <class Shape>
bool leaf_hit(const Shape& shape, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  double lo = k > 0 ? c.t[k - 1] : -Interval::kInfinity;
  double hi = k + 1 < c.count ? c.t[k + 1] : Interval::kInfinity;
  return intersect(shape, ray, Interval(lo, hi), hit);
}

inline bool leaf_hit(const Torus& tor, const Ray& ray, const CsgLeafCrossings& c, int k, SurfaceHit& hit) {
  torus_hit_at(tor, ray, c.t[k], hit);
  return true;
}

}  // namespace rts::render
