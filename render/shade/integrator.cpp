#include "render/shade/integrator.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <cmath>
#include <limits>
#include <numbers>

#include "render/shade/layers.hpp"
#include "render/shade/material.hpp"
#include "render/shade/path/path_integrator.hpp"
#include "render/shade/shading.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {
namespace {

// Clamps overflowing radiance to a large finite value (NaN passes through, to be counted).
Rgb saturate(const Rgb& c) {
  auto sat = [](double v) { return v > tol::kMaxRadiance ? tol::kMaxRadiance : v; };
  return Rgb(sat(c.x), sat(c.y), sat(c.z));
}

}  // namespace

namespace {
// Where a shadow ray towards light sample `ls` stops (just short of the light).
double shadow_end(const LightSample& ls) {
  return std::isinf(ls.distance) ? Interval::kInfinity : ls.distance * (1.0 - tol::kShadowEndRelative);
}

// The region holding every shadow segment from `point` to area light `l`: the rays start at
// `origin` (the point's offset copy) along the direction from `point` to a light sample and
// stop short of it, so they lie in the pyramid from `origin` over the light's rectangle moved
// by origin - point (a disc light lies inside its rectangle).
ShadowRegion shadow_region(const CompiledLight& l, const Vec3& point, const Vec3& origin) {
  return shadow_pyramid(origin, l.position + (origin - point), l.u, l.v);
}

// The sampler values direct_light draws for one light: a permutation seed, and a 2D jitter
// per sample of an area light.
uint32_t sampler_values(const CompiledLight& l) {
  return 1 + (l.kind == LightKind::Area ? 2 * static_cast<uint32_t>(l.samples) : 0);
}
}  // namespace

Integrator::Integrator(const World& world, const std::vector<CompiledLight>& lights,
                       const std::vector<MaterialDesc>& materials,
                       const std::vector<CompiledTexture>& textures, const Settings& settings,
                       int max_depth, unsigned mask, const std::vector<CompiledMedium>* media)
    : world_(world), materials_(materials), textures_(textures),
      background_(to_rgb(settings.background)), ambient_light_(to_rgb(settings.ambient_light)),
      max_depth_(max_depth) {
  // Shadow rays through glass whose `transmit` is a texture need the hit point, which the
  // specialised one-pass crossing test does not keep: such scenes take the generic path.
  bool textured_transmit = false;
  // A placed material's ambient is a colour (emitted_and_ambient), or its reflection metallic.
  bool pov_finish_extras = false;
  static const std::vector<CompiledMedium> kNoMedia;
  media_ = media ? media : &kNoMedia;
  atmosphere_ = settings.medium < media_->size() ? settings.medium : kNoId;
  media_samples_ = std::max(1, settings.media_samples);
  media_on_ = atmosphere_ != kNoId;
  std::vector<bool> seen(materials.size(), false);  // each placed material once, not per instance
  for (std::size_t i = 0; i < world.instance_count(); ++i) {
    const MaterialId placed = world.instance(i).material;
    if (placed >= materials.size() || seen[placed]) continue;
    seen[placed] = true;
    // A material chosen by pattern transmits by the point, as a transmit texture does.
    const bool chosen = materials[placed].choice_count > 0;
    if (chosen && reaches_layers(materials, placed)) layers_on_ = true;
    for_each_material_choice(materials, placed, [&](MaterialId, const MaterialDesc& m) {
      if (m.transmit_texture != kNoId || (chosen && transmits(m))) textured_transmit = true;
      if (m.medium < media_->size() && transmits(m)) media_on_ = true;
      if (passes_through(m)) has_pass_through_ = true;
      if (!(m.ambient_color == Color(1.0)) || m.reflect_metallic > 0.0 || m.has_reflect_min) pov_finish_extras = true;
    });
  }
  // Media scenes, and scenes with surfaces light passes through unchanged, take the generic
  // path: shadow rays walk surface by surface to know which medium each stretch is in, and
  // the specialised paths carry none of this (leave-out: a scene without media pays nothing).
  bool generic = (mask & trace_flags::kGeneric) != 0 || textured_transmit || media_on_ || has_pass_through_ ||
                 layers_on_ || pov_finish_extras || settings.fog_filter > 0.0;
  uint32_t skipped = 0;
  for (const CompiledLight& l : lights) {
    // A light of power 0 adds nothing anywhere: leave it out, remembering what it would draw.
    if (!generic && l.power == Rgb(0.0)) {
      skipped += sampler_values(l);
      continue;
    }
    lights_.push_back(l);
    skip_before_.push_back(skipped);
    skipped = 0;
  }
  skip_after_ = skipped;
  trace_ = trace_for(generic ? (trace_flags::kGeneric | trace_flags::kAll) : (mask & trace_flags::kAll));
  if (settings.environment < textures.size()) {
    environment_ = &textures[settings.environment];
    environment_ambient_ = settings.environment_ambient;
  }
  if (settings.fog_distance > 0.0) {
    fog_on_ = true;
    fog_ = Fog::from(settings);
    fog_color_ = to_rgb(settings.fog_color);
    // POV-Ray's fog filter tints what the fog lets through: the generic path (scenes with it).
    fog_tint_ = Rgb(1.0 - settings.fog_filter) + settings.fog_filter * fog_color_;
    fog_tinted_ = settings.fog_filter > 0.0;
  }
}

