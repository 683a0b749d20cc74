// Cylinder between `from` and `to` with `radius`, optionally capped: the cone with equal radii.
#pragma once

#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/params.hpp"
#include "render/geometry/shapes/cone.hpp"

namespace rts::render {

// The `cylinder` block: see docs/shapes.md#cylinder.
template <>
struct ShapeTraits<Cylinder> {
  static constexpr PropertyInfo kProperties[] = {
      {"from", "vector", "*required*", "Centre of one end."},
      {"to", "vector", "*required*", "Centre of the other end; must differ from `from`."},
      {"radius", "number > 0", "*required*", "The radius."},
      {"capped", "bool", "`true`", "`false` leaves the ends open (a tube: you see its inside)."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "cylinder", .properties = kProperties, .closure = Closure::WhenCapped};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Cylinder build(ParamSet& ps) {
    Cylinder g;
    g.from = ps.require_vec3("from");
    g.to = ps.require_vec3("to");
    distinct(ps, "to", "from", g.to - g.from);
    g.radius = positive(ps, "radius", ps.require_number("radius"));
    g.capped = ps.boolean("capped", g.capped);
    return g;
  }
};

inline AABB bounds(const Cylinder& c) { return cone_bounds(c.from, c.to, c.radius, c.radius); }

inline bool intersect(const Cylinder& c, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  if (!(c.radius > 0.0)) return false;
  return intersect_cone(c.from, c.to, c.radius, c.radius, c.capped, ray, ray_t, hit);
}

}  // namespace rts::render
