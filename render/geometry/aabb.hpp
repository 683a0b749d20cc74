// Axis-aligned bounding boxes and the slab test used by BVH traversal.
#pragma once

#include <algorithm>
#include <limits>

#include "render/geometry/interval.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

struct AABB {
  Vec3 lo{std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity()};

  bool valid() const { return lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z; }
  void extend(const Vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
  void extend(const AABB& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
  Vec3 centroid() const { return 0.5 * (lo + hi); }
  Vec3 extent() const { return hi - lo; }
  double surface_area() const {
    if (!valid()) return 0.0;
    Vec3 e = extent();
    return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  bool finite() const {
    return std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(lo.z) &&
           std::isfinite(hi.x) && std::isfinite(hi.y) && std::isfinite(hi.z);
  }
};

// The box of `b`'s eight corners after the affine transform m.
inline AABB transform_bounds(const Mat4& m, const AABB& b) {
  AABB out;
  for (int i = 0; i < 8; ++i) {
    Vec3 c((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
    out.extend(Vec3(m * glm::dvec4(c, 1.0)));
  }
  return out;
}

// Ray data precomputed once per traversal: reciprocal direction for the slab test.
struct RayInverse {
  Vec3 origin;
  Vec3 inv_dir;
  explicit RayInverse(const Vec3& o, const Vec3& d) : origin(o), inv_dir(1.0 / d.x, 1.0 / d.y, 1.0 / d.z) {}
};

// Slab test: does the ray overlap the box within ray_t? A zero direction component gives an
// infinite reciprocal; the comparisons below are written so that a NaN (0 * inf, origin on a
// slab plane) leaves the range unchanged instead of rejecting or accepting by accident.
inline bool slab_hit(const AABB& b, const RayInverse& r, const Interval& ray_t, double& t_entry) {
  double t0 = ray_t.min, t1 = ray_t.max;
  for (int a = 0; a < 3; ++a) {
    double ta = (b.lo[a] - r.origin[a]) * r.inv_dir[a];
    double tb = (b.hi[a] - r.origin[a]) * r.inv_dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = ta > t0 ? ta : t0;
    t1 = tb < t1 ? tb : t1;
  }
  t_entry = t0;
  return t0 <= t1;
}

inline bool slab_hit(const AABB& b, const RayInverse& r, const Interval& ray_t) {
  double t_entry;
  return slab_hit(b, r, ray_t, t_entry);
}

}  // namespace rts::render
