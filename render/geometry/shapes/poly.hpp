// POV-Ray's poly, quartic and cubic: the surface F(x, y, z) = sum c x^i y^j z^k = 0 of an
// algebraic polynomial of degree `order` (2 to 6), the solid where F < 0. Unbounded in general
// (a paraboloid, a saddle), so kept out of the BVH and tested like a plane; in CSG, an
// intersection with a box bounds it.
//
// Along a ray the polynomial is one of degree <= order in the ray parameter. It is formed
// about the ray's point closest to the object's origin, with a unit direction, so that the
// coefficients stay of the shape's own size however far away the ray starts (as the torus
// does); its real roots are isolated by poly_roots (no closed form to lose digits to) inside
// the Cauchy bound of the polynomial, which holds every root. A tangent ray (a double root)
// is a graze, not a crossing.
#pragma once

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/geometry/interval.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/poly_roots.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/geometry/tolerances.hpp"
#include "render/scene/params.hpp"

namespace rts::render {

inline constexpr int kPolyMinOrder = 2;
inline constexpr int kPolyMaxOrder = kPolyMaxDegree;  // what poly_roots isolates

// The number of coefficients of a poly of `order`: one per term x^i y^j z^k, i + j + k <= order.
constexpr int poly_coefficient_count(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }

// POV-Ray's order of the coefficients: i from `order` down to 0, then j from order - i down to
// 0, then k from order - i - j down to 0 (a quartic's first is x^4, its last the constant).
template <class F>
void for_each_poly_term(int order, F&& f) {
  int index = 0;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - i - j; k >= 0; --k) f(index++, i, j, k);
}

// The `poly` block: see docs/shapes.md#poly.
template <>
struct ShapeTraits<Poly> {
  static constexpr PropertyInfo kProperties[] = {
      {"order", "whole number, 2 to 6", "*required*", "The polynomial's degree (POV-Ray's quartic is 4, cubic 3)."},
      {"coefficients", "list of numbers", "*required*",
       "One per term x^i y^j z^k with i + j + k ≤ `order`, in POV-Ray's order (x^4, x^3 y, x^3 z, x^3, ... , "
       "z, 1 for a quartic): 10, 20, 35, 56 or 84 of them."},
  };
  static constexpr ShapeInfo kInfo{
      // Closed: the solid is where the polynomial is negative, as in POV-Ray.
      .name = "poly", .properties = kProperties, .closure = Closure::Closed, .bounded = false};
  // From the block's parameters (unknown names are checked by the builder afterwards).
  static Poly build(ParamSet& ps) {
    Poly g;
    if (!ps.has("order")) ps.fail_block("poly needs property 'order'");
    g.order = ps.integer("order", 0);
    if (g.order < kPolyMinOrder || g.order > kPolyMaxOrder)
      throw SceneError(loc_of(ps, "order"), fmt::format("poly order must be {} to {}, got {}", kPolyMinOrder,
                                                        kPolyMaxOrder, g.order));
    const ParamValue* v = ps.value("coefficients");
    if (!v) ps.fail_block("poly needs property 'coefficients'");
    const auto* list = std::get_if<std::vector<double>>(v);
    if (!list)
      throw SceneError(loc_of(ps, "coefficients"),
                       fmt::format("property 'coefficients' of poly expects a list of numbers, got a {}",
                                   param_type_name(*v)));
    const int want = poly_coefficient_count(g.order);
    if (static_cast<int>(list->size()) != want)
      throw SceneError(loc_of(ps, "coefficients"),
                       fmt::format("a poly of order {} takes {} coefficients, got {}", g.order, want, list->size()));
    for_each_poly_term(g.order, [&](int index, int i, int j, int k) {
      const double c = (*list)[index];
      if (!std::isfinite(c))
        throw SceneError(loc_of(ps, "coefficients"), fmt::format("poly coefficient {} is not finite", index + 1));
      if (c != 0.0)
        g.terms.push_back(PolyTerm{c, static_cast<uint8_t>(i), static_cast<uint8_t>(j), static_cast<uint8_t>(k)});
    });
    bool surface = false;  // a constant has no surface
    for (const PolyTerm& t : g.terms) surface = surface || t.i + t.j + t.k > 0;
    if (!surface)
      throw SceneError(loc_of(ps, "coefficients"), "poly has no surface: every coefficient but the constant is zero");
    return g;
  }
};

