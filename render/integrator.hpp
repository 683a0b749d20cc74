// Whitted ray tracing: Phong direct lighting with (transmission-filtered) shadow rays, then
// mirror/glossy reflection and Snell refraction (through nested media) up to max_depth,
// walked with an explicit stack of pending rays.
#pragma once

#include <vector>

#include "render/lights.hpp"
#include "render/medium_stack.hpp"
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
  // A ray still to trace, with the product of the reflect/transmit weights that lead to it
  // and the media it is inside.
  struct PendingRay {
    Ray ray;
    Rgb weight;
    int depth;
    MediumStack media;
  };
  // The indices on the two sides of a transmissive surface, from the side the ray comes from.
  struct Interface {
    double n_from = 1.0, n_to = 1.0;
  };
  static Interface interface(const MediumStack& media, uint32_t instance, const MaterialDesc& m,
                             bool entering);
  // The light a pending ray's hit sends back along it (emission, ambient, direct light); its
  // reflected and refracted rays go onto `pending`.
  Rgb shade(const PendingRay& pr, Path& path, std::vector<PendingRay>& pending) const;
  Rgb direct_light(const WorldHit& hit, const MaterialDesc& m, const Rgb& albedo, const Vec3& n,
                   const Vec3& shadow_origin, const Vec3& view, Path& path) const;
  Rgb shadow_transmittance(const Vec3& origin, const LightSample& ls, Path& path) const;
  const MaterialDesc& material(uint32_t instance) const;
  Rgb albedo(const MaterialDesc& m, const WorldHit& hit) const;

  const World& world_;
  const std::vector<CompiledLight>& lights_;
  const std::vector<MaterialDesc>& materials_;
  const std::vector<CompiledTexture>& textures_;
  MaterialDesc default_material_;
  Rgb background_, ambient_light_;
  int max_depth_;
};

// Snell refraction of unit `incident` through unit normal `n` (facing the incident side) with
// relative index eta = n_from / n_to. Returns false on total internal reflection.
bool refract(const Vec3& incident, const Vec3& n, double eta, Vec3& refracted);

// Schlick's approximation of Fresnel reflectance for reflectance at normal incidence f0.
double schlick(double cos_theta, double f0);

}  // namespace rts::render
