// Axis-aligned box in object space (rotate it with a transform). Slab test that reports which
// face was crossed, for entering and for leaving (rays starting inside).
#pragma once

#include <cmath>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/params.hpp"
#include "render/geometry/surface_hit.hpp"

namespace rts::render {

// The `box` block: see docs/shapes.md#box.
template <>
struct ShapeTraits<Box> {
  static constexpr PropertyInfo kProperties[] = {
      {"min", "vector", "*required*", "The corner with the smallest coordinates."},
      {"max", "vector", "*required*", "The opposite corner; `max ≥ min` in every component."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "box", .properties = kProperties, .closure = Closure::Closed, .has_uv = true};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Box build(ParamSet& ps) {
    Box g;
    g.min = ps.require_vec3("min");
    g.max = ps.require_vec3("max");
    if (g.min.x > g.max.x || g.min.y > g.max.y || g.min.z > g.max.z)
      throw SceneError(loc_of(ps, "max"), "box max must be >= min in every component");
    return g;
  }
};

inline AABB bounds(const Box& b) { return AABB{glm::min(b.min, b.max), glm::max(b.min, b.max)}; }

// The line's passage through the box's three slabs: where it enters and leaves, and the axis
// of the slab that set each (-1: none did, the line is parallel to all three). False when the
// line misses the box. intersect() and the CSG crossings (leaf_crossings.hpp) both read it.
struct BoxSlabs {
  double t_enter = -Interval::kInfinity, t_exit = Interval::kInfinity;
  int enter_axis = -1, exit_axis = -1;
};

inline bool box_slabs(const Box& box, const Ray& ray, BoxSlabs& s) {
  Vec3 lo = glm::min(box.min, box.max), hi = glm::max(box.min, box.max);
  for (int a = 0; a < 3; ++a) {
    double d = ray.direction[a], o = ray.origin[a];
    if (d == 0.0) {
      if (o < lo[a] || o > hi[a]) return false;  // parallel and outside this slab
      continue;
    }
    double ta = (lo[a] - o) / d, tb = (hi[a] - o) / d;
    if (ta > tb) std::swap(ta, tb);
    if (ta > s.t_enter) { s.t_enter = ta; s.enter_axis = a; }
    if (tb < s.t_exit) { s.t_exit = tb; s.exit_axis = a; }
    if (s.t_enter > s.t_exit) return false;
  }
  return true;
}

inline bool intersect(const Box& box, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  BoxSlabs slabs;
  if (!box_slabs(box, ray, slabs)) return false;
  const auto [t_enter, t_exit, enter_axis, exit_axis] = slabs;
  Vec3 lo = glm::min(box.min, box.max), hi = glm::max(box.min, box.max);
  double t;
  int axis;
  double sign;  // the outward normal's sign along `axis`
  if (enter_axis >= 0 && ray_t.surrounds(t_enter)) {
    t = t_enter;
    axis = enter_axis;
    sign = ray.direction[axis] > 0 ? -1.0 : 1.0;
  } else if (exit_axis >= 0 && ray_t.surrounds(t_exit)) {
    t = t_exit;
    axis = exit_axis;
    sign = ray.direction[axis] > 0 ? 1.0 : -1.0;
  } else {
    return false;
  }
  hit.t = t;
  hit.point = ray.at(t);
  hit.error = ray_point_error(ray, t);
  hit.point[axis] = sign > 0 ? hi[axis] : lo[axis];  // exactly on the face it crossed
  Vec3 n(0.0);
  n[axis] = sign;
  hit.normal = n;
  hit.shading_normal = n;
  // Face UVs: the two other coordinates, normalised to [0,1] over the face.
  int ua = (axis + 1) % 3, va = (axis + 2) % 3;
  Vec3 ext = hi - lo;
  hit.uv = {ext[ua] > 0 ? (hit.point[ua] - lo[ua]) / ext[ua] : 0.0,
            ext[va] > 0 ? (hit.point[va] - lo[va]) / ext[va] : 0.0};
  hit.has_uv = true;
  return true;
}

}  // namespace rts::render
