// Triangle (watertight: Woop, Benthin and Wald 2013). Degenerate (zero-area) triangles are never hit. Barycentric
// coordinates interpolate optional vertex normals; shared with mesh triangles.
#pragma once

#include <cmath>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/surface_hit.hpp"

namespace rts::render {

// The `triangle` block: see docs/shapes.md#triangle.
template <>
struct ShapeTraits<Triangle> {
  static constexpr PropertyInfo kProperties[] = {
      {"v0", "vector", "*required*",
       "A corner. The order of the corners gives the geometric normal (`(v1 − v0) × (v2 − v0)`)."},
      {"v1", "vector", "*required*", "The second corner."},
      {"v2", "vector", "*required*", "The third corner."},
      {"n0", "vector", "none",
       "Vertex normal at `v0` for smooth shading, interpolated across the face; all three or none."},
      {"n1", "vector", "none", "Vertex normal at `v1`."},
      {"n2", "vector", "none", "Vertex normal at `v2`."},
      {"vertex_colors", "list of 3 colors", "none",
       "A color per corner, interpolated; replaces the material's `color`."},
      {"vertex_diffuse", "list of 3 numbers", "none", "A `diffuse` weight per corner, interpolated."},
      {"vertex_specular", "list of 3 numbers or colors", "none",
       "A highlight color per corner (a number x is `rgb(x)`), interpolated."},
      {"vertex_shininess", "list of 3 numbers", "none", "A `shininess` per corner, interpolated."},
  };
  static constexpr ShapeInfo kInfo{.name = "triangle", .properties = kProperties, .closure = Closure::Open};
};

inline AABB bounds(const Triangle& tri) {
  AABB b;
  b.extend(tri.v0);
  b.extend(tri.v1);
  b.extend(tri.v2);
  return b;
}

// A ray prepared for the watertight ray/triangle test (Woop, Benthin and Wald 2013, "Watertight
// Ray/Triangle Intersection", JCGT 2(1)): the axes permuted so the direction's largest
// component is z, and the shear that maps the direction onto +z. Built once per ray, used
// for every triangle it meets.
struct TriangleRay {
  Vec3 origin{0.0};
  Vec3 direction{0, 0, 1};
  int kx = 0, ky = 1, kz = 2;
  double sx = 0.0, sy = 0.0, sz = 1.0;

