// The path tracer's BSDF at one surface point, shaped like pbrt-v4's BxDFs (sample / f / pdf):
// a mixture of up to four lobes read from rts's material weights (docs/path-tracing.md):
//   diffuse   Lambert, albedo color x diffuse;
//   glossy    specular/shininess as a normalised GGX lobe, alpha = sqrt(2 / (shininess + 2));
//   reflect   a mirror (delta) or, with roughness > 0, a GGX lobe of alpha = roughness;
//   transmit  a dielectric (exact Fresnel, total internal reflection): smooth, or with
//             roughness > 0 rough glass: one GGX lobe that reflects or refracts at each facet
//             by the facet's own Fresnel term (pbrt-v4's rough DielectricBxDF), so a facet
//             that reflects totally inside sends its light back, not nowhere.
// Delta lobes are sampled only; f and pdf cover the others, as MIS needs.
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "render/shade/bsdf.hpp"
#include "render/shade/path/microfacet.hpp"
#include "render/shade/path/warp.hpp"

namespace rts::render::path {

using Rgb = glm::dvec3;

// A material's lobe weights at one point, before Fresnel (see Bsdf).
struct Lobes {
  Rgb diffuse{0.0}, glossy{0.0}, reflect{0.0}, transmit{0.0};
  double glossy_alpha = 1.0;
  double reflect_alpha = 0.0;   // 0: a perfect mirror
  double transmit_alpha = 0.0;  // 0: smooth refraction
  bool fresnel = false;         // opaque: `reflect` is the reflectance at normal incidence (Schlick)
  double eta = 1.0;             // transmissive: n_from / n_to across the surface
};

using render::BsdfSample;  // render/shade/bsdf.hpp

// Exact Fresnel reflectance of an unpolarised dielectric interface; `cos_i` > 0 on the incident
// side, eta = n_from / n_to. 1 on total internal reflection.
double fresnel_dielectric(double cos_i, double eta);

class Bsdf {
 public:
  // `n`: the shading normal, `ng`: the geometric normal, both facing `wo` (world, unit,
  // towards where the light goes).
  Bsdf(const Lobes& lobes, const Vec3& n, const Vec3& ng, const Vec3& wo);

  bool black() const { return total_ <= 0.0; }
  // Only one lobe can be chosen: sample() ignores u_lobe (rough glass reads it to choose
  // between a facet's reflection and refraction).
  bool single_lobe() const {
    return !rough_glass_ && (p_diffuse_ > 0.0) + (p_glossy_ > 0.0) + (p_reflect_ > 0.0) + (p_transmit_ > 0.0) == 1;
  }
  bool has_smooth() const {
    return p_diffuse_ + p_glossy_ + (reflect_delta_ ? 0.0 : p_reflect_) + (rough_glass_ ? p_transmit_ : 0.0) > 0.0;
  }
  Rgb f(const Vec3& wi) const;
  // |cos| between wi and the normal the lobes are shaded with.
  double cos_theta(const Vec3& wi) const { return std::abs(glm::dot(wi, frame_.n)); }
  double pdf(const Vec3& wi) const;
  // False when the sample carries nothing (below the surface, absorbed).
  bool sample(double u_lobe, glm::dvec2 u, BsdfSample& out) const;

 private:
  Frame frame_;
  Vec3 ng_, wo_, wo_local_;
  Rgb diffuse_, glossy_, reflect_, transmit_;
  Ggx glossy_ggx_, reflect_ggx_, glass_ggx_;
  bool reflect_delta_ = true;
  // Rough glass: its lobe's share is p_transmit_; the facets reflect glass_reflect_ and
  // transmit transmit_, each times its Fresnel share.
  bool rough_glass_ = false;
  Rgb glass_reflect_{0.0};
  double eta_ = 1.0;
  double p_diffuse_ = 0, p_glossy_ = 0, p_reflect_ = 0, p_transmit_ = 0, total_ = 0;
};

static_assert(render::Bsdf<Bsdf>, "the path tracer's BSDF implements the material unit's seam (render/shade/bsdf.hpp)");

}  // namespace rts::render::path
