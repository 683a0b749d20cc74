// Isosurface (POV-Ray's `isosurface { function { ... } threshold max_gradient contained_by }`):
// the solid f(p) < threshold inside a container (a box or a sphere), f a macro of the point
// compiled once into register code (render/geometry/function/compiled_function.hpp).
//
// Root finding follows POV-Ray's contract: `max_gradient` G is a bound on |grad f|, so at a
// point where |f - threshold| = v no surface lies nearer than v / G, and the ray may step that
// far (never less than `accuracy`); a sign change between two steps is bisected until the
// bracket is shorter than `accuracy`, then placed by one secant step. A G below the function's
// real gradient can step over thin parts: the slope between every two samples is measured
// and, after rendering, a warning names the largest one seen (IsoGradientMonitor).
//
// The container's own surface closes the solid where f < threshold on it (as POV-Ray does
// unless `open`), so an isosurface is always a closed CSG operand.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/geometry/tolerances.hpp"
#include "render/geometry/function/compiled_function.hpp"
#include "render/scene/params.hpp"

namespace rts::render {

// The largest slope |f(b) - f(a)| / |b - a| seen between consecutive samples, over all rays.
struct IsoGradientMonitor {
  std::atomic<double> max_seen{0.0};
  void observe(double slope) {
    double cur = max_seen.load(std::memory_order_relaxed);
    while (slope > cur && !max_seen.compare_exchange_weak(cur, slope, std::memory_order_relaxed)) {
    }
  }
};

// The `isosurface` block: see docs/shapes.md#isosurface.
template <>
struct ShapeTraits<Isosurface> {
  static constexpr PropertyInfo kProperties[] = {
      {"function", "macro of a point", "*required*", "f(p): the solid is where f(p) < `threshold`."},
      {"threshold", "number", "`0`", "The value of f on the surface."},
      {"max_gradient", "number > 0", "`1.1`", "A bound on the length of f's gradient: the ray steps (f − threshold) / max_gradient."},
      {"accuracy", "number > 0", "`0.001`", "Roots are bracketed to this length (object space)."},
      {"max_trace", "whole number ≥ 1", "`1`", "Accepted as in POV-Ray; rts finds every crossing CSG needs."},
      {"contained_by", "box or sphere", "`box { min = <-1,-1,-1>  max = <1,1,1> }`",
       "The container; its surface closes the solid where f < threshold on it."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "isosurface", .properties = kProperties, .closure = Closure::Closed, .has_uv = true};
  static Isosurface build(ParamSet& ps) {
    IsosurfaceData g;
    const ParamValue* f = ps.value("function");
    if (!f)
      ps.fail_block("isosurface needs property 'function' (a macro of one point, e.g. macro f(p) { return length(p) - 1 })");
    auto* ref = std::get_if<FunctionRef>(f);
    if (!ref || !ref->function)
      throw SceneError(loc_of(ps, "function"),
                       fmt::format("property 'function' of isosurface expects a macro of one point, got a {}",
                                   param_type_name(*f)));
    g.function = ref->function;
    g.threshold = ps.number("threshold", g.threshold);
    require(ps, "threshold", std::isfinite(g.threshold), "finite", g.threshold);
    g.max_gradient = positive(ps, "max_gradient", ps.number("max_gradient", g.max_gradient));
    g.accuracy = positive(ps, "accuracy", ps.number("accuracy", g.accuracy));
    g.max_trace = ps.integer("max_trace", g.max_trace);
    require(ps, "max_trace", g.max_trace >= 1, ">= 1", g.max_trace);
    if (const ParamValue* c = ps.value("contained_by")) {
      auto* box = std::get_if<ContainerParam>(c);
      if (!box)
        throw SceneError(loc_of(ps, "contained_by"),
                         fmt::format("property 'contained_by' of isosurface expects a box or a sphere, got a {}",
                                     param_type_name(*c)));
      g.container_sphere = box->sphere;
      g.box_min = box->min;
      g.box_max = box->max;
      g.center = box->center;
      g.radius = box->radius;
    }
    Vec3 size = g.container_sphere ? Vec3(2.0 * g.radius) : g.box_max - g.box_min;
    if (!(size.x > 0.0 && size.y > 0.0 && size.z > 0.0) || !std::isfinite(size.x + size.y + size.z))
      throw SceneError(loc_of(ps, "contained_by"),
                       "the isosurface's container is empty: a box needs max > min in every component, a sphere a "
                       "radius > 0");
    g.monitor = std::make_shared<IsoGradientMonitor>();
    return Isosurface(std::move(g));
  }
};

inline AABB iso_container_box(const IsosurfaceData& s) {
  if (s.container_sphere) return AABB{s.center - Vec3(s.radius), s.center + Vec3(s.radius)};
  return AABB{s.box_min, s.box_max};
}

inline AABB bounds(const IsosurfaceData& s) { return iso_container_box(s); }

// The segment of the line inside the container, [t0, t1]; false when it misses.
inline bool iso_container_span(const IsosurfaceData& s, const Ray& ray, double& t0, double& t1) {
  if (s.container_sphere) {
    Vec3 oc = ray.origin - s.center;
    double a = glm::dot(ray.direction, ray.direction), b = glm::dot(oc, ray.direction);
    // The discriminant about the closest point (no cancellation far from the sphere).
    Vec3 perp = oc - (b / a) * ray.direction;
    double disc = s.radius * s.radius - glm::dot(perp, perp);
    if (!(a > 0.0) || !(disc > 0.0)) return false;
    double h = std::sqrt(disc * a);
    t0 = (-b - h) / a;
    t1 = (-b + h) / a;
    return t0 < t1;
  }
  t0 = -Interval::kInfinity;
  t1 = Interval::kInfinity;
  for (int k = 0; k < 3; ++k) {
    double d = ray.direction[k], o = ray.origin[k];
    if (d == 0.0) {
      if (o < s.box_min[k] || o > s.box_max[k]) return false;
      continue;
    }
    double ta = (s.box_min[k] - o) / d, tb = (s.box_max[k] - o) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return t0 < t1;
}

// f(p) - threshold: negative inside. A NaN counts as outside (eval maps it to 0).
inline double iso_value(const IsosurfaceData& s, const Vec3& p) { return s.function->eval(p) - s.threshold; }

// Samples at least this many per container span (see iso_crossings).
inline constexpr double kIsoMinSamples = 16.0;

// Every crossing of the solid's surface along the line within [a, b] (a part of the container
// span [t0, t1]), ascending, at most `max_out`. The container's faces count where the solid
// touches them (only at t0 and t1 themselves). `first_only` stops at the first crossing.
// `on_container[i]` says crossing i is on the container.
inline int iso_crossings(const IsosurfaceData& s, const Ray& ray, double t0, double t1, double a, double b,
                         double* t_out, bool* on_container, int max_out) {
  const double dl = glm::length(ray.direction);
  if (!(dl > 0.0) || !(a < b) || !s.function) return 0;
  const double min_step = s.accuracy / dl, inv_g = 1.0 / (s.max_gradient * dl);
  // No step longer than a kIsoMinSamples-th of the span: with too small a max_gradient the
  // steps would otherwise leap over the whole solid, and the slopes measured between samples
  // (the warning's evidence) would say nothing.
  const double max_step = (t1 - t0) / kIsoMinSamples;
  int count = 0;
  double t = a, v = iso_value(s, ray.at(a));
  if (!std::isfinite(v)) v = 1.0;
  if (v < 0.0 && a == t0) {
    on_container[count] = true;
    t_out[count++] = t0;
    if (count >= max_out) return count;
  }
  double slope_max = 0.0;
  // A safety bound on the samples: the segment in accuracy-long steps, and 1e6 at most.
  const double max_steps = std::min(1e6, (b - a) / min_step + 2.0);
  for (double steps = 0; t < b && steps < max_steps; ++steps) {
    double step = std::clamp(std::abs(v) * inv_g, min_step, std::max(max_step, min_step));
    double tn = std::min(t + step, b);
    double vn = iso_value(s, ray.at(tn));
    if (!std::isfinite(vn)) vn = 1.0;
    // A slope over less than `accuracy` measures the function's rounding, not its gradient:
    // the steps add up to b one ulp short, and the last, one-ulp step of a torus's distance
    // function read as a gradient of 4 (a false warning on bench/race/isosurface.rts).
    if (tn - t >= min_step) slope_max = std::max(slope_max, std::abs(vn - v) / ((tn - t) * dl));
    if ((v < 0.0) != (vn < 0.0)) {
      double lo = t, hi = tn, vlo = v, vhi = vn;
      while ((hi - lo) * dl > s.accuracy) {
        double m = 0.5 * (lo + hi);
        if (m <= lo || m >= hi) break;
        double vm = iso_value(s, ray.at(m));
        if (!std::isfinite(vm)) vm = 1.0;
        if ((vm < 0.0) == (vlo < 0.0)) {
          lo = m;
          vlo = vm;
        } else {
          hi = m;
          vhi = vm;
        }
      }
      // One secant step inside the bracket places the root far better than its middle.
      double root = vhi != vlo ? lo + (hi - lo) * (vlo / (vlo - vhi)) : 0.5 * (lo + hi);
      on_container[count] = false;
      t_out[count++] = std::clamp(root, lo, hi);
      if (count >= max_out) break;
    }
    t = tn;
    v = vn;
  }
  if (count < max_out && t >= b && b == t1 && v < 0.0) {
    on_container[count] = true;
    t_out[count++] = t1;
  }
  if (s.monitor) s.monitor->observe(slope_max);
  return count;
}

// The outward normal of the container at p (on its surface).
inline Vec3 iso_container_normal(const IsosurfaceData& s, const Vec3& p) {
  if (s.container_sphere) {
    Vec3 n = p - s.center;
    double len = glm::length(n);
    return len > 0.0 ? n / len : Vec3(0, 1, 0);
  }
  Vec3 c = 0.5 * (s.box_min + s.box_max), h = 0.5 * (s.box_max - s.box_min);
  Vec3 q = (p - c) / h;
  int k = std::abs(q.x) >= std::abs(q.y) ? (std::abs(q.x) >= std::abs(q.z) ? 0 : 2) : (std::abs(q.y) >= std::abs(q.z) ? 1 : 2);
  Vec3 n(0.0);
  n[k] = q[k] >= 0.0 ? 1.0 : -1.0;
  return n;
}

// The hit at crossing t: on the function's surface the normal is grad f by central
// differences (steps of kIsoNormalStep of the container's size); on the container, its own.
inline void iso_hit_at(const IsosurfaceData& s, const Ray& ray, double t, bool on_container, SurfaceHit& hit) {
  Vec3 p = ray.at(t);
  AABB box = iso_container_box(s);
  Vec3 size = box.hi - box.lo;
  double extent = std::max({size.x, size.y, size.z});
  Vec3 n;
  if (on_container) {
    n = iso_container_normal(s, p);
  } else {
    const double h = tol::kIsoNormalStep * extent;
    Vec3 g(iso_value(s, p + Vec3(h, 0, 0)) - iso_value(s, p - Vec3(h, 0, 0)),
           iso_value(s, p + Vec3(0, h, 0)) - iso_value(s, p - Vec3(0, h, 0)),
           iso_value(s, p + Vec3(0, 0, h)) - iso_value(s, p - Vec3(0, 0, h)));
    double len = glm::length(g);
    n = len > 0.0 && std::isfinite(len) ? g / len : -glm::normalize(ray.direction);
  }
  hit.t = t;
  hit.point = p;
  // A root is placed within `accuracy` along the ray; the point's own rounding comes on top.
  hit.error = (on_container ? 0.0 : s.accuracy) + 4.0 * ray_point_error(ray, t);
  hit.normal = n;
  hit.shading_normal = n;
  // u around y from +x (as the sphere's), v up the container.
  Vec3 c = 0.5 * (box.lo + box.hi);
  double u = 0.5 + std::atan2(p.z - c.z, p.x - c.x) / (2.0 * std::numbers::pi);
  hit.uv = {u, std::clamp((p.y - box.lo.y) / size.y, 0.0, 1.0)};
  hit.has_uv = true;
}

// The first crossing inside ray_t (t, and whether it is on the container): when the segment
// starts inside the solid at ray_t.min (not at the container), the first sign change is where
// the ray leaves it.
inline bool iso_first_crossing(const IsosurfaceData& s, const Ray& ray, Interval ray_t, double& t,
                               bool& on_container) {
  double t0, t1;
  if (!iso_container_span(s, ray, t0, t1)) return false;
  double a = std::max(t0, ray_t.min), b = std::min(t1, ray_t.max);
  if (!(a < b)) return false;
  return iso_crossings(s, ray, t0, t1, a, b, &t, &on_container, 1) > 0 && ray_t.surrounds(t);
}

inline bool intersect(const IsosurfaceData& s, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  double t;
  bool on;
  if (!iso_first_crossing(s, ray, ray_t, t, on)) return false;
  iso_hit_at(s, ray, t, on, hit);
  return true;
}

// For a shadow ray: intersect's answer without the hit, whose normal alone is six evaluations
// of the function (profile finding: shadow rays blocked by an isosurface computed it and the
// uv's atan2 for nothing).
inline bool occludes(const IsosurfaceData& s, const Ray& ray, Interval ray_t) {
  double t;
  bool on;
  return iso_first_crossing(s, ray, ray_t, t, on);
}

// The shape as the scene and the world hold it (its data boxed: scene.hpp).
inline bool occludes(const Isosurface& s, const Ray& ray, Interval ray_t) { return occludes(*s, ray, ray_t); }
inline AABB bounds(const Isosurface& s) { return bounds(*s); }
inline bool intersect(const Isosurface& s, const Ray& ray, Interval ray_t, SurfaceHit& hit) {
  return intersect(*s, ray, ray_t, hit);
}

// After rendering: when the slopes seen between samples exceeded max_gradient, the ray could
// have stepped over thin parts of the surface (POV-Ray warns the same way).
inline std::optional<std::string> after_render_warning(const IsosurfaceData& s) {
  double seen = s.monitor ? s.monitor->max_seen.load() : 0.0;
  if (!(seen > s.max_gradient)) return std::nullopt;
  return fmt::format("isosurface: the function's gradient reached {:.3g} along the rays traced, above max_gradient "
                     "{:g}; parts of the surface may be missing (set max_gradient = {:.2g} or more)",
                     seen, s.max_gradient, seen * 1.1);
}
inline std::optional<std::string> after_render_warning(const Isosurface& s) { return after_render_warning(*s); }

}  // namespace rts::render
