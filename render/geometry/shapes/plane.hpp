// Infinite plane dot(normal, p) = offset. Unbounded: kept outside the BVH. Planar UVs are the
// point's coordinates along two tangents (x and z for a y-up plane).
#pragma once

#include <cmath>

#include "render/geometry/interval.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/params.hpp"
#include "render/geometry/surface_hit.hpp"

namespace rts::render {

// The `plane` block: see docs/shapes.md#plane.
template <>
struct ShapeTraits<Plane> {
  static constexpr PropertyInfo kProperties[] = {
      {"normal", "vector, non-zero", "*required*", "The plane's normal (normalised for you)."},
      {"offset", "number", "`0`", "Distance from the origin along `normal`."},
  };
  static constexpr ShapeInfo kInfo{
      // Closed: in CSG a plane is the half-space away from its normal, as in POV-Ray.
      .name = "plane", .properties = kProperties, .closure = Closure::Closed, .has_uv = true, .bounded = false};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Plane build(ParamSet& ps) {
    Plane g;
    g.normal = unit_vector(direction(ps, "normal", ps.require_vec3("normal")));
    g.offset = ps.number("offset", g.offset);
    return g;
  }
};

// Two unit tangents of a unit normal; for n = +y they are +x and +z.
inline void plane_tangents(const Vec3& n, Vec3& t1, Vec3& t2) {
  // Project +x onto the plane unless the normal is (nearly) along x; then use +z instead.
  Vec3 ref = std::abs(n.x) < tol::kReferenceAxisCosine ? Vec3(1, 0, 0) : Vec3(0, 0, 1);
  t1 = glm::normalize(ref - n * glm::dot(n, ref));
  t2 = glm::cross(t1, n);
}

// What the test derives from the plane, computed once when the world is built instead of per
// ray (profile finding, leave-out scene: the tangents' normalisation per plane hit, and a
// plane is tested by every ray). The values are the ones the per-ray test computed, so hits
// are the same bit for bit.
struct PlaneFrame {
  bool valid = false;      // a normal of usable length
  Vec3 n{0.0};             // the unit normal
  double offset = 0.0;     // offset / |normal|: dot(n, p) = offset on the plane
  Vec3 t1{0.0}, t2{0.0};   // the tangents of the uv (plane_tangents)
  explicit PlaneFrame(const Plane& p) {
    const double len = glm::length(p.normal);
    if (!(len > tol::kTinyLength)) return;
    valid = true;
    n = p.normal / len;
    offset = p.offset / len;
    plane_tangents(n, t1, t2);
  }
};

inline bool intersect(const PlaneFrame& p, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  if (!p.valid) return false;
  const Vec3& n = p.n;
  double denom = glm::dot(n, ray.direction);
  if (nearly_parallel(denom, 1.0, 1.0, ray)) return false;   // n is unit length
  double t = (p.offset - glm::dot(n, ray.origin)) / denom;
  if (!ray_t.surrounds(t)) return false;
  hit.t = t;
  hit.point = ray.at(t);
  hit.error = ray_point_error(ray, t);
  hit.normal = n;
  hit.shading_normal = n;
  hit.uv = {glm::dot(hit.point, p.t1), glm::dot(hit.point, p.t2)};
  hit.has_uv = true;
  return true;
}

inline bool intersect(const Plane& p, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  return intersect(PlaneFrame(p), ray, ray_t, hit);
}

}  // namespace rts::render