Rgb Integrator::background(const Vec3& direction) const {
  return environment_ ? to_rgb(environment_->eval_direction(direction)) : background_;
}

Integrator::TraceFn Integrator::trace_for(unsigned mask) {
  static constexpr auto table = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<TraceFn, sizeof...(I)>{&Integrator::trace_tree<static_cast<unsigned>(I)>...};
  }(std::make_index_sequence<trace_flags::kAll + 1>{});
  if (mask & trace_flags::kGeneric) return &Integrator::trace_tree<trace_flags::kGeneric | trace_flags::kAll>;
  return table[mask & trace_flags::kAll];
}

void Integrator::use_path_tracer(const path::PathIntegrator* tracer) {
  path_tracer_ = tracer;
  if (tracer) trace_ = &Integrator::trace_path;
}

Rgb Integrator::trace_path(const Ray& ray, Path& path) const {
  return path_tracer_->trace(ray, path.sampler, path.counters);
}

const MaterialDesc& Integrator::material(uint32_t instance) const {
  MaterialId id = world_.instance(instance).material;
  return id < materials_.size() ? materials_[id] : default_material_;
}

const MaterialDesc& Integrator::chosen_material(const WorldHit& hit) const {
  const MaterialId id = surface_material_id(world_.instance(hit.instance).material, materials_, world_, hit, textures_);
  return id < materials_.size() ? materials_[id] : default_material_;
}

template <unsigned F>
Rgb Integrator::albedo(const MaterialDesc& m, const WorldHit& hit) const {
  if ((F & trace_flags::kTexture) && m.texture != kNoId && m.texture < textures_.size()) {
    return to_rgb(textures_[m.texture].eval(texture_point(world_, hit, textures_[m.texture])));
  }
  return to_rgb(m.color);
}

Rgb Integrator::trace(const Ray& ray, Sampler& sampler, RayCounters& counters) const {
  ++counters.camera;
  Path path{sampler, counters};
  // One indirect call per camera sample, always to the same target; everything inside is direct.
  return (this->*trace_)(ray, path);
}