// F(p), and its gradient when `grad` is not null.
inline double poly_value(const Poly& poly, const Vec3& p, Vec3* grad = nullptr) {
  double px[kPolyMaxOrder + 1], py[kPolyMaxOrder + 1], pz[kPolyMaxOrder + 1];
  px[0] = py[0] = pz[0] = 1.0;
  for (int e = 1; e <= poly.order; ++e) {
    px[e] = px[e - 1] * p.x;
    py[e] = py[e - 1] * p.y;
    pz[e] = pz[e - 1] * p.z;
  }
  double f = 0.0;
  Vec3 g(0.0);
  for (const PolyTerm& t : poly.terms) {
    f += t.c * px[t.i] * py[t.j] * pz[t.k];
    if (grad) {
      if (t.i > 0) g.x += t.c * t.i * px[t.i - 1] * py[t.j] * pz[t.k];
      if (t.j > 0) g.y += t.c * t.j * px[t.i] * py[t.j - 1] * pz[t.k];
      if (t.k > 0) g.z += t.c * t.k * px[t.i] * py[t.j] * pz[t.k - 1];
    }
  }
  if (grad) *grad = g;
  return f;
}

// Every crossing of the surface along the whole line origin + t direction, ascending (at most
// `order`); `inside_at_start`: whether the line starts (t -> -infinity) inside the solid.
inline int poly_crossings(const Poly& poly, const Ray& ray, double* t_out, bool& inside_at_start) {
  inside_at_start = false;
  const double len = glm::length(ray.direction);
  if (!(len > tol::kTinyLength) || !std::isfinite(len)) return 0;
  const Vec3 d = ray.direction / len;
  const double s0 = -glm::dot(ray.origin, d);  // unit-speed parameter of the point closest to the origin
  const Vec3 p0 = ray.origin + s0 * d;
  if (!std::isfinite(s0) || !std::isfinite(p0.x + p0.y + p0.z)) return 0;
  // (p0 + s d)^e per axis, as coefficients of s^0..s^e.
  constexpr int N = kPolyMaxOrder + 1;
  double ax[N][N] = {}, ay[N][N] = {}, az[N][N] = {};
  ax[0][0] = ay[0][0] = az[0][0] = 1.0;
  for (int e = 1; e <= poly.order; ++e)
    for (int m = 0; m <= e; ++m) {
      ax[e][m] = (m < e ? ax[e - 1][m] * p0.x : 0.0) + (m > 0 ? ax[e - 1][m - 1] * d.x : 0.0);
      ay[e][m] = (m < e ? ay[e - 1][m] * p0.y : 0.0) + (m > 0 ? ay[e - 1][m - 1] * d.y : 0.0);
      az[e][m] = (m < e ? az[e - 1][m] * p0.z : 0.0) + (m > 0 ? az[e - 1][m - 1] * d.z : 0.0);
    }
  double c[N] = {};
  for (const PolyTerm& t : poly.terms) {
    double xy[N] = {};
    for (int a = 0; a <= t.i; ++a)
      for (int b = 0; b <= t.j; ++b) xy[a + b] += ax[t.i][a] * ay[t.j][b];
    for (int ab = 0; ab <= t.i + t.j; ++ab)
      for (int k = 0; k <= t.k; ++k) c[ab + k] += t.c * xy[ab] * az[t.k][k];
  }
  int n = poly.order;
  double bound = 0.0;
  for (;;) {
    while (n > 0 && c[n] == 0.0) --n;
    if (n == 0) break;
    // Cauchy's bound: every root s has |s| < 1 + max |c_m / c_n|.
    bound = 0.0;
    for (int m = 0; m < n; ++m) bound = std::max(bound, std::abs(c[m] / c[n]));
    bound = (1.0 + bound) * 1.0000001;
    if (bound <= tol::kPolyFarthestRoot) break;
    --n;
  }
  // Far back along the line the leading term decides the sign.
  inside_at_start = n % 2 == 0 ? c[n] < 0.0 : c[n] > 0.0;
  if (n == 0) return 0;
  double s[kPolyMaxOrder];
  const int count = poly_roots</*kWide=*/true>(c, n, -bound, bound, s);
  for (int r = 0; r < count; ++r) t_out[r] = (s0 + s[r]) / len;
  return count;
}

// The hit at crossing t (one of poly_crossings'): the normal is F's gradient there.
inline void poly_hit_at(const Poly& poly, const Ray& ray, double t, SurfaceHit& hit) {
  hit.t = t;
  hit.point = ray.at(t);
  hit.error = ray_point_error(ray, t);
  Vec3 g;
  poly_value(poly, hit.point, &g);
  const double glen = glm::length(g);
  // A singular point of the surface (a cone's apex) has no gradient: face the ray.
  const Vec3 n = glen > tol::kTinyLength && std::isfinite(glen) ? g / glen : -glm::normalize(ray.direction);
  hit.normal = n;
  hit.shading_normal = n;
  hit.has_uv = false;
}

inline bool intersect(const Poly& poly, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double ts[kPolyMaxOrder];
  bool inside_at_start;
  const int n = poly_crossings(poly, ray, ts, inside_at_start);
  for (int i = 0; i < n; ++i)
    if (ray_t.surrounds(ts[i])) {
      poly_hit_at(poly, ray, ts[i], hit);
      return true;
    }
  return false;
}

}  // namespace rts::render
