// Whitted ray tracing: Phong direct lighting with (transmission-filtered) shadow rays, then
// mirror/glossy reflection and Snell refraction (through nested media) up to max_depth,
// walked with an explicit stack of pending rays.
#pragma once

#include <vector>

#include "render/shade/cache_line_allocator.hpp"
#include "render/shade/features.hpp"
#include "render/shade/fog.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/material.hpp"
#include "render/shade/medium.hpp"
#include "render/shade/medium_stack.hpp"
#include "render/sample/sampler.hpp"
#include "render/image/stats.hpp"
#include "render/shade/texture.hpp"
#include "render/accel/world.hpp"

namespace rts::render {

namespace path {
class PathIntegrator;
}

// What the first hit of a pixel's centre ray shows, for the AOV images.
struct FirstHit {
  bool hit = false;
  Vec3 normal{0.0};     // world shading normal, outward
  double depth = 0.0;   // distance from the camera
  bool bounded = false; // the surface is bounded geometry (not an infinite plane)
  Rgb albedo{0.0};
};

// The shading paths are compiled for each combination of trace_flags (render/shade/features.hpp,
// where the leave-out table says which feature sets which flag): a scene runs through the one
// for the features it uses.

class Integrator {
 public:
  // `mask`: trace_flags::for_features(the scene's features), or trace_flags::kGeneric | trace_flags::kAll.
  Integrator(const World& world, const std::vector<CompiledLight>& lights,
             const std::vector<MaterialDesc>& materials, const std::vector<CompiledTexture>& textures,
             const Settings& settings, int max_depth, unsigned mask = trace_flags::kGeneric | trace_flags::kAll,
             const std::vector<CompiledMedium>* media = nullptr);

