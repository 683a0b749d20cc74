// Quad: the parallelogram corner + s*edge_u + t*edge_v, s and t in [0, 1], one-sided only in
// its normal's direction (cross(edge_u, edge_v)); both sides are hit. Its texture coordinates
// are (s, t), so an image covers it exactly once (UW CSE 457's `square`).
#pragma once

#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/params.hpp"
#include <cmath>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

// The `quad` block: see docs/shapes.md#quad.
template <>
struct ShapeTraits<Quad> {
  static constexpr PropertyInfo kProperties[] = {
      {"corner", "vector", "`<-0.5, -0.5, 0>`",
       "One corner; the quad is `corner + s edge_u + t edge_v` for s, t in [0, 1]."},
      {"edge_u", "vector, non-zero", "`<1, 0, 0>`",
       "The edge along which the texture coordinate u runs from 0 to 1."},
      {"edge_v", "vector, non-zero", "`<0, 1, 0>`", "The edge along which v runs; not parallel to `edge_u`."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "quad", .properties = kProperties, .closure = Closure::Open, .has_uv = true, .has_tangents = true};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Quad build(ParamSet& ps) {
    Quad g;
    g.corner = ps.vec3("corner", g.corner);
    g.edge_u = direction(ps, "edge_u", ps.vec3("edge_u", g.edge_u));
    g.edge_v = direction(ps, "edge_v", ps.vec3("edge_v", g.edge_v));
    if (glm::length(glm::cross(unit_vector(g.edge_u), unit_vector(g.edge_v))) < kMinDirectionLength)
      throw SceneError(loc_of(ps, "edge_v"), "quad edge_u and edge_v must not be parallel");
    return g;
  }
};

inline AABB bounds(const Quad& q) {
  AABB b;
  b.extend(q.corner);
  b.extend(q.corner + q.edge_u);
  b.extend(q.corner + q.edge_v);
  b.extend(q.corner + q.edge_u + q.edge_v);
  return b;
}

// What the test derives from the three vectors, computed once per quad when the world is
// built instead of per ray (profile finding, path-traced Cornell box: the quad test was the
// largest share of the render, three cross products per test). The values are the ones the
// per-ray test computed, so hits are the same bit for bit.
//
// n2 is an edge's length to the fourth power and the duals to the third, which overflow past
// edges of about 1e77 units and underflow below 1e-77: such a quad's frame is made from its
// edges scaled by a power of two near 1 / |edge| (`scale`, exact), and the test scales the
// offset from the corner by it. Inside tol::kUnscaledLength* `scale` is 1: the old bits.
struct QuadFrame {
  Vec3 corner, edge_u, edge_v;
  Vec3 n;        // cross(edge_u, edge_v) * scale^2, not unit length
  Vec3 dual_u;   // cross(edge_v, n) * scale^3: s = dot((p - corner) * scale, dual_u) / n2
  Vec3 dual_v;   // cross(n, edge_u) * scale^3: t = dot((p - corner) * scale, dual_v) / n2
  Vec3 unit_n;   // n / |n|
  double n2 = 0.0, len_n = 0.0;
  double scale = 1.0;
  explicit QuadFrame(const Quad& q) : corner(q.corner), edge_u(q.edge_u), edge_v(q.edge_v) {
    const double m = std::max(max_abs_component(q.edge_u), max_abs_component(q.edge_v));
    if (m > 0.0 && std::isfinite(m) && !(m > tol::kUnscaledLengthMin && m < tol::kUnscaledLengthMax))
      scale = std::ldexp(1.0, -std::ilogb(m));
    const Vec3 eu = q.edge_u * scale, ev = q.edge_v * scale;
    n = glm::cross(eu, ev);
    dual_u = glm::cross(ev, n);
    dual_v = glm::cross(n, eu);
    n2 = glm::dot(n, n);
    len_n = std::sqrt(n2);
    unit_n = n / len_n;
  }
};

inline bool intersect(const QuadFrame& q, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  const Vec3& n = q.n;
  const double n2 = q.n2;
  if (!(n2 > 0.0)) return false;   // degenerate (parallel or zero edges): never hit
  const double denom = glm::dot(n, ray.direction);
  if (nearly_parallel(denom, n2, q.len_n, ray)) return false;
  const double t = glm::dot(q.corner - ray.origin, n) / denom;
  if (!ray_t.surrounds(t)) return false;
  const Vec3 p = ray.at(t);
  const Vec3 d = (p - q.corner) * q.scale;
  // Coordinates along the (not necessarily orthogonal) edges: solve d = s*eu + t*ev with the
  // dual basis cross(ev, n) / n2 and cross(n, eu) / n2.
  const double s = glm::dot(d, q.dual_u) / n2;
  const double tv = glm::dot(d, q.dual_v) / n2;
  if (!(s >= 0.0 && s <= 1.0 && tv >= 0.0 && tv <= 1.0)) return false;
  hit.t = t;
  hit.point = p;
  // Without it a spawned ray starts at the minimum offset, which at a few units' distance is
  // inside the rounding of p: the quad shadowed itself (ambient-only walls).
  hit.error = ray_point_error(ray, t);
  hit.normal = q.unit_n;
  hit.shading_normal = hit.normal;
  hit.uv = {s, tv};
  hit.has_uv = true;
  hit.dpdu = q.edge_u;
  hit.dpdv = q.edge_v;
  return true;
}

inline bool intersect(const Quad& q, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  return intersect(QuadFrame(q), ray, ray_t, hit);
}

}  // namespace rts::render