template <unsigned F>
Rgb Integrator::trace_tree(const Ray& ray, Path& path) const {
  // The Whitted tree (a reflected and a refracted ray per transmissive hit) is walked with an
  // explicit stack, not recursion, so max_depth is limited by time (tol::kMaxDepth), never by
  // the worker threads' stacks. Popping the reflected ray before the refracted one visits the
  // nodes in the recursive order, so the sampler hands out the same numbers. The stack is
  // per thread and reused: no allocation per ray once it has grown.
  thread_local PendingStack pending;
  pending.clear();
  if constexpr (!(F & trace_flags::kSecondary)) {
    // Nothing reflects or transmits: the tree is the camera ray's hit alone.
    return shade<F>(PendingRay{ray, Rgb(1.0), 0, MediumStack{}}, path, pending);
  }
  // Only the generic path knows media (the others are never used with them).
  pending.push_back(PendingRay{ray, Rgb(1.0), 0, (F & trace_flags::kGeneric) ? camera_media_ : MediumStack{}});
  Rgb color(0.0);
  while (!pending.empty()) {
    PendingRay pr = pending.back();
    pending.pop_back();
    color += pr.weight * shade<F>(pr, path, pending);
  }
  return color;
}

FirstHit Integrator::first_hit(const Ray& ray) const {
  FirstHit out;
  WorldHit hit;
  if (!world_.intersect(ray, Interval::positive(), hit)) return out;
  out.hit = true;
  out.normal = hit.shading_normal;
  out.depth = hit.t * glm::length(ray.direction);
  out.bounded = world_.instance(hit.instance).kind != kPrimKind<Plane>;
  MaterialScratch scratch;   // vertex colors are the albedo too
  out.albedo = albedo(shading_material(material(hit), world_, hit, textures_, scratch), hit);
  return out;
}

template <unsigned F>
Rgb Integrator::shadow_transmittance(const Vec3& origin, const LightSample& ls, const MediumStack& media,
                                     Path& path) const {
  ++path.counters.shadow;
  Ray ray{origin, ls.direction};
  double end = shadow_end(ls);
  if constexpr (!(F & trace_flags::kTransmissiveShadows)) {
    // Nothing lets light through.
    return world_.occluded(ray, Interval(0.0, end)) ? Rgb(0.0) : Rgb(1.0);
  } else if constexpr (!(F & trace_flags::kGeneric)) {
    // One traversal: stops at the first opaque hit, else collects the glass crossed, which is
    // multiplied through in order along the ray (the same product as the closest-hit walk).
    ShadowCrossings crossed;
    if (world_.shadow_crossings(ray, Interval(0.0, end), crossed)) return Rgb(0.0);
    for (int i = 1; i < crossed.count; ++i)  // insertion sort: a handful of crossings
      for (int k = i; k > 0 && crossed.t[k] < crossed.t[k - 1]; --k) {
        std::swap(crossed.t[k], crossed.t[k - 1]);
        std::swap(crossed.instance[k], crossed.instance[k - 1]);
      }
    Rgb t(1.0);
    for (int i = 0; i < crossed.count; ++i) {
      t *= glm::clamp(to_rgb(material(crossed.instance[i]).transmit), 0.0, 1.0);
      if (max_channel(t) < tol::kMinPathWeight) return Rgb(0.0);
    }
    return t;
  }
  // Any opaque occluder blocks the light whatever else lies on the segment: test those first
  // with an early-exit traversal.
  if (world_.occluded(ray, Interval(0.0, end), /*opaque_only=*/true)) return Rgb(0.0);
  if (media_on_) return media_shadow(ray, end, media);
  if (!world_.has_transmissive()) return Rgb(1.0);
  // Only transmissive surfaces remain: multiply through each one up to the light, restarting
  // just beyond each surface (offset by its own error bound, like any spawned ray).
  Rgb t(1.0);
  for (int i = 0; i < tol::kMaxShadowSurfaces; ++i) {
    WorldHit hit;
    if (!world_.intersect(ray, Interval(0.0, end), hit, /*transmissive_only=*/true, /*shadow_ray=*/true)) return t;
    MaterialScratch scratch;
    Rgb kt = to_rgb(shading_material(material(hit), world_, hit, textures_, scratch).transmit);
    t *= glm::clamp(kt, 0.0, 1.0);
    if (max_channel(t) < tol::kMinPathWeight) return Rgb(0.0);
    Vec3 next = offset_ray_origin(hit.point, hit.normal, ls.direction, hit.error);
    end -= glm::dot(next - ray.origin, ls.direction);
    ray.origin = next;
  }
  return Rgb(0.0);
}

