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
#include "render/shade/fog.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/medium.hpp"
#include "render/shade/medium_stack.hpp"
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
                 const std::vector<CompiledTexture>& textures, const std::vector<CompiledMedium>& media, int max_depth,
                 std::vector<Warning>& warnings);

  // Radiance arriving along a camera ray.
  Rgb trace(const Ray& ray, Sampler& sampler, RayCounters& counters) const;

  // Media: the objects around the camera at `eye` (media_around), which its rays start inside.
  void start_at(const Vec3& eye) {
    if (has_media_) camera_media_ = media_around(world_, materials_, eye);
  }

  // The path features this scene uses and leaves out (for --stats).
  void describe(std::vector<std::string>& used, std::vector<std::string>& left_out) const;

 private:
  Lobes lobes(const MaterialDesc& m, uint32_t material_id, const WorldHit& hit) const;
  const MaterialDesc& material(const WorldHit& hit) const;
  // The material a hit on material `id` shows (a choice by pattern resolved; `id` becomes its id).
  const MaterialDesc& surface_material(uint32_t& id, const WorldHit& hit) const;  // a material chosen by pattern: the choice there
  const CompiledMedium* medium_of(const MediumStack& media) const {
    const MediumId id = media.medium(atmosphere_);
    return id < media_.size() ? &media_[id] : nullptr;
  }
  // Next-event estimation from `point` (inside the media `media`): one light, its radiance
  // times `response(wi)` (the BSDF's f·cos, or the phase function), weighed against
  // `scatter_pdf(wi)` by the power heuristic. The shadow ray leaves a surface point offset
  // along its facing normal `ng` by `error` (a medium point: ng 0, no offset).
  template <class Response, class Pdf>
  Rgb light_sample(const Vec3& point, const Vec3& ng, double error, const MediumStack& media, double u_pick,
                   glm::dvec2 u_light, Sampler& sampler, RayCounters& counters, Response&& response,
                   Pdf&& scatter_pdf) const;
  // What reaches `origin + end * dir` from `origin` along unit `dir`: 0 behind anything but
  // pass-through surfaces, else the media's transmittance (scenes with media or pass-through
  // surfaces; the others test occlusion alone).
  Rgb shadow(const Vec3& origin, const Vec3& dir, double end, const MediumStack& media, Sampler& sampler) const;

  const World& world_;
  const std::vector<MaterialDesc>& materials_;
  const std::vector<CompiledTexture>& textures_;
  MaterialDesc default_material_;
  LightSet lights_;
  std::vector<double> scale_;   // by MaterialId: the energy normalisation (1 when none is needed)
  int max_depth_;
  double clamp_;  // settings.clamp; 0: none
  bool has_transmission_ = false, has_microfacets_ = false;
  const std::vector<CompiledMedium>& media_;
  MediumId atmosphere_ = kNoId;
  // Some placed material has a medium (or settings do), or lets light through unchanged:
  // shadow rays walk surfaces one by one and each segment may hold a medium.
  bool has_media_ = false, has_pass_through_ = false;
  bool has_layers_ = false;  // a placed material is layered: one sampler value per hit picks the layer
  // Fog (settings.fog_*): in path mode a medium that absorbs and glows with its colour, so
  // every path segment brings T L + (1 - T) fog_color, and light reaching a point by a
  // shadow ray is dimmed by T too (unlike the Whitted integrator's POV-Ray rule).
  MediumStack camera_media_;
  bool fog_on_ = false;
  Fog fog_;
  Rgb fog_color_{0.0};
};

}  // namespace rts::render::path
