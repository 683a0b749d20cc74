// The path tracer (`settings { integrator = "path" }`, `rts render --integrator path`): an
// unbiased estimate of the rendering equation for each camera sample. At each surface it adds
// next-event estimation to one light (LightSet), continues by sampling the BSDF (Bsdf), and
// weighs the two ways of finding an emitter by the power heuristic; delta lights and specular
// lobes are counted by their one strategy alone. max_depth bounds the bounces after the first
// hit; Russian roulette ends dim paths from kRouletteStart bounces on. Nothing is clamped.
#pragma once

#include <string>
#include <vector>

#include "render/accel/world.hpp"
#include "render/scene/source_ref.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/path/bsdf.hpp"
#include "render/shade/path/light_set.hpp"
#include "render/shade/texture.hpp"
#include "render/sample/sampler.hpp"
#include "render/image/stats.hpp"

namespace rts::render::path {

// Bounces before Russian roulette may end a path (pbrt-v4 and Cycles start it about here).
inline constexpr int kRouletteStart = 3;

class PathIntegrator {
 public:
  // Materials whose weights would reflect more than they receive are scaled down, each with
  // a located warning appended to `warnings`.
  PathIntegrator(const World& world, const SceneDesc& scene, const std::vector<CompiledLight>& lights,
                 const std::vector<CompiledTexture>& textures, int max_depth, std::vector<Warning>& warnings);

  // Radiance arriving along a camera ray.
  Rgb trace(const Ray& ray, Sampler& sampler, RayCounters& counters) const;

  // The path features this scene uses and leaves out (for --stats).
  void describe(std::vector<std::string>& used, std::vector<std::string>& left_out) const;

 private:
  Lobes lobes(const MaterialDesc& m, uint32_t material_id, const WorldHit& hit) const;

  const World& world_;
  const std::vector<MaterialDesc>& materials_;
  const std::vector<CompiledTexture>& textures_;
  MaterialDesc default_material_;
  LightSet lights_;
  std::vector<double> scale_;   // by MaterialId: the energy normalisation (1 when none is needed)
  int max_depth_;
  double clamp_;  // settings.clamp; 0: none
  bool has_transmission_ = false, has_microfacets_ = false;
};

}  // namespace rts::render::path
