#include "render/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "render/tolerances.hpp"

namespace rts::render {
namespace {

Rgb to_rgb(const Color& c) { return Rgb(c.r, c.g, c.b); }
double max_channel(const Rgb& c) { return std::max({c.x, c.y, c.z}); }
bool is_black(const Rgb& c) { return !(max_channel(c) > 0.0); }

// Uniform point in the unit ball from three uniforms (for glossy perturbation).
Vec3 in_unit_ball(Sampler& s) {
  double z = 2.0 * s.next() - 1.0;
  double phi = 2.0 * std::numbers::pi * s.next();
  double r = std::cbrt(s.next());
  double xy = std::sqrt(std::max(0.0, 1.0 - z * z));
  return r * Vec3(xy * std::cos(phi), xy * std::sin(phi), z);
}

}  // namespace

bool refract(const Vec3& incident, const Vec3& n, double eta, Vec3& refracted) {
  double cos_i = -glm::dot(incident, n);
  double sin2_t = eta * eta * std::max(0.0, 1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) return false;
  double cos_t = std::sqrt(1.0 - sin2_t);
  refracted = glm::normalize(eta * incident + (eta * cos_i - cos_t) * n);
  return true;
}

double schlick(double cos_theta, double f0) {
  double m = std::clamp(1.0 - cos_theta, 0.0, 1.0);
  double m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

Integrator::Integrator(const World& world, const std::vector<CompiledLight>& lights,
                       const std::vector<MaterialDesc>& materials,
                       const std::vector<CompiledTexture>& textures, const Settings& settings,
                       int max_depth)
    : world_(world), lights_(lights), materials_(materials), textures_(textures),
      background_(to_rgb(settings.background)), ambient_light_(to_rgb(settings.ambient_light)),
      max_depth_(max_depth) {}

const MaterialDesc& Integrator::material(uint32_t instance) const {
  MaterialId id = world_.instance(instance).material;
  return id < materials_.size() ? materials_[id] : default_material_;
}

Rgb Integrator::albedo(const MaterialDesc& m, const WorldHit& hit) const {
  if (m.texture != kNoId && m.texture < textures_.size()) {
    TexturePoint p;
    p.object_point = hit.object_point;
    p.has_uv = hit.has_uv;
    if (p.has_uv) p.uv = world_.surface_uv(hit);
    return to_rgb(textures_[m.texture].eval(p));
  }
  return to_rgb(m.color);
}

Rgb Integrator::trace(const Ray& ray, Sampler& sampler, RayCounters& counters) const {
  ++counters.camera;
  Path path{sampler, counters};
  return radiance(ray, 0, Rgb(1.0), path);
}

FirstHit Integrator::first_hit(const Ray& ray) const {
  FirstHit out;
  WorldHit hit;
  if (!world_.intersect(ray, Interval::positive(), hit)) return out;
  out.hit = true;
  out.normal = hit.shading_normal;
  out.depth = hit.t * glm::length(ray.direction);
  out.bounded = world_.instance(hit.instance).kind != PrimKind::Plane;
  out.albedo = albedo(material(hit.instance), hit);
  return out;
}

Rgb Integrator::shadow_transmittance(const Vec3& origin, const LightSample& ls, Path& path) const {
  ++path.counters.shadow;
  Ray ray{origin, ls.direction};
  double end = std::isinf(ls.distance) ? Interval::kInfinity
                                        : ls.distance * (1.0 - tol::kShadowEndRelative);
  Interval range(0.0, end);
  // Any opaque occluder blocks the light whatever else lies on the segment: test those first
  // with an early-exit traversal.
  if (world_.occluded(ray, range, /*opaque_only=*/true)) return Rgb(0.0);
  if (!world_.has_transmissive()) return Rgb(1.0);
  // Only transmissive surfaces remain: multiply through each one up to the light.
  Rgb t(1.0);
  for (int i = 0; i < tol::kMaxShadowSurfaces; ++i) {
    WorldHit hit;
    if (!world_.intersect(ray, range, hit, /*transmissive_only=*/true)) return t;
    Rgb kt = to_rgb(material(hit.instance).transmit);
    t *= glm::clamp(kt, 0.0, 1.0);
    if (max_channel(t) < tol::kMinPathWeight) return Rgb(0.0);
    range.min = hit.t + tol::kRayOffsetAbsolute +
                tol::kRayOffsetRelative * std::max(max_abs_component(hit.point), hit.t);
  }
  return Rgb(0.0);
}

Rgb Integrator::direct_light(const WorldHit& hit, const MaterialDesc& m, const Rgb& albedo,
                             const Vec3& n, const Vec3& shadow_origin, const Vec3& view,
                             Path& path) const {
  Sampler& sampler = path.sampler;
  Rgb sum(0.0);
  for (const CompiledLight& light : lights_) {
    uint32_t perm = sampler.next_bits();
    bool area = light.kind == LightKind::Area;
    uint32_t col = 0, row = 0;  // the grid stratum of sample j, stepped without dividing
    for (int j = 0; j < light.samples; ++j) {
      glm::dvec2 on_light(0.5);
      if (area) {
        glm::dvec2 jitter = sampler.next2();
        if (light.strata_side > 0) {
          on_light = (glm::dvec2(col, row) + jitter) * light.inv_strata;
          if (++col == light.strata_side) col = 0, ++row;
        } else {
          on_light = stratified_2d(static_cast<uint32_t>(j), static_cast<uint32_t>(light.samples), 0,
                                   jitter, perm);
        }
      }
      LightSample ls = sample_light(light, hit.point, on_light);
      double n_dot_l = glm::dot(n, ls.direction);
      if (n_dot_l <= 0.0 || is_black(ls.radiance)) continue;
      Rgb shade = m.diffuse * n_dot_l * albedo;
      if (m.specular > 0.0) {
        Vec3 r = 2.0 * n_dot_l * n - ls.direction;  // mirror of the light direction
        double r_dot_v = glm::dot(r, view);
        if (r_dot_v > 0.0) shade += m.specular * std::pow(r_dot_v, m.shininess) * to_rgb(m.specular_color);
      }
      if (is_black(shade)) continue;
      Rgb transmittance = light.shadows ? shadow_transmittance(shadow_origin, ls, path) : Rgb(1.0);
      sum += shade * ls.radiance * transmittance;
    }
  }
  return sum;
}

Rgb Integrator::radiance(const Ray& ray, int depth, const Rgb& weight, Path& path) const {
  WorldHit hit;
  if (!world_.intersect(ray, Interval::positive(), hit)) return background_;
  const MaterialDesc& m = material(hit.instance);
  double dir_len = glm::length(ray.direction);
  Vec3 incident = ray.direction / dir_len;
  double travelled = hit.t * dir_len;

  // The geometric normal decides the side: face it towards the incoming ray (leaving a solid
  // = hitting its back side). The shading normal is then put into the same hemisphere as the
  // faced geometric normal on its own, so vertex normals that disagree with the triangle's
  // winding (common in OBJ files and hand-written meshes) shade the same as consistent ones.
  Vec3 ng = hit.normal, n = hit.shading_normal;
  bool entering = glm::dot(ng, incident) < 0.0;
  if (!entering) ng = -ng;
  if (glm::dot(n, ng) < 0.0) n = -n;
  Vec3 view = -incident;
  Rgb base = albedo(m, hit);
  Rgb color = to_rgb(m.emission) + m.ambient * base * ambient_light_;
  Vec3 front_origin = offset_ray_origin(hit.point, ng, ng, travelled);
  color += direct_light(hit, m, base, n, front_origin, view, path);

  if (depth >= max_depth_) return color;

  Rgb kr = to_rgb(m.reflect), kt = to_rgb(m.transmit);
  double cos_i = std::clamp(glm::dot(n, view), 0.0, 1.0);
  Vec3 refracted(0.0);
  if (!is_black(kt)) {
    double eta = entering ? 1.0 / m.ior : m.ior;
    // With fresnel, the interface splits one budget, max(reflect, transmit) per channel,
    // between the two directions: a fraction F reflects, 1 - F (filtered by `transmit`)
    // passes, so kr + kt never exceeds the larger weight (1 for clear glass, whatever
    // `reflect` adds). Without fresnel the two weights simply add, as documented.
    if (!refract(incident, n, eta, refracted)) {
      // Total internal reflection: the transmitted energy is reflected (F = 1).
      kr = m.fresnel ? glm::max(kr, kt) : kr + kt;
      kt = Rgb(0.0);
    } else if (m.fresnel) {
      double f0 = (m.ior - 1.0) / (m.ior + 1.0);
      f0 *= f0;
      // Schlick uses the angle on the less dense side.
      double cos_outside = entering ? cos_i : -glm::dot(refracted, n);
      double f = schlick(std::abs(cos_outside), f0);
      kr = glm::max(kr, kt) * f;
      kt *= (1.0 - f);
    }
  } else if (m.fresnel && !is_black(kr)) {
    // Opaque: `reflect` is the reflectance at normal incidence, rising to 1 at grazing angles.
    double f = schlick(cos_i, 0.0);
    kr = kr + (Rgb(1.0) - kr) * f;
  }

  if (max_channel(kr * weight) > tol::kMinPathWeight) {
    Vec3 mirror = incident + 2.0 * cos_i * n;
    Vec3 dir = mirror;
    if (m.roughness > 0.0) {
      Vec3 glossy = mirror + m.roughness * in_unit_ball(path.sampler);
      // Perturbed below the surface: fall back to the mirror direction.
      if (glm::dot(glossy, ng) > 0.0 && glm::length(glossy) > tol::kTinyLength) dir = glm::normalize(glossy);
    }
    ++path.counters.reflection;
    Ray r{offset_ray_origin(hit.point, ng, dir, travelled), dir};
    color += kr * radiance(r, depth + 1, weight * kr, path);
  }
  if (max_channel(kt * weight) > tol::kMinPathWeight) {
    ++path.counters.refraction;
    Ray r{offset_ray_origin(hit.point, ng, refracted, travelled), refracted};
    color += kt * radiance(r, depth + 1, weight * kt, path);
  }
  return color;
}

}  // namespace rts::render
