// Triangle (Möller–Trumbore). Degenerate (zero-area) triangles are never hit. Barycentric
// coordinates interpolate optional vertex normals; shared with mesh triangles.
#pragma once

#include <cmath>

#include "render/aabb.hpp"
#include "render/ray.hpp"
#include "render/surface_hit.hpp"

namespace rts::render {

inline AABB bounds(const Triangle& tri) {
  AABB b;
  b.extend(tri.v0);
  b.extend(tri.v1);
  b.extend(tri.v2);
  return b;
}

// Returns t and barycentrics (b1, b2) of the hit, or false.
inline bool intersect_triangle(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Ray& ray,
                               const Interval& ray_t, double& t, double& b1, double& b2) {
  Vec3 e1 = v1 - v0, e2 = v2 - v0;
  Vec3 pvec = glm::cross(ray.direction, e2);
  double det = glm::dot(e1, pvec);
  if (det == 0.0) return false;
  double inv_det = 1.0 / det;
  Vec3 tvec = ray.origin - v0;
  double u = glm::dot(tvec, pvec) * inv_det;
  if (u < 0.0 || u > 1.0) return false;
  Vec3 qvec = glm::cross(tvec, e1);
  double v = glm::dot(ray.direction, qvec) * inv_det;
  if (v < 0.0 || u + v > 1.0) return false;
  double tt = glm::dot(e2, qvec) * inv_det;
  if (!ray_t.surrounds(tt)) return false;
  // Scale-free degeneracy test, done last since most candidates fail the bounds above:
  // det = d . (e1 x e2) against |d| |e1| |e2| (squared, no sqrt). Zero-area triangles and
  // rays in the triangle's plane fail it.
  double scale2 = glm::dot(ray.direction, ray.direction) * glm::dot(e1, e1) * glm::dot(e2, e2);
  if (!(det * det > tol::kTriangleDeterminant * tol::kTriangleDeterminant * scale2)) return false;
  t = tt;
  b1 = u;
  b2 = v;
  return true;
}

inline bool intersect(const Triangle& tri, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double t, b1, b2;
  if (!intersect_triangle(tri.v0, tri.v1, tri.v2, ray, ray_t, t, b1, b2)) return false;
  hit.t = t;
  hit.point = ray.at(t);
  hit.normal = glm::normalize(glm::cross(tri.v1 - tri.v0, tri.v2 - tri.v0));
  hit.shading_normal = hit.normal;
  if (tri.has_normals) {
    Vec3 n = (1.0 - b1 - b2) * tri.n0 + b1 * tri.n1 + b2 * tri.n2;
    double len = glm::length(n);
    if (len > tol::kTinyLength) hit.shading_normal = n / len;
  }
  hit.uv = {b1, b2};
  hit.has_uv = false;  // a lone triangle has no texture parameterisation
  return true;
}

}  // namespace rts::render