template <unsigned F>
Rgb Integrator::direct_light(const WorldHit& hit, const MaterialDesc& m, const Rgb& albedo,
                             const Vec3& n, const Vec3& shadow_origin, const Vec3& view,
                             const MediumStack& media, Path& path) const {
  Sampler& sampler = path.sampler;
  Rgb sum(0.0);
  // Without kRandom no light is an area light and nothing later draws from the sampler: one
  // sample per light, no permutation seed, no jitter.
  constexpr bool kRandom = (F & trace_flags::kRandom) != 0;
  for (std::size_t k = 0; k < lights_.size(); ++k) {
    const CompiledLight& light = lights_[k];
    if constexpr (kRandom) sampler.skip(skip_before_[k]);
    uint32_t perm = kRandom ? sampler.next_bits() : 0;
    bool area = kRandom && light.kind == LightKind::Area;
    int samples = kRandom ? light.samples : 1;
    uint32_t col = 0, row = 0;  // the grid stratum of sample j, stepped without dividing
    // Opaque shadows from an area light: the objects that can block any of this point's
    // samples, found once (World::occluder_candidates); each shadow ray tests only those.
    OccluderCandidates candidates;
    bool culled = false;
    if constexpr (!(F & trace_flags::kTransmissiveShadows)) {
      if (area && samples > 1 && light.shadows)
        culled = world_.occluder_candidates(shadow_region(light, hit.point, shadow_origin), candidates);
    }
    // Light samples are drawn and placed a batch at a time, then shaded in the same order:
    // nothing in between draws from the sampler, so the numbers and the sum are unchanged,
    // while the batch's square roots and divisions (sample_light's, ~20% of the soft-shadow
    // race scene) overlap instead of waiting behind each shadow ray's branches.
    constexpr int kBatch = 16;
    // Left uninitialised (each slot is written before it is read): value-initialising the 16
    // samples was an 896-byte `rep stos` per light per shaded point, whatever the light's
    // sample count (profile finding: 9% of shade<> on the glossy race scene, two point lights).
    union Slot {
      Slot() {}
      LightSample sample;
    } batch[kBatch];
    for (int j0 = 0; j0 < samples; j0 += kBatch) {
      const int count = std::min(kBatch, samples - j0);
      for (int b = 0; b < count; ++b) {
        glm::dvec2 on_light(0.5);
        if (area) {
          glm::dvec2 jitter = sampler.next2();
          if (light.strata_side > 0) {
            on_light = (glm::dvec2(col, row) + jitter) * light.inv_strata;
            if (++col == light.strata_side) col = 0, ++row;
          } else {
            on_light = stratified_2d(static_cast<uint32_t>(j0 + b), static_cast<uint32_t>(light.samples), 0,
                                     jitter, perm);
          }
        }
        batch[b].sample = sample_light(light, hit.point, on_light);
      }
      for (int b = 0; b < count; ++b) {
        const LightSample& ls = batch[b].sample;
        double n_dot_l = glm::dot(n, ls.direction);
        if (n_dot_l <= 0.0 || is_black(ls.radiance)) continue;
        Rgb shade = phong<(F & trace_flags::kSpecular) != 0>(m, albedo, n, ls.direction, n_dot_l, view);
        if (is_black(shade)) continue;
        Rgb transmittance(1.0);
        if (culled) {
          ++path.counters.shadow;
          if (world_.occluded_by(candidates, Ray{shadow_origin, ls.direction}, Interval(0.0, shadow_end(ls))))
            transmittance = Rgb(0.0);
        } else if (light.shadows) {
          transmittance = shadow_transmittance<F>(shadow_origin, ls, media, path);
        }
        sum += shade * ls.radiance * transmittance;
      }
    }
  }
  if constexpr (kRandom) sampler.skip(skip_after_);
  return sum;
}

