#include "render/shade/path/path_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "render/geometry/tolerances.hpp"
#include "render/shade/medium_stack.hpp"
#include "render/shade/shading.hpp"

namespace rts::render::path {
namespace {

Rgb to_rgb(const Color& c) { return Rgb(c.r, c.g, c.b); }
double max_channel(const Rgb& c) { return std::max({c.x, c.y, c.z}); }
bool is_black(const Rgb& c) { return !(max_channel(c) > 0.0); }
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

// The indices on the two sides of a transmissive surface, from the medium stack, as the
// Whitted integrator reads them: `ior` is absolute unless `ior_relative`.
void interface(const MediumStack& media, uint32_t instance, const MaterialDesc& m, bool entering,
               double& n_from, double& n_to) {
  if (entering) {
    n_from = media.current();
    n_to = m.ior_relative ? n_from * m.ior : m.ior;
  } else {
    n_to = media.outside(instance);
    if (!media.find(instance, n_from)) n_from = m.ior_relative ? n_to * m.ior : m.ior;
  }
}

}  // namespace

PathIntegrator::PathIntegrator(const World& world, const SceneDesc& scene, const std::vector<CompiledLight>& lights,
                               const std::vector<CompiledTexture>& textures, int max_depth,
                               std::vector<Warning>& warnings)
    : world_(world), materials_(scene.materials), textures_(textures),
      lights_(world, scene, lights, textures), max_depth_(max_depth), clamp_(scene.settings.clamp) {
  std::vector<bool> placed(scene.materials.size(), false);
  for (std::size_t i = 0; i < world.instance_count(); ++i)
    if (world.instance(i).material < placed.size()) placed[world.instance(i).material] = true;
  scale_.assign(scene.materials.size(), 1.0);
  for (std::size_t id = 0; id < scene.materials.size(); ++id) {
    if (!placed[id]) continue;
    const MaterialDesc& m = scene.materials[id];
    if (max_channel(to_rgb(m.transmit)) > 0.0 || m.transmit_texture != kNoId) has_transmission_ = true;
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

Rgb PathIntegrator::trace(const Ray& camera_ray, Sampler& sampler, RayCounters& counters) const {
  Rgb radiance(0.0), beta(1.0);
  // The product of the (n_from / n_to)^2 factors refraction put into beta: Russian roulette
  // looks at beta without them, so a path inside glass, whose radiance is only compressed, is
  // not ended more often than one outside (pbrt-v4's etaScale).
  double eta_scale = 1.0;
  Ray ray = camera_ray;
  bool specular = true;   // the last vertex was the camera or a delta lobe: no MIS for what it finds
  double prev_pdf = 0.0;  // the BSDF density that chose the current ray (solid angle)
  Vec3 prev_point(0.0);
  MediumStack media;
  for (int bounce = 0;; ++bounce) {
    Vec3 dir = glm::normalize(ray.direction);
    WorldHit hit;
    if (!world_.intersect(ray, Interval::positive(), hit)) {
      if (lights_.has_sky()) {
        double w = specular ? 1.0 : power_heuristic(prev_pdf, lights_.pdf_sky(dir));
        radiance += beta * lights_.sky(dir) * w;
      }
      break;
    }
    const uint32_t material_id = world_.instance(hit.instance).material;
    const MaterialDesc& base = material_id < materials_.size() ? materials_[material_id] : default_material_;
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
      interface(media, hit.medium, m, entering, n_from, n_to);
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
      LightSample ls;
      if (lights_.sample(hit.point, u_pick, u_light, ls) && !is_black(ls.radiance)) {
        Rgb f = bsdf.f(ls.wi);
        if (!is_black(f)) {
          ++counters.shadow;
          Vec3 origin = offset_ray_origin(hit.point, ng, ls.wi, hit.error);
          double end = std::isinf(ls.distance) ? Interval::kInfinity : ls.distance * (1.0 - tol::kShadowEndRelative);
          if (!world_.occluded(Ray{origin, ls.wi}, Interval(0.0, end))) {
            double w = ls.delta ? 1.0 : power_heuristic(ls.pdf, bsdf.pdf(ls.wi));
            Rgb c = beta * f * ls.radiance * (bsdf.cos_theta(ls.wi) * w / ls.pdf);
            if (finite(c)) radiance += c;
          }
        }
      }
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
        media.enter(hit.medium, n_to);
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
