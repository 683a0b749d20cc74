// Blob (POV-Ray's `blob { threshold  sphere { C, r, s }  cylinder { A, B, r, s } }`): the
// solid where the summed field of its components exceeds `threshold`. A component of radius r
// and strength s adds s (1 - d^2/r^2)^2 at distance d < r from its centre (a sphere) or from
// its axis segment (a cylinder, whose ends are hemispheres), nothing beyond: POV-Ray's field.
//
// Along a ray, d^2 is a quadratic in t on each piece (inside a component's reach, and for a
// cylinder on the body or either cap), so the field is a quartic on each interval between the
// pieces' ends. The crossings are the roots of (field - threshold) on each interval, isolated
// by poly_roots about the interval's middle (coefficients of the blob's own size wherever the
// ray starts): exact up to rounding, no step to miss a thin part.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/poly_roots.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/geometry/tolerances.hpp"
#include "render/scene/params.hpp"

namespace rts::render {

// The `blob` block: see docs/shapes.md#blob.
template <>
struct ShapeTraits<Blob> {
  static constexpr PropertyInfo kProperties[] = {
      {"threshold", "number > 0", "`1`", "The field's value on the surface; inside, the field is larger."},
      {"spheres", "list of `[center, radius, strength]`", "`[]`", "Sphere components (POV-Ray's `sphere { C, r, s }`)."},
      {"cylinders", "list of `[from, to, radius, strength]`", "`[]`",
       "Cylinder components with hemispherical ends (POV-Ray's `cylinder { A, B, r, s }`)."},
  };
  static constexpr ShapeInfo kInfo{.name = "blob", .properties = kProperties, .closure = Closure::Closed, .has_uv = true};
  static Blob build(ParamSet& ps) {
    Blob g;
    g.threshold = positive(ps, "threshold", ps.number("threshold", g.threshold));
    auto rows = [&](std::string_view name, int vectors) {
      std::vector<BlobComponent> out;
      const ParamValue* v = ps.value(name);
      if (!v) return out;
      const std::string shape = vectors == 1 ? "[center, radius, strength]" : "[from, to, radius, strength]";
      const auto* list = std::get_if<RowsParam>(v);
      const auto* empty = std::get_if<std::vector<double>>(v);
      if (empty && empty->empty()) return out;
      if (!list)
        throw SceneError(loc_of(ps, name), fmt::format("property '{}' of blob expects a list of {} lists, got a {}",
                                                       name, shape, param_type_name(*v)));
      for (std::size_t i = 0; i < list->rows.size(); ++i) {
        const RowsParam::Row& r = list->rows[i];
        if (r.vectors.size() != static_cast<std::size_t>(vectors) || r.numbers.size() != 2)
          throw SceneError(loc_of(ps, name), fmt::format("blob {} entry {} must be {}", name, i + 1, shape));
        BlobComponent c;
        c.cylinder = vectors == 2;
        c.a = r.vectors[0];
        c.b = c.cylinder ? r.vectors[1] : r.vectors[0];
        c.radius = r.numbers[0];
        c.strength = r.numbers[1];
        if (!(c.radius > 0.0) || !std::isfinite(c.radius))
          throw SceneError(loc_of(ps, name),
                           fmt::format("blob {} entry {}: the radius must be > 0, got {}", name, i + 1, c.radius));
        if (!(c.strength != 0.0) || !std::isfinite(c.strength))
          throw SceneError(loc_of(ps, name), fmt::format("blob {} entry {}: the strength must be a non-zero number, got {}",
                                                         name, i + 1, c.strength));
        if (c.cylinder && !(glm::length(c.b - c.a) > tol::kTinyLength))
          throw SceneError(loc_of(ps, name),
                           fmt::format("blob cylinders entry {}: 'from' and 'to' must differ (use a sphere)", i + 1));
        out.push_back(c);
      }
      return out;
    };
    for (const BlobComponent& c : rows("spheres", 1)) g.components.push_back(c);
    for (const BlobComponent& c : rows("cylinders", 2)) g.components.push_back(c);
    if (g.components.empty()) ps.fail_block("blob needs at least one component: 'spheres' or 'cylinders'");
    if (g.components.size() > kMaxBlobComponents)
      ps.fail_block(fmt::format("this blob has {} components, more than the {} one blob may hold", g.components.size(),
                                kMaxBlobComponents));
    return g;
  }
};

inline AABB bounds(const Blob& b) {
  AABB box;
  for (const BlobComponent& c : b.components) {
    if (!(c.strength > 0.0)) continue;  // negative components only take field away
    box.extend(glm::min(c.a, c.b) - Vec3(c.radius));
    box.extend(glm::max(c.a, c.b) + Vec3(c.radius));
  }
  return box;
}

// The field at p, and its gradient when asked.
inline double blob_field(const Blob& b, const Vec3& p, Vec3* grad = nullptr) {
  double f = 0.0;
  Vec3 g(0.0);
  for (const BlobComponent& c : b.components) {
    Vec3 q = c.a;
    if (c.cylinder) {
      Vec3 u = c.b - c.a;
      double h = std::clamp(glm::dot(p - c.a, u) / glm::dot(u, u), 0.0, 1.0);
      q = c.a + h * u;
    }
    Vec3 rel = p - q;
    double d2 = glm::dot(rel, rel), r2 = c.radius * c.radius;
    if (d2 >= r2) continue;
    double k = 1.0 - d2 / r2;
    f += c.strength * k * k;
    g += (-4.0 * c.strength * k / r2) * rel;
  }
  if (grad) *grad = g;
  return f;
}

namespace detail {
// d^2(s) = A s^2 + B s + C, the squared distance from p0 + s d to the point q (rel0 = p0 - q)
// or, with a unit axis w, to the line through q along w.
struct Dist2 {
  double A, B, C;
};
inline Dist2 dist2(const Vec3& rel0, const Vec3& d, const Vec3* w) {
  Dist2 q{glm::dot(d, d), 2.0 * glm::dot(rel0, d), glm::dot(rel0, rel0)};
  if (w) {
    double hd = glm::dot(d, *w), h0 = glm::dot(rel0, *w);
    q.A -= hd * hd;
    q.B -= 2.0 * hd * h0;
    q.C -= h0 * h0;
  }
  return q;
}
// The s where d^2(s) = r2 (0 or 2 of them), appended to out.
inline void reach_ends(const Dist2& q, double r2, double t_ref, double* out, int& n) {
  if (!(q.A > 0.0)) return;
  double disc = q.B * q.B - 4.0 * q.A * (q.C - r2);
  if (!(disc > 0.0)) return;
  double h = -0.5 * (q.B + std::copysign(std::sqrt(disc), q.B));
  out[n++] = t_ref + h / q.A;
  if (h != 0.0) out[n++] = t_ref + (q.C - r2) / h;
}
// The piece of component c that holds the point p: the point or axis its distance is to.
inline const Vec3* piece(const BlobComponent& c, const Vec3& p, Vec3& q, Vec3& w) {
  q = c.a;
  if (!c.cylinder) return nullptr;
  Vec3 u = c.b - c.a;
  double len = glm::length(u);
  w = u / len;
  double h = glm::dot(p - c.a, w);
  if (h > len) q = c.b;
  return h >= 0.0 && h <= len ? &w : nullptr;
}
}  // namespace detail

// Every crossing of the surface along the whole line, ascending (at most max_out); how many.
// Between consecutive "ends" (where the ray enters or leaves a component's reach, or passes a
// cylinder's end plane) every component is one polynomial piece or absent, decided at the
// interval's middle; the roots of field - threshold there are the crossings.
//
// Solved along a direction as long as the blob's largest radius (t = s r / |d|): the
// quartic's leading coefficient is (|d| / r)^4 of the others, so a blob 1e4 units across (or
// one placed with `scale 1e4`, traced in object space with |d| = 1e-4) fell below
// tol::kBlobLeadingCoefficient, its crossings were solved as a quadratic's and the surface
// showed holes.
inline int blob_crossings_scaled(const Blob& b, const Ray& ray, double* t_out, int max_out);

inline int blob_crossings(const Blob& b, const Ray& ray, double* t_out, int max_out) {
  const double len = scaled_length(ray.direction);
  if (!(len > 0.0) || !std::isfinite(len)) return 0;
  double reach = 0.0;
  for (const BlobComponent& c : b.components) reach = std::max(reach, c.radius);
  if (!(reach > 0.0) || !std::isfinite(reach)) return 0;
  const double step = reach / len;  // t per unit of the scaled ray's parameter
  if (step == 1.0) return blob_crossings_scaled(b, ray, t_out, max_out);
  const int n = blob_crossings_scaled(b, Ray{ray.origin, (ray.direction / len) * reach}, t_out, max_out);
  for (int i = 0; i < n; ++i) t_out[i] *= step;
  return n;
}

inline int blob_crossings_scaled(const Blob& b, const Ray& ray, double* t_out, int max_out) {
  const Vec3& o = ray.origin;
  const Vec3& d = ray.direction;
  const double dd = glm::dot(d, d);
  if (!(dd > 0.0) || !std::isfinite(dd)) return 0;
  // About the point of the line nearest the blob's centre: coefficients of the blob's size.
  AABB box = bounds(b);
  if (!box.valid()) return 0;
  const double t_ref = glm::dot(0.5 * (box.lo + box.hi) - o, d) / dd;
  const Vec3 p_ref = o + t_ref * d;
  uint16_t near[kMaxBlobComponents];
  int nn = 0;
  double ends[8 * kMaxBlobComponents];
  int ne = 0;
  for (std::size_t i = 0; i < b.components.size(); ++i) {
    const BlobComponent& c = b.components[i];
    const double r2 = c.radius * c.radius;
    const int before = ne;
    detail::reach_ends(detail::dist2(p_ref - c.a, d, nullptr), r2, t_ref, ends, ne);
    if (c.cylinder) {
      Vec3 u = c.b - c.a;
      Vec3 w = u / glm::length(u);
      detail::reach_ends(detail::dist2(p_ref - c.b, d, nullptr), r2, t_ref, ends, ne);
      detail::reach_ends(detail::dist2(p_ref - c.a, d, &w), r2, t_ref, ends, ne);
      double ud = glm::dot(u, d);
      if (ne > before && ud != 0.0) {
        ends[ne++] = glm::dot(c.a - o, u) / ud;
        ends[ne++] = glm::dot(c.b - o, u) / ud;
      }
    }
    if (ne > before) near[nn++] = static_cast<uint16_t>(i);
  }
  if (nn == 0) return 0;
  std::sort(ends, ends + ne);
  int count = 0;
  for (int i = 0; i + 1 < ne && count < max_out; ++i) {
    const double ta = ends[i], tb = ends[i + 1];
    if (!(tb > ta)) continue;
    const double tm = 0.5 * (ta + tb);
    const Vec3 pm = o + tm * d;
    double cc[5] = {-b.threshold, 0.0, 0.0, 0.0, 0.0};
    for (int j = 0; j < nn; ++j) {
      const BlobComponent& c = b.components[near[j]];
      const double r2 = c.radius * c.radius;
      Vec3 q, w;
      const Vec3* axis = detail::piece(c, pm, q, w);
      detail::Dist2 dq = detail::dist2(pm - q, d, axis);
      if (dq.C >= r2) continue;  // out of reach on this interval
      // k(s) = 1 - d2/r2 = k2 s^2 + k1 s + k0, the field strength k^2.
      double k2 = -dq.A / r2, k1 = -dq.B / r2, k0 = 1.0 - dq.C / r2;
      cc[4] += c.strength * k2 * k2;
      cc[3] += c.strength * 2.0 * k2 * k1;
      cc[2] += c.strength * (k1 * k1 + 2.0 * k2 * k0);
      cc[1] += c.strength * 2.0 * k1 * k0;
      cc[0] += c.strength * k0 * k0;
    }
    double scale = 0.0;
    for (double x : cc) scale = std::max(scale, std::abs(x));
    int n = 4;
    while (n > 0 && std::abs(cc[n]) <= tol::kBlobLeadingCoefficient * scale) --n;
    if (n == 0) continue;
    double roots[4];
    int nr = poly_roots(cc, n, ta - tm, tb - tm, roots);
    for (int k = 0; k < nr && count < max_out; ++k) t_out[count++] = tm + roots[k];
  }
  return count;
}

// The hit at crossing t: the normal is minus the field's gradient (the field grows inwards).
inline void blob_hit_at(const Blob& b, const Ray& ray, double t, SurfaceHit& hit) {
  Vec3 p = ray.at(t);
  Vec3 g;
  blob_field(b, p, &g);
  double len = glm::length(g);
  Vec3 n = len > 0.0 && std::isfinite(len) ? -g / len : -glm::normalize(ray.direction);
  hit.t = t;
  hit.point = p;
  // The root is exact to the polynomial's rounding, a few ulps of the blob's size.
  AABB box = bounds(b);
  Vec3 size = box.hi - box.lo;
  hit.error = 4.0 * ray_point_error(ray, t) + error_gamma(64) * (max_abs_component(box.lo) + max_abs_component(box.hi));
  hit.normal = n;
  hit.shading_normal = n;
  Vec3 c = 0.5 * (box.lo + box.hi);
  double u = 0.5 + std::atan2(p.z - c.z, p.x - c.x) / (2.0 * std::numbers::pi);
  hit.uv = {u, size.y > 0.0 ? std::clamp((p.y - box.lo.y) / size.y, 0.0, 1.0) : 0.5};
  hit.has_uv = true;
}

inline bool intersect(const Blob& b, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double ts[2 * kMaxBlobComponents];
  int n = blob_crossings(b, ray, ts, 2 * static_cast<int>(kMaxBlobComponents));
  for (int i = 0; i < n; ++i)
    if (ray_t.surrounds(ts[i])) {
      blob_hit_at(b, ray, ts[i], hit);
      return true;
    }
  return false;
}

}  // namespace rts::render