Integrator::Interface Integrator::interface(const MediumStack& media, uint32_t instance,
                                             const MaterialDesc& m, bool entering) {
  // `ior` is absolute (the medium inside the object) unless `ior_relative` says it is the
  // ratio to the medium around the object (the pre-medium-stack idiom `ior = 1/1.5`).
  Interface f;
  media.interface(instance, m, entering, f.n_from, f.n_to);
  return f;
}

template <unsigned F>
Rgb Integrator::shade(const PendingRay& pr, Path& path, PendingStack& pending) const {
  const Ray& ray = pr.ray;
  // One hit record per thread, reused: a fresh WorldHit's default member initialisers are a
  // 216-byte `rep stos` on every shaded ray (profile finding: see MaterialScratch). Safe because
  // shade is never re-entered and World::intersect writes every field of a hit it returns
  // (tests/render/test_instancing.cpp checks it); a miss reads nothing from it.
  thread_local WorldHit hit;
  const bool found = world_.intersect(ray, Interval::positive(), hit);
  // A medium on the way: what it adds along the segment, and what it lets through (with no
  // media, one test and the results bit for bit).
  Rgb medium_in(0.0), medium_t(1.0);
  constexpr bool kMedia = (F & trace_flags::kGeneric) != 0;
  const CompiledMedium* medium = kMedia && media_on_ ? medium_of(pr.media) : nullptr;
  if (medium) {
    const double len = glm::length(ray.direction);
    medium_in = medium_segment(*medium, ray.origin, ray.direction / len,
                               found ? hit.t * len : std::numeric_limits<double>::infinity(), pr.media, path,
                               medium_t);
  }
  auto through_medium = [&](const Rgb& c) {
    if constexpr (kMedia) return medium ? saturate(medium_in + medium_t * c) : c;
    return c;
  };
  if (!found) {
    const Rgb c = through_medium(background(ray.direction));
    if (!fog_on_) return c;
    double t = fog_.transmittance(ray.origin, ray.direction, std::numeric_limits<double>::infinity());
    if constexpr (kMedia)
      if (fog_tinted_) return t * (fog_tint_ * c) + (1.0 - t) * fog_color_;  // POV-Ray's fog filter
    return t * c + (1.0 - t) * fog_color_;
  }
  // What the fog between the ray's origin and the hit leaves of the light from the hit (1: no
  // fog); the rest of the segment's light is the fog's colour.
  const double fog_t = fog_on_ ? fog_.transmittance(ray.origin, ray.direction, hit.t) : 1.0;
  auto fogged = [&](const Rgb& c) {
    const Rgb seen = through_medium(c);
    if constexpr (kMedia)
      if (fog_tinted_) return fog_t * (fog_tint_ * seen) + (1.0 - fog_t) * fog_color_;  // POV-Ray's fog filter
    return fog_on_ ? fog_t * seen + (1.0 - fog_t) * fog_color_ : seen;
  };
  if constexpr (kMedia) {
    // Layered materials (only scenes with one, which take the generic path): each layer lit.
    if (layers_on_) {
      const MaterialId layered = layered_at(world_.instance(hit.instance).material, materials_, world_, hit, textures_);
      if (layered != kNoId) return fogged(layers<F>(pr, hit, materials_[layered], fog_t, medium_t, path, pending));
    }
  }
  MaterialScratch scratch;
  const MaterialDesc& m = shading_material(material(hit), world_, hit, textures_, scratch);
  if (kMedia && has_pass_through_ && passes_through(m)) {
    const Vec3 incident = glm::normalize(ray.direction);
    const bool into = glm::dot(hit.normal, incident) < 0.0;
    MediumStack beyond = pr.media;
    if (beyond.cross_clear(hit.medium, m, into)) {
      // Not there for the light: the ray goes on from the far side, in the medium beyond.
      if (pr.passes < tol::kMaxPassThrough)
        pending.push_back(PendingRay{Ray{offset_ray_origin(hit.point, into ? -hit.normal : hit.normal, incident,
                                                           hit.error),
                                         ray.direction},
                                     saturate(pr.weight * fog_t * medium_t), pr.depth, beyond, pr.passes + 1});
      return fogged(Rgb(0.0));
    }
  }
  return fogged(surface<F, false>(pr, hit, m, fog_t, medium_t, Rgb(1.0), path, pending));
}