  explicit TriangleRay(const Ray& ray) : origin(ray.origin), direction(ray.direction) {
    Vec3 ad = glm::abs(ray.direction);
    kz = ad.x > ad.y ? (ad.x > ad.z ? 0 : 2) : (ad.y > ad.z ? 1 : 2);
    kx = kz == 2 ? 0 : kz + 1;
    ky = kx == 2 ? 0 : kx + 1;
    if (ray.direction[kz] < 0.0) std::swap(kx, ky);  // keep the winding
    sx = ray.direction[kx] / ray.direction[kz];
    sy = ray.direction[ky] / ray.direction[kz];
    sz = 1.0 / ray.direction[kz];
  }
};

namespace detail {
// Whether a ray along d meets the plane of edges e1, e2 at more than tol::kTriangleDeterminant
// of the largest angle it could: d . (e1 x e2) against |d| |e1| |e2|, scale-free. Compared
// squared, without a square root, while those squares (a length to the fourth power) stay
// inside tol::kUnscaledLength*'s fourth powers; past that (a scene modelled at 1e100 or
// 1e-100 units) with the lengths themselves, whose products stay finite to about 1e154.
inline bool crosses_plane(const Vec3& d, const Vec3& e1, const Vec3& e2) {
  const double det3 = glm::dot(d, glm::cross(e1, e2));
  const double scale2 = glm::dot(d, d) * glm::dot(e1, e1) * glm::dot(e2, e2);
  constexpr double k = tol::kTriangleDeterminant;
  constexpr double lo = tol::kUnscaledLengthMin, hi = tol::kUnscaledLengthMax;
  if (scale2 > lo * lo * lo * lo && scale2 < hi * hi * hi * hi) return det3 * det3 > k * k * scale2;
  return std::abs(det3) > k * scaled_length(d) * scaled_length(e1) * scaled_length(e2);
}

// The three edge functions of the sheared, projected vertices (2D cross products). Each
// depends only on its own edge's two vertices, computed the same way from both triangles
// sharing the edge: a ray through an edge gets exactly the same value (with opposite sign)
// from both, so it can never pass between them.
template <typename F>
inline void edge_functions(F ax, F ay, F bx, F by, F cx, F cy, F& u, F& v, F& w) {
  u = cx * by - cy * bx;
  v = ax * cy - ay * cx;
  w = bx * ay - by * ax;
}
}  // namespace detail

// Returns t and barycentrics (b1, b2) of the hit, or false. Edges and vertices are inclusive,
// so a ray through a shared edge hits both triangles; zero-area triangles, NaN vertices and
// rays in the triangle's plane are never hit.
inline bool intersect_triangle(const Vec3& v0, const Vec3& v1, const Vec3& v2, const TriangleRay& ray,
                               const Interval& ray_t, double& t, double& b1, double& b2) {
  const Vec3 a = v0 - ray.origin, b = v1 - ray.origin, c = v2 - ray.origin;
  const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
  const double ax = a[kx] - ray.sx * a[kz], ay = a[ky] - ray.sy * a[kz];
  const double bx = b[kx] - ray.sx * b[kz], by = b[ky] - ray.sy * b[kz];
  const double cx = c[kx] - ray.sx * c[kz], cy = c[ky] - ray.sy * c[kz];
  double u, v, w;
  detail::edge_functions(ax, ay, bx, by, cx, cy, u, v, w);
  // An edge function that rounds to exactly zero is re-evaluated in extended precision, as
  // the paper falls back from float to double: its sign decides which side of the edge.
  if (u == 0.0 || v == 0.0 || w == 0.0) {
    long double lu, lv, lw;
    detail::edge_functions<long double>(ax, ay, bx, by, cx, cy, lu, lv, lw);
    u = static_cast<double>(lu);
    v = static_cast<double>(lv);
    w = static_cast<double>(lw);
  }
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
  const double det = u + v + w;
  if (!(det != 0.0)) return false;  // zero, or NaN from NaN vertices
  const double az = ray.sz * a[kz], bz = ray.sz * b[kz], cz = ray.sz * c[kz];
  // det is the sheared triangle's doubled area (a length squared) and the sum below a length
  // cubed, which overflows past about 1e100 units and underflows below 1e-100: outside the
  // squares of tol::kUnscaledLength* the barycentric weights (each within [0, 1]) multiply
  // the depths instead, at one more rounding per term; inside, the paper's formula keeps its bits.
  constexpr double lo = tol::kUnscaledLengthMin, hi = tol::kUnscaledLengthMax;
  const double abs_det = std::abs(det);
  const double tt = abs_det > lo * lo && abs_det < hi * hi ? (u * az + v * bz + w * cz) / det
                                                           : (u / det) * az + (v / det) * bz + (w / det) * cz;
  if (!ray_t.surrounds(tt)) return false;
  // Scale-free degeneracy test, done last since most candidates fail the tests above.
  // Zero-area triangles and rays in the triangle's plane fail it (a neighbour across a
  // shared edge is hit instead, since edges are inclusive).
  if (!detail::crosses_plane(ray.direction, v1 - v0, v2 - v0)) return false;
  t = tt;
  b1 = v / det;
  b2 = w / det;
  return true;
}

inline bool intersect_triangle(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Ray& ray,
                               const Interval& ray_t, double& t, double& b1, double& b2) {
  return intersect_triangle(v0, v1, v2, TriangleRay(ray), ray_t, t, b1, b2);
}

// The hit point from the barycentrics (pbrt-v4): on the triangle's plane up to rounding,
// however far the ray travelled; `error` bounds that rounding.
inline Vec3 triangle_point(const Vec3& v0, const Vec3& v1, const Vec3& v2, double b1, double b2,
                           double& error) {
  double b0 = 1.0 - b1 - b2;
  Vec3 p0 = b0 * v0, p1 = b1 * v1, p2 = b2 * v2;
  error = error_gamma(7) * max_abs_component(glm::abs(p0) + glm::abs(p1) + glm::abs(p2));
  return p0 + p1 + p2;
}

inline bool intersect(const Triangle& tri, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double t, b1, b2;
  if (!intersect_triangle(tri.v0, tri.v1, tri.v2, TriangleRay(ray), ray_t, t, b1, b2)) return false;
  hit.t = t;
  hit.point = triangle_point(tri.v0, tri.v1, tri.v2, b1, b2, hit.error);
  hit.normal = unit_vector(glm::cross(tri.v1 - tri.v0, tri.v2 - tri.v0));  // 1e100-unit edges too
  hit.shading_normal = hit.normal;
  if (tri.normals) {
    const TriangleNormals& tn = *tri.normals;
    Vec3 n = (1.0 - b1 - b2) * tn.n0 + b1 * tn.n1 + b2 * tn.n2;
    double len = glm::length(n);
    if (len > tol::kTinyLength) hit.shading_normal = n / len;
  }
  hit.uv = {b1, b2};
  hit.has_uv = false;  // a lone triangle has no texture parameterisation
  return true;
}

}  // namespace rts::render
