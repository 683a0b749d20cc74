#include "render/shade/path/path_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "render/geometry/tolerances.hpp"
#include "render/shade/medium_stack.hpp"
#include "render/shade/material.hpp"
#include "render/shade/layers.hpp"
#include "render/shade/shading.hpp"

namespace rts::render::path {
namespace {

// to_rgb, max_channel and is_black are material.hpp's.
Rgb unit_clamp(const Rgb& c) { return glm::clamp(c, 0.0, 1.0); }
bool finite(const Rgb& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }

// Phong exponent to GGX roughness: alpha = sqrt(2 / (n + 2)) matches the Phong lobe's width
// (Walter et al. 2007, via Beckmann); shininess 32 gives 0.24, 1000 gives 0.045.
double shininess_alpha(double shininess) { return std::sqrt(2.0 / (std::max(shininess, 0.0) + 2.0)); }

// The most a material's weights send back per channel (textures count as 1): Lambert albedo,
// the glossy and the specular lobes (a dielectric splits max(reflect, transmit) between its
// reflection and transmission).
double reflected_fraction(const MaterialDesc& m) {
  Rgb color = m.texture != kNoId || m.diffuse_texture != kNoId ? Rgb(1.0) : unit_clamp(to_rgb(m.color));
  Rgb spec = m.specular_texture != kNoId ? Rgb(1.0) : to_rgb(m.specular_color);
  Rgb r = m.reflect_texture != kNoId ? Rgb(1.0) : to_rgb(m.reflect);
  Rgb t = m.transmit_texture != kNoId ? Rgb(1.0) : to_rgb(m.transmit);
  Rgb sum = std::max(m.diffuse, 0.0) * color + std::max(m.specular, 0.0) * glm::max(spec, 0.0) +
            (max_channel(t) > 0.0 ? glm::max(glm::max(r, t), 0.0) : glm::max(r, 0.0));
  return max_channel(sum);
}

// Where a shadow ray from `origin` (the offset copy of `point`) towards light sample `ls`
// stops: short of the emitter's own surface, whose hit from there rounds like any point at
// that distance. The offset moves the origin towards the light by up to 16 of the point's
// rounding bounds (offset_ray_origin), about 1e-14 of its distance from the world origin:
// measured from `point`, the end lay beyond the emitter once that exceeded the relative
// margin (a lamp 2 units above a floor 1e6 from the origin shadowed the floor it lit).
double shadow_end(const Vec3& point, const Vec3& origin, const LightSample& ls) {
  if (std::isinf(ls.distance)) return Interval::kInfinity;
  const double from_origin = ls.distance - glm::dot(origin - point, ls.wi);
  return from_origin * (1.0 - tol::kShadowEndRelative) -
         tol::kOffsetErrorScale * ray_point_error(Ray{origin, ls.wi}, from_origin);
}

}  // namespace

PathIntegrator::PathIntegrator(const World& world, const SceneDesc& scene, const std::vector<CompiledLight>& lights,
                               const std::vector<CompiledTexture>& textures, const std::vector<CompiledMedium>& media,
                               int max_depth, std::vector<Warning>& warnings)
    : world_(world), materials_(scene.materials), textures_(textures),
      lights_(world, scene, lights, textures), max_depth_(max_depth), clamp_(scene.settings.clamp), media_(media) {
  atmosphere_ = scene.settings.medium < media.size() ? scene.settings.medium : kNoId;
  if (scene.settings.fog_distance > 0.0) {
    fog_on_ = true;
    fog_ = Fog::from(scene.settings);
    fog_color_ = to_rgb(scene.settings.fog_color);
  }
  has_media_ = atmosphere_ != kNoId;
  std::vector<bool> placed(scene.materials.size(), false), on_instance(scene.materials.size(), false);
  for (std::size_t i = 0; i < world.instance_count(); ++i)
    if (world.instance(i).material < on_instance.size()) on_instance[world.instance(i).material] = true;
  for (std::size_t id = 0; id < on_instance.size(); ++id)  // each once; a material chosen by pattern: its choices
    if (on_instance[id]) {
      if (reaches_layers(scene.materials, static_cast<MaterialId>(id))) has_layers_ = true;
      for_each_material_choice(scene.materials, static_cast<MaterialId>(id),
                               [&](MaterialId c, const MaterialDesc&) { placed[c] = true; });
    }
  // A layered material's coats: what they transmit shows the layers below, so it is no
  // part of the light they reflect (render/shade/layers.hpp).
  std::vector<bool> coat(scene.materials.size(), false);
  for (const MaterialDesc& m : scene.materials)
    if (m.layered)
      for (uint32_t k = 1; k < m.choice_count && m.first_choice + k < coat.size(); ++k) coat[m.first_choice + k] = true;
  scale_.assign(scene.materials.size(), 1.0);
  for (std::size_t id = 0; id < scene.materials.size(); ++id) {
    if (!placed[id]) continue;
    MaterialDesc as_coat;
    if (coat[id]) {
      as_coat = scene.materials[id];
      as_coat.transmit = Color(0.0);
      as_coat.transmit_texture = kNoId;
    }
    const MaterialDesc& m = coat[id] ? as_coat : scene.materials[id];
    if (transmits(m)) {
      has_transmission_ = true;
      if (m.medium < media.size()) has_media_ = true;
    }
    if (passes_through(m)) has_pass_through_ = true;
    if (m.specular > 0.0 || m.roughness > 0.0) has_microfacets_ = true;
    double sum = reflected_fraction(m);
    if (sum > 1.0 + 1e-9) {
      scale_[id] = 1.0 / sum;
      warnings.push_back({m.loc, fmt::format("in path mode this material would reflect {:.3g} times the light it "
                                             "receives (diffuse x color + specular + reflect/transmit): its weights "
                                             "are scaled by {:.3g}",
                                             sum, 1.0 / sum)});
    }
  }
}

void PathIntegrator::describe(std::vector<std::string>& used, std::vector<std::string>& left_out) const {
  auto report = [&](bool on, const char* name) { (on ? used : left_out).emplace_back(name); };
  report(!lights_.empty(), "next_event_estimation");
  report(lights_.has_shape_emitters() || lights_.has_sky(), "mis");
  report(lights_.has_shape_emitters(), "emissive_shapes");
  report(lights_.has_delta_lights(), "delta_lights");
  report(lights_.has_area_lights(), "area_lights");
  report(lights_.has_sky(), "sky_light");
  report(has_transmission_, "dielectric_medium_stack");
  report(has_microfacets_, "microfacet_lobes");
  report(has_media_, "media");
  report(fog_on_, "fog");
  report(has_pass_through_, "pass_through_surfaces");
  report(has_layers_, "layered_materials");
  report(max_depth_ >= kRouletteStart, "russian_roulette");
  report(clamp_ > 0.0, "clamp");
}

Lobes PathIntegrator::lobes(const MaterialDesc& m, uint32_t material_id, const WorldHit& hit) const {
  Rgb albedo = to_rgb(m.color);
  if (m.texture != kNoId && m.texture < textures_.size())
    albedo = to_rgb(textures_[m.texture].eval(texture_point(world_, hit, textures_[m.texture])));
  double s = material_id < scale_.size() ? scale_[material_id] : 1.0;
  Lobes lb;
  lb.diffuse = s * std::max(m.diffuse, 0.0) * unit_clamp(diffuse_color(m, albedo, world_, hit, textures_));
  lb.glossy = s * std::max(m.specular, 0.0) * unit_clamp(to_rgb(m.specular_color));
  lb.glossy_alpha = shininess_alpha(m.shininess);
  lb.reflect = s * unit_clamp(to_rgb(m.reflect));
  lb.reflect_alpha = std::clamp(m.roughness, 0.0, 1.0);
  lb.transmit = s * unit_clamp(to_rgb(m.transmit));
  lb.transmit_alpha = lb.reflect_alpha;  // rough glass refracts through the facets it reflects from
  lb.fresnel = m.fresnel;
  return lb;
}

const MaterialDesc& PathIntegrator::surface_material(uint32_t& id, const WorldHit& hit) const {
  id = surface_material_id(id, materials_, world_, hit, textures_);
  return id < materials_.size() ? materials_[id] : default_material_;
}

const MaterialDesc& PathIntegrator::material(const WorldHit& hit) const {
  const uint32_t id = surface_material_id(world_.instance(hit.instance).material, materials_, world_, hit, textures_);
  return id < materials_.size() ? materials_[id] : default_material_;
}

Rgb PathIntegrator::shadow(const Vec3& origin, const Vec3& dir, double end, const MediumStack& media,
                           Sampler& sampler) const {
  if (!has_media_ && !has_pass_through_) return world_.occluded(Ray{origin, dir}, Interval(0.0, end)) ? Rgb(0.0) : Rgb(1.0);
  // One sampler value seeds the ratio tracking of every heterogeneous stretch on the way.
  MediumRng rng(sampler.next());
  MediumStack stack = media;
  Ray ray{origin, dir};
  Rgb t(1.0);
  for (int i = 0; i <= tol::kMaxPassThrough; ++i) {
    WorldHit hit;
    const bool found = world_.intersect(ray, Interval(0.0, end), hit, /*transmissive_only=*/false, /*shadow_ray=*/true);
    if (const CompiledMedium* medium = medium_of(stack))
      t *= medium->transmittance(ray.origin, dir, found ? hit.t : end, rng);
    if (!found) return t;
    const MaterialDesc& m = material(hit);
    const bool into = glm::dot(hit.normal, dir) < 0.0;
    if (!(max_channel(t) > 0.0) || !stack.cross_clear(hit.medium, m, into)) return Rgb(0.0);
    const Vec3 next = offset_ray_origin(hit.point, into ? -hit.normal : hit.normal, dir, hit.error);
    end -= glm::dot(next - ray.origin, dir);
    ray.origin = next;
  }
  return Rgb(0.0);
}

template <class Response, class Pdf>
Rgb PathIntegrator::light_sample(const Vec3& point, const Vec3& ng, double error, const MediumStack& media, double u_pick,
                                 glm::dvec2 u_light, Sampler& sampler, RayCounters& counters, Response&& response,
                                 Pdf&& scatter_pdf) const {
  LightSample ls;
  if (!lights_.sample(point, u_pick, u_light, ls) || is_black(ls.radiance)) return Rgb(0.0);
  const Rgb f = response(ls.wi);
  if (is_black(f)) return Rgb(0.0);
  ++counters.shadow;
  const Vec3 origin = offset_ray_origin(point, ng, ls.wi, error);
  const double end = shadow_end(point, origin, ls);
  Rgb tr = shadow(origin, ls.wi, end, media, sampler);
  if (fog_on_) tr *= fog_.transmittance(origin, ls.wi, end);
  if (is_black(tr)) return Rgb(0.0);
  const double w = ls.delta ? 1.0 : power_heuristic(ls.pdf, scatter_pdf(ls.wi));
  const Rgb c = f * tr * ls.radiance * (w / ls.pdf);
  return finite(c) ? c : Rgb(0.0);
}

Rgb PathIntegrator::trace(const Ray& camera_ray, Sampler& sampler, RayCounters& counters) const {
  Rgb radiance(0.0), beta(1.0);
  // The product of the (n_from / n_to)^2 factors refraction put into beta: Russian roulette
  // looks at beta without them, so a path inside glass, whose radiance is only compressed, is
  // not ended more often than one outside (pbrt-v4's etaScale).
  double eta_scale = 1.0;
  Ray ray = camera_ray;
  bool specular = true;   // the last vertex was the camera or a delta lobe: no MIS for what it finds
  double prev_pdf = 0.0;  // the density that chose the current ray (solid angle): BSDF or phase
  Vec3 prev_point(0.0);
  MediumStack media = camera_media_;
  int passes = 0;  // pass-through surfaces crossed (they are not bounces)
  for (int bounce = 0;; ++bounce) {
    Vec3 dir = glm::normalize(ray.direction);
    WorldHit hit;
    const bool found = world_.intersect(ray, Interval::positive(), hit);

    // Fog over a segment of length t (in units of `d`): what it leaves of the light behind it,
    // and its own colour for the rest.
    auto fog_segment = [&](const Vec3& d, double t) {
      const double tr = fog_.transmittance(ray.origin, d, t);
      radiance += beta * ((1.0 - tr) * fog_color_);
      beta *= tr;
    };
    bool fogged = false;
    // A medium on the way: emission found, survival, or a scattering event inside it (the
    // free flight draws from its own stream, seeded by one sampler value per segment).
    if (has_media_) {
      const double u_seed = sampler.next();
      if (const CompiledMedium* medium = medium_of(media)) {
        const double len = glm::length(ray.direction);
        double t = 0.0;
        MediumRng rng(u_seed);
        const bool scattered = medium->free_flight(ray.origin, dir, found ? hit.t * len : Interval::kInfinity, rng,
                                                   beta, radiance, t);
        if (fog_on_ && scattered) {
          fog_segment(dir, t);
          fogged = true;
        }
        if (!finite(beta) || is_black(beta)) break;
        if (scattered) {
          if (bounce > max_depth_) break;
          const Vec3 p = ray.origin + t * dir;
          const double g = medium->eccentricity();
          // The same sampler dimensions as a surface vertex: light pick, light point, (lobe
          // choice: unused here), direction, roulette.
          const double u_pick = !lights_.single() ? sampler.next() : (sampler.skip(1), 0.0);
          const glm::dvec2 u_light = sampler.next2();
          sampler.skip(1);
          const glm::dvec2 u_dir = sampler.next2();
          const bool roulette = bounce + 1 >= kRouletteStart;
          const double u_roulette = roulette ? sampler.next() : (sampler.skip(1), 0.0);
          if (!lights_.empty()) {
            auto phase = [&](const Vec3& wi) { return Rgb(hg_phase(glm::dot(dir, wi), g)); };
            auto phase_pdf = [&](const Vec3& wi) { return hg_phase(glm::dot(dir, wi), g); };
            radiance += beta * light_sample(p, Vec3(0.0), 0.0, media, u_pick, u_light, sampler, counters, phase,
                                            phase_pdf);
          }
          double pdf = 0.0;
          const Vec3 wi = hg_sample(dir, g, u_dir, pdf);  // phase / pdf = 1: beta is unchanged
          specular = false;
          prev_pdf = pdf;
          prev_point = p;
          ray = Ray{p, wi};
          ++counters.reflection;
          if (roulette) {
            const double q = std::min(1.0, max_channel(beta) / eta_scale);
            if (u_roulette >= q) break;
            beta /= q;
          }
          continue;
        }
      }
    }

    if (fog_on_ && !fogged) {
      fog_segment(ray.direction, found ? hit.t : Interval::kInfinity);
      if (is_black(beta)) break;
    }
    if (!found) {
      if (lights_.has_sky()) {
        double w = specular ? 1.0 : power_heuristic(prev_pdf, lights_.pdf_sky(dir));
        radiance += beta * lights_.sky(dir) * w;
      }
      break;
    }
    // A layered material shows one layer per hit, picked by its share (render/shade/layers.hpp);
    // only scenes with one draw the value.
    MaterialScratch layer_scratch;
    uint32_t material_id = world_.instance(hit.instance).material;
    const MaterialDesc& base =
        has_layers_ ? path_layer(material_id, materials_, world_, hit, textures_, sampler.next(), layer_scratch,
                                 default_material_, material_id)
                    : surface_material(material_id, hit);
    const bool into = glm::dot(hit.normal, dir) < 0.0;
    if (has_pass_through_ && media.cross_clear(hit.medium, base, into)) {
      // Not a bounce: the ray goes on from the far side, into the medium beyond, with what
      // chose it (MIS still weighs what it finds against the last real vertex).
      if (++passes > tol::kMaxPassThrough) break;
      ray = Ray{offset_ray_origin(hit.point, into ? -hit.normal : hit.normal, dir, hit.error), dir};
      --bounce;
      continue;
    }
    MaterialScratch scratch;
    const MaterialDesc& m = shading_material(base, world_, hit, textures_, scratch);

    // Emission found by the ray: all of it after a delta lobe or from an emitter NEE does not
    // sample, else weighed against NEE's density for the same point.
    Rgb le = to_rgb(m.emission);
    if (!is_black(le)) {
      double w = 1.0;
      if (!specular && lights_.sampled(hit.instance))
        w = power_heuristic(prev_pdf, lights_.pdf_hit(prev_point, hit));
      radiance += beta * le * w;
    }
    if (bounce > max_depth_) break;

    // Face the geometric normal towards the ray; the shading normal joins its side.
    Vec3 ng = hit.normal, n = hit.shading_normal;
    const bool entering = glm::dot(ng, dir) < 0.0;
    if (!entering) ng = -ng;
    if (glm::dot(n, ng) < 0.0) n = -n;
    n = detail_normal(m, world_, hit, n, textures_);
    Lobes lb = lobes(m, material_id, hit);
    double n_from = 1.0, n_to = 1.0;
    if (has_transmission_ && !is_black(lb.transmit)) {
      media.interface(hit.medium, m, entering, n_from, n_to);
      lb.eta = n_from / n_to;
    }
    Bsdf bsdf(lb, n, ng, -dir);
    if (bsdf.black()) break;

    // Next-event estimation: one light, one shadow ray. Every bounce takes the same sampler
    // dimensions whether it uses them or not; a value nothing reads is skipped, not computed
    // (profile finding, perf on the Cycles Cornell box: Sampler::next and next2 were 16% of
    // the render, and a one-light scene's pick, a one-lobe surface's lobe choice and the
    // first bounces' roulette value are never read). Skipping leaves every value the same.
    const bool nee = bsdf.has_smooth() && !lights_.empty();
    const double u_pick = nee && !lights_.single() ? sampler.next() : (sampler.skip(1), 0.0);
    const glm::dvec2 u_light = nee ? sampler.next2() : (sampler.skip(2), glm::dvec2(0.0));
    if (nee) {
      auto response = [&](const Vec3& wi) {
        const Rgb f = bsdf.f(wi);
        return is_black(f) ? f : f * bsdf.cos_theta(wi);
      };
      auto bsdf_pdf = [&](const Vec3& wi) { return bsdf.pdf(wi); };
      // A shadow ray towards the back of a transmissive surface is blocked by it (its BSDF
      // lobe there is a delta), so the media it starts in are the ones on the ray's side.
      radiance += beta * light_sample(hit.point, ng, hit.error, media, u_pick, u_light, sampler, counters,
                                      response, bsdf_pdf);
    }

    // Continue along a direction sampled from the BSDF.
    const double u_lobe = bsdf.single_lobe() ? (sampler.skip(1), 0.5) : sampler.next();
    const glm::dvec2 u_dir = sampler.next2();
    const bool roulette = bounce + 1 >= kRouletteStart;
    const double u_roulette = roulette ? sampler.next() : (sampler.skip(1), 0.0);
    BsdfSample bs;
    if (!bsdf.sample(u_lobe, u_dir, bs)) break;
    beta *= bs.weight;
    if (is_black(beta) || !finite(beta)) break;
    beta = glm::min(beta, Rgb(tol::kMaxRadiance));
    specular = bs.delta;
    prev_pdf = bs.pdf;
    prev_point = hit.point;
    if (bs.transmitted) {
      ++counters.refraction;
      eta_scale *= lb.eta * lb.eta;
      if (entering)
        media.enter(hit.medium, n_to, m.medium);
      else
        media.leave(hit.medium);
    } else {
      ++counters.reflection;
    }
    ray = Ray{offset_ray_origin(hit.point, ng, bs.wi, hit.error), bs.wi};
    // Russian roulette: continue with probability q (the path's largest weight without the
    // refraction factors, at most 1: pbrt-v4's rrBeta) and divide by it, so the estimate stays
    // unbiased. Cycles' sqrt(weight) keeps paths longer: on the Cycles Cornell box it cut the
    // RMSE at equal spp by 4% for 12% more CPU time, no gain at equal error (path-tracing.md).
    if (roulette) {
      double q = std::min(1.0, max_channel(beta) / eta_scale);
      if (u_roulette >= q) break;
      beta /= q;
    }
  }
  // settings.clamp: a sample's largest channel at most clamp, its colour kept (biased; off by
  // default).
  if (clamp_ > 0.0) {
    const double peak = max_channel(radiance);
    if (peak > clamp_) radiance *= clamp_ / peak;
  }
  return radiance;
}

}  // namespace rts::render::path