template <unsigned F>
Rgb Integrator::layers(const PendingRay& pr, const WorldHit& hit, const MaterialDesc& layered, double fog_t,
                       const Rgb& medium_t, Path& path, PendingStack& pending) const {
  // From the top coat down, each layer lit as a material of its own and weighted by what the
  // coats above it let through (POV-Ray's layered textures); its reflected rays carry the same
  // weight. The base is an ordinary material: what it transmits enters the object.
  Rgb sum(0.0), left(1.0);
  for (uint32_t k = layered.choice_count; k-- > 0;) {
    const MaterialId id = surface_material_id(layered.first_choice + k, materials_, world_, hit, textures_);
    const MaterialDesc& layer = id < materials_.size() ? materials_[id] : default_material_;
    MaterialScratch scratch;
    if (k == 0) {
      sum += left * surface<F, true>(pr, hit, shading_material(layer, world_, hit, textures_, scratch), fog_t,
                                     medium_t, left, path, pending);
      break;
    }
    Rgb through;
    const MaterialDesc& coat = coat_at(layer, world_, hit, textures_, scratch, through);
    sum += left * surface<F, true>(pr, hit, coat, fog_t, medium_t, left, path, pending);
    left *= through;
    if (!(max_channel(left) > tol::kMinPathWeight)) break;  // nothing below shows
  }
  return saturate(sum);
}

template <unsigned F, bool kLayer>
Rgb Integrator::surface(const PendingRay& pr, const WorldHit& hit, const MaterialDesc& m, double fog_t,
                        const Rgb& medium_t, const Rgb& layer, Path& path, PendingStack& pending) const {
  const Ray& ray = pr.ray;
  constexpr bool kMedia = (F & trace_flags::kGeneric) != 0;
  Vec3 incident = glm::normalize(ray.direction);

  // The geometric normal decides the side: face it towards the incoming ray (leaving a solid
  // = hitting its back side). The shading normal is then put into the same hemisphere as the
  // faced geometric normal on its own, so vertex normals that disagree with the triangle's
  // winding (common in OBJ files and hand-written meshes) shade the same as consistent ones.
  Vec3 ng = hit.normal, n = hit.shading_normal;
  bool entering = glm::dot(ng, incident) < 0.0;
  if (!entering) ng = -ng;
  if (glm::dot(n, ng) < 0.0) n = -n;
  n = detail_normal(m, world_, hit, n, textures_);
  Vec3 view = -incident;
  Rgb base = albedo<F>(m, hit);
  Rgb ambient = environment_ambient_ ? ambient_light_ * background(n) : ambient_light_;
  Rgb color = emitted_and_ambient<kMedia>(m, base, ambient);
  Vec3 front_origin = offset_ray_origin(hit.point, ng, ng, hit.error);
  color += direct_light<F>(hit, m, diffuse_color(m, base, world_, hit, textures_), n, front_origin, view, pr.media,
                           path);
  color = saturate(color);

  if constexpr (!(F & trace_flags::kSecondary)) return color;  // nothing reflects or transmits
  if (pr.depth >= max_depth_) return color;
  // The light the secondary rays bring back crosses the same fog (x * 1.0 is exact: without
  // fog the weights are unchanged), and for a layer, its share.
  Rgb weight = kMedia ? pr.weight * fog_t * medium_t : pr.weight * fog_t;
  if constexpr (kLayer) weight *= layer;
  if constexpr (kMedia)
    if (fog_tinted_) weight *= fog_tint_;

  double cos_i = std::clamp(glm::dot(n, view), 0.0, 1.0);
  Interface f;
  if (!is_black(to_rgb(m.transmit))) f = interface(pr.media, hit.medium, m, entering);
  SpecularWeights w = specular_weights(m, incident, n, cos_i, f.n_from, f.n_to);
  if constexpr (kMedia) {
    // POV-Ray's reflection { min, max } (only scenes with it, which take the generic path).
    // Total internal reflection (a transmitting surface that refracts nothing) stays a mirror.
    // With fresnel the interface splits its budget as specular_weights does: what reflects does
    // not pass (POV-Ray's conserve_energy, which its glass finishes write).
    const bool transmits = !is_black(to_rgb(m.transmit));
    if (m.has_reflect_min && !(transmits && is_black(w.transmit))) {
      w.reflect = variable_reflection(m, cos_i, transmits ? f.n_to / f.n_from : m.ior);
      if (transmits && m.fresnel) w.transmit = to_rgb(m.transmit) * glm::max(Rgb(0.0), Rgb(1.0) - w.reflect);
    }
  }
  const Rgb &kr = w.reflect, &kt = w.transmit;
  const Vec3& refracted = w.refracted;

  // Pushed refracted first so the reflected subtree is walked first (see trace()). Weights
  // saturate so colors above 1 reflected thousands of times stay finite.
  if (max_channel(kt * weight) > tol::kMinPathWeight) {
    ++path.counters.refraction;
    Ray r{offset_ray_origin(hit.point, ng, refracted, hit.error), refracted};
    pending.push_back(PendingRay{r, saturate(weight * kt), pr.depth + 1, pr.media, pr.passes});
    // The refracted ray is inside the object now, or has left it.
    if (entering)
      pending.back().media.enter(hit.medium, f.n_to, m.medium);
    else
      pending.back().media.leave(hit.medium);
  }
  if (max_channel(kr * weight) > tol::kMinPathWeight) {
    Vec3 dir = reflected_direction(m, incident + 2.0 * cos_i * n, ng, path.sampler);
    ++path.counters.reflection;
    Ray r{offset_ray_origin(hit.point, ng, dir, hit.error), dir};
    // POV-Ray's reflection { metallic } (only scenes with it, which take the generic path).
    Rgb reflected = weight * kr;
    if constexpr (kMedia)
      if (m.reflect_metallic > 0.0) reflected *= metallic_reflection(m, base, cos_i);
    pending.push_back(PendingRay{r, saturate(reflected), pr.depth + 1, pr.media, pr.passes});
  }
  return color;
}

