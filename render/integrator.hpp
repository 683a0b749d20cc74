// Whitted ray tracing: Phong direct lighting with (transmission-filtered) shadow rays, then
// recursive mirror/glossy reflection and Snell refraction up to max_depth.
#pragma once

#include <vector>

#include "render/lights.hpp"
#include "render/sampler.hpp"
#include "render/stats.hpp"
#include "render/texture.hpp"
#include "render/world.hpp"

namespace rts::render {

// What the first hit of a pixel's centre ray shows, for the AOV images.
struct FirstHit {
  bool hit = false;
  Vec3 normal{0.0};     // world shading normal, outward
  double depth = 0.0;   // distance from the camera
  bool bounded = false; // the surface is bounded geometry (not an infinite plane)
  Rgb albedo{0.0};
};

class Integrator {
 public:
  Integrator(const World& world, const std::vector<CompiledLight>& lights,
             const std::vector<MaterialDesc>& materials, const std::vector<CompiledTexture>& textures,
             const Settings& settings, int max_depth);

  // Radiance arriving along a camera ray.
  Rgb trace(const Ray& ray, Sampler& sampler, RayCounters& counters) const;
  FirstHit first_hit(const Ray& ray) const;

 private:
  // What one camera sample's path carries along.
  struct Path {
    Sampler& sampler;
    RayCounters& counters;
  };
  Rgb radiance(const Ray& ray, int depth, const Rgb& weight, Path& path) const;
  Rgb direct_light(const WorldHit& hit, const MaterialDesc& m, const Rgb& albedo, const Vec3& n,
                   const Vec3& shadow_origin, const Vec3& view, Path& path) const;
  Rgb shadow_transmittance(const Vec3& origin, const LightSample& ls, Path& path) const;
  const MaterialDesc& material(uint32_t instance) const;
  Rgb albedo(const MaterialDesc& m, const WorldHit& hit) const;
  // What a ray that leaves the scene sees: the environment map, else the background color.
  Rgb background(const Vec3& direction) const;

  const World& world_;
  const std::vector<CompiledLight>& lights_;
  const std::vector<MaterialDesc>& materials_;
  const std::vector<CompiledTexture>& textures_;
  MaterialDesc default_material_;
  Rgb background_, ambient_light_;
  const CompiledTexture* environment_ = nullptr;   // settings.environment, if any
  bool environment_ambient_ = false;
  int max_depth_;
};

// Snell refraction of unit `incident` through unit normal `n` (facing the incident side) with
// relative index eta = n_from / n_to. Returns false on total internal reflection.
bool refract(const Vec3& incident, const Vec3& n, double eta, Vec3& refracted);

// Schlick's approximation of Fresnel reflectance for reflectance at normal incidence f0.
double schlick(double cos_theta, double f0);

}  // namespace rts::render