  // Radiance arriving along a camera ray.
  Rgb trace(const Ray& ray, Sampler& sampler, RayCounters& counters) const;
  FirstHit first_hit(const Ray& ray) const;
  // Path mode (settings.integrator = "path"): camera samples go to `tracer` instead of the
  // Whitted tree, through the same one indirect call, so Whitted scenes pay nothing for it.
  // The AOVs still come from first_hit.
  void use_path_tracer(const path::PathIntegrator* tracer);
  // Media: jitter the marched points (one sampler value per segment) and area lights' points
  // on them, for renders of several samples per pixel; else midpoints and centres (the same
  // image every time at one sample).
  void jitter_media(bool on) { media_jitter_ = on; }
  // Media: the objects around the camera at `eye` (media_around), which its rays start inside.
  void start_at(const Vec3& eye) {
    if (media_on_) camera_media_ = media_around(world_, materials_, eye);
  }

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
    int passes = 0;  // pass-through surfaces crossed on the way (tol::kMaxPassThrough)
  };
  // Each thread's stack of pending rays: a heap block written per reflected ray, allocated on
  // cache-line boundaries in whole lines, so it shares no line with whatever the allocator puts
  // beside it. Profile finding (glossy race scene, 2 threads, in some runs): 1.46 s of CPU
  // against 0.97 s on one thread, 90% of World::occluded's samples on one load from the
  // instance array, whose line the other thread's pending rays shared; with the block aligned,
  // 0.96 s in every run. (Aligning PendingRay itself did the same but cost the stack copies in
  // trace_tree a realigned frame: +0.7% instructions on the leave-out scene.)
  using PendingStack = std::vector<PendingRay, CacheLineAllocator<PendingRay>>;
  // The indices on the two sides of a transmissive surface, from the side the ray comes from.
  struct Interface {
    double n_from = 1.0, n_to = 1.0;
  };
  using TraceFn = Rgb (Integrator::*)(const Ray&, Path&) const;
  static TraceFn trace_for(unsigned mask);
  Rgb trace_path(const Ray& ray, Path& path) const;
  // The whole Whitted tree of one camera ray, compiled for feature set F.
  template <unsigned F>
  Rgb trace_tree(const Ray& ray, Path& path) const;
  static Interface interface(const MediumStack& media, uint32_t instance, const MaterialDesc& m,
                             bool entering);
  // The light a pending ray's hit sends back along it (emission, ambient, direct light); its
  // reflected and refracted rays go onto `pending`.
  template <unsigned F>
  Rgb shade(const PendingRay& pr, Path& path, PendingStack& pending) const;
  // The light a surface of material `m` at `hit` sends back along the pending ray (emission,
  // ambient, direct light), pushing its reflected and refracted rays with the pending ray's
  // weight past the fog (fog_t) and media (medium_t), times `layer` for a layer (kLayer).
  template <unsigned F, bool kLayer>
  [[gnu::always_inline]] inline Rgb surface(const PendingRay& pr, const WorldHit& hit, const MaterialDesc& m,
                                            double fog_t, const Rgb& medium_t, const Rgb& layer, Path& path,
                                            PendingStack& pending) const;
  // A layered material's layers, each lit by surface() and weighted by what the coats above
  // it let through (render/shade/layers.hpp).
  template <unsigned F>
  Rgb layers(const PendingRay& pr, const WorldHit& hit, const MaterialDesc& layered, double fog_t,
             const Rgb& medium_t, Path& path, PendingStack& pending) const;
  template <unsigned F>
  Rgb direct_light(const WorldHit& hit, const MaterialDesc& m, const Rgb& albedo, const Vec3& n,
                   const Vec3& shadow_origin, const Vec3& view, const MediumStack& media, Path& path) const;
  template <unsigned F>
  Rgb shadow_transmittance(const Vec3& origin, const LightSample& ls, const MediumStack& media, Path& path) const;
  // Media (only scenes with media, which take the generic path): what a ray segment of
  // `length` from `origin` along unit `dir` inside `medium` adds (emission, and single
  // scattering of the lights marched at settings.media_samples points), and its transmittance.
  Rgb medium_segment(const CompiledMedium& medium, const Vec3& origin, const Vec3& dir, double length,
                     const MediumStack& media, Path& path, Rgb& transmittance) const;
  // The lights' light scattered at `p` inside `medium` towards -dir.
  Rgb in_scattered(const CompiledMedium& medium, const Vec3& p, const Vec3& dir, const MediumStack& media,
                   Path& path) const;
  // The medium transmittance along a shadow ray through glass and pass-through surfaces.
  Rgb media_shadow(Ray ray, double end, const MediumStack& media) const;
  const CompiledMedium* medium_of(const MediumStack& media) const {
    const MediumId id = media.medium(atmosphere_);
    return id < media_->size() ? &(*media_)[id] : nullptr;
  }
  const MaterialDesc& material(uint32_t instance) const;
  // The hit's material; for a material chosen by pattern, the choice there (out of line: a
  // scene without one pays the test on choice_count alone; profile finding, callgrind on
  // bench/leave_out_a.rts: one out-of-line call per shaded hit was +1.4% of its instructions).
  [[gnu::always_inline]] const MaterialDesc& material(const WorldHit& hit) const {
    const MaterialId id = world_.instance(hit.instance).material;
    if (id >= materials_.size()) return default_material_;
    const MaterialDesc& m = materials_[id];
    return m.choice_count == 0 ? m : chosen_material(hit);
  }
  [[gnu::noinline]] const MaterialDesc& chosen_material(const WorldHit& hit) const;
  template <unsigned F = trace_flags::kAll>
  Rgb albedo(const MaterialDesc& m, const WorldHit& hit) const;
  // What a ray that leaves the scene sees: the environment map, else the background color.
  Rgb background(const Vec3& direction) const;

  const World& world_;
  // The lights shading visits: all of them (generic), or those that send light, each with the
  // sampler values the left-out lights before it would have drawn (so images stay the same).
  std::vector<CompiledLight> lights_;
  std::vector<uint32_t> skip_before_;
  uint32_t skip_after_ = 0;
  TraceFn trace_;
  const std::vector<MaterialDesc>& materials_;
  const std::vector<CompiledTexture>& textures_;
  MaterialDesc default_material_;
  Rgb background_, ambient_light_;
  const CompiledTexture* environment_ = nullptr;   // settings.environment, if any
  bool environment_ambient_ = false;
  // Fog, when settings.fog_distance > 0: one test per ray when there is none (a branch that
  // always goes the same way), and unfogged results bit for bit.
  bool fog_on_ = false;
  Fog fog_;
  Rgb fog_color_{0.0};
  Rgb fog_tint_{1.0};        // (1 - fog_filter) + fog_filter * fog_color
  bool fog_tinted_ = false;  // fog_filter > 0: generic path only
  // Media: off (one test per ray) unless a placed material or the settings have one.
  const std::vector<CompiledMedium>* media_ = nullptr;
  bool media_on_ = false;
  MediumId atmosphere_ = kNoId;
  int media_samples_ = 16;
  bool media_jitter_ = false;
  MediumStack camera_media_;
  // Some placed material lets light through unchanged (passes_through): checked per hit only then.
  bool has_pass_through_ = false;
  // Some placed material is layered: the generic path asks per hit only then.
  bool layers_on_ = false;
  int max_depth_;
  const path::PathIntegrator* path_tracer_ = nullptr;
};

}  // namespace rts::render