// ---- media ----------------------------------------------------------------------------------

Rgb Integrator::in_scattered(const CompiledMedium& medium, const Vec3& p, const Vec3& dir, const MediumStack& media,
                             Path& path) const {
  // One light sample per light at each marched point (an area light's centre, or a random
  // point of it when the render samples): the march's points together cover the light.
  Rgb sum(0.0);
  for (const CompiledLight& light : lights_) {
    const bool area = light.kind == LightKind::Area;
    const glm::dvec2 on_light = area && media_jitter_ ? path.sampler.next2() : glm::dvec2(0.5);
    LightSample ls = sample_light(light, p, on_light);
    if (is_black(ls.radiance)) continue;
    if (area) ls.radiance *= static_cast<double>(light.samples);  // one sample stands for all
    Rgb tr(1.0);
    if (light.shadows) {
      ++path.counters.shadow;
      const double end = shadow_end(ls);
      Ray ray{p, ls.direction};
      if (world_.occluded(ray, Interval(0.0, end), /*opaque_only=*/true)) continue;
      tr = media_shadow(ray, end, media);
    }
    sum += hg_phase(glm::dot(dir, ls.direction), medium.eccentricity()) * ls.radiance * tr;
  }
  return sum;
}

Rgb Integrator::medium_segment(const CompiledMedium& medium, const Vec3& origin, const Vec3& dir, double length,
                               const MediumStack& media, Path& path, Rgb& transmittance) const {
  const int n = media_samples_;
  const bool scatter = medium.scatters() && !lights_.empty();
  // A render that samples anyway jitters the marched points (one value per segment); a
  // deterministic one takes the midpoints of the strata, as POV-Ray's media do.
  const double jitter = media_jitter_ && (scatter || !medium.homogeneous()) ? path.sampler.next() : 0.5;
  Rgb in(0.0);
  if (medium.homogeneous()) {
    transmittance = medium.transmittance(length);
    if (medium.emits()) in += medium.emitted(length);
    if (!scatter) return in;
    // Single scattering: the points are placed by the transmittance of the channel that
    // fades slowest (exponential spacing: an infinite segment is covered too), each channel
    // weighed by its own transmittance against it.
    double sig = 0.0;
    for (int c = 0; c < 3; ++c)
      if (medium.sigma_t()[c] > 0.0 && (sig == 0.0 || medium.sigma_t()[c] < sig)) sig = medium.sigma_t()[c];
    if (!(sig > 0.0)) return in;  // unreachable: sigma_t >= sigma_s > 0
    const double span = -std::expm1(-sig * length);  // 1 for an infinite segment
    for (int i = 0; i < n; ++i) {
      const double u = (i + jitter) / n;
      const double s = -std::log1p(-u * span) / sig;
      Rgb w;
      for (int c = 0; c < 3; ++c) w[c] = std::exp(-(medium.sigma_t()[c] - sig) * s) * span / (sig * n);
      in += w * medium.sigma_s() * in_scattered(medium, origin + s * dir, dir, media, path);
    }
    return in;
  }
  // Heterogeneous: the midpoint rule over [0, reach], the optical depth summed on the way.
  const double majorant = medium.majorant();
  const double reach =
      majorant > 0.0 ? std::min(length, tol::kMediaMarchDepth / majorant) : (std::isinf(length) ? 0.0 : length);
  const double ds = reach / n;
  double depth = 0.0;  // density times length so far
  for (int i = 0; i < n; ++i) {
    const Vec3 p = origin + (i + jitter) * ds * dir;
    const double rho = medium.density(p);
    if (rho > 0.0) {
      Rgb tr;
      for (int c = 0; c < 3; ++c) tr[c] = std::exp(-medium.sigma_t()[c] * (depth + rho * jitter * ds));
      Rgb source = medium.emission();
      if (scatter) source += medium.sigma_s() * in_scattered(medium, p, dir, media, path);
      in += tr * (rho * ds) * source;
    }
    depth += rho * ds;
  }
  for (int c = 0; c < 3; ++c) transmittance[c] = std::exp(-medium.sigma_t()[c] * depth);
  return in;
}

Rgb Integrator::media_shadow(Ray ray, double end, const MediumStack& media) const {
  // Opaque blockers are already excluded: walk the glass and pass-through surfaces in order,
  // each stretch between them in the medium the stack says, filtered by each surface.
  MediumStack stack = media;
  const double len = glm::length(ray.direction);
  const Vec3 dir = ray.direction / len;
  Rgb t(1.0);
  for (int i = 0; i < tol::kMaxShadowSurfaces; ++i) {
    WorldHit hit;
    const bool found = world_.intersect(ray, Interval(0.0, end), hit, /*transmissive_only=*/true, /*shadow_ray=*/true);
    if (const CompiledMedium* medium = medium_of(stack))
      t *= medium->transmittance_marched(ray.origin, dir, (found ? hit.t : end) * len, media_samples_,
                                         /*shadow=*/true);
    if (!found) return t;
    MaterialScratch scratch;
    const MaterialDesc& m = shading_material(material(hit), world_, hit, textures_, scratch);
    t *= glm::clamp(to_rgb(m.transmit), 0.0, 1.0);
    if (max_channel(t) < tol::kMinPathWeight) return Rgb(0.0);
    if (glm::dot(hit.normal, dir) < 0.0)
      stack.enter(hit.medium, 1.0, m.medium);
    else
      stack.leave(hit.medium);
    Vec3 next = offset_ray_origin(hit.point, hit.normal, dir, hit.error);
    end -= glm::dot(next - ray.origin, ray.direction) / (len * len);
    ray.origin = next;
  }
  return Rgb(0.0);
}

}  // namespace rts::render
