#include "render/shade/path/bsdf.hpp"

#include <algorithm>
#include <cmath>

#include "render/geometry/tolerances.hpp"

namespace rts::render::path {
namespace {

double mean(const Rgb& c) { return (c.x + c.y + c.z) / 3.0; }

double schlick_weight(double cos_theta) {
  double m = std::clamp(1.0 - cos_theta, 0.0, 1.0);
  double m2 = m * m;
  return m2 * m2 * m;
}

Vec3 reflect_local(const Vec3& w, const Vec3& h) { return 2.0 * glm::dot(w, h) * h - w; }

}  // namespace

double fresnel_dielectric(double cos_i, double eta) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) return 1.0;
  double cos_t = std::sqrt(1.0 - sin2_t);
  // eta = n_from / n_to: r_parl and r_perp in terms of the relative index.
  double r_parl = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  double r_perp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return 0.5 * (r_parl * r_parl + r_perp * r_perp);
}

Bsdf::Bsdf(const Lobes& lobes, const Vec3& n, const Vec3& ng, const Vec3& wo)
    // A shading normal that faces away from wo (interpolated or bumped normals at grazing
    // views) would leave the lobes undefined: shade with the geometric normal instead.
    : frame_(glm::dot(n, wo) > tol::kGrazingCosine ? n : ng), ng_(ng), wo_(wo),
      diffuse_(lobes.diffuse), glossy_(lobes.glossy), reflect_(lobes.reflect), transmit_(lobes.transmit),
      eta_(lobes.eta) {
  wo_local_ = frame_.to_local(wo);
  wo_local_.z = std::max(wo_local_.z, tol::kGrazingCosine);
  const double cos_o = wo_local_.z;
  glossy_ggx_.alpha = std::max(lobes.glossy_alpha, tol::kMinMicrofacetAlpha);
  reflect_delta_ = !(lobes.reflect_alpha > 0.0);
  reflect_ggx_.alpha = std::max(lobes.reflect_alpha, tol::kMinMicrofacetAlpha);
  rough_glass_ = lobes.transmit_alpha > 0.0 && mean(transmit_) > 0.0;
  glass_ggx_.alpha = std::max(lobes.transmit_alpha, tol::kMinMicrofacetAlpha);
  if (rough_glass_) {
    // Rough glass: the split between reflection and transmission is made per facet (f, pdf,
    // sample); the lobe is chosen by the split the macro surface would make.
    double fr = fresnel_dielectric(cos_o, eta_);
    glass_reflect_ = glm::max(reflect_, transmit_);
    reflect_ = Rgb(0.0);
    p_transmit_ = mean(glass_reflect_) * fr + mean(transmit_) * (1.0 - fr);
  } else if (mean(transmit_) > 0.0) {
    // A dielectric: a fraction Fr of the light reflects (tinted by the larger of reflect and
    // transmit, as in Whitted mode with fresnel), 1 - Fr passes, filtered by transmit.
    double fr = fresnel_dielectric(cos_o, eta_);
    reflect_ = glm::max(reflect_, transmit_) * fr;
    transmit_ *= (1.0 - fr);
  } else if (lobes.fresnel) {
    // Opaque with fresnel: reflectance rises from `reflect` to 1 at grazing angles (Schlick)
    // and the lobes beneath keep what the reflection leaves.
    Rgb f0 = reflect_;
    double w = schlick_weight(cos_o);
    reflect_ = f0 + (Rgb(1.0) - f0) * w;
    for (int c = 0; c < 3; ++c) {
      double keep = f0[c] < 1.0 ? (1.0 - reflect_[c]) / (1.0 - f0[c]) : 0.0;
      diffuse_[c] *= keep;
      glossy_[c] *= keep;
    }
  }
  p_diffuse_ = mean(diffuse_);
  p_glossy_ = mean(glossy_);
  p_reflect_ = mean(reflect_);
  if (!rough_glass_) p_transmit_ = mean(transmit_);
  total_ = p_diffuse_ + p_glossy_ + p_reflect_ + p_transmit_;
  if (total_ > 0.0) {
    p_diffuse_ /= total_;
    p_glossy_ /= total_;
    p_reflect_ /= total_;
    p_transmit_ /= total_;
  }
}

Rgb Bsdf::f(const Vec3& wi_world) const {
  Vec3 wi = frame_.to_local(wi_world);
  if (glm::dot(wi_world, ng_) <= 0.0) {
    // Below the surface only rough glass passes light, and only into the shading frame's
    // lower side.
    Vec3 m;
    if (!rough_glass_ || wi.z >= 0.0 || !Ggx::half_transmit(wo_local_, wi, eta_, m)) return Rgb(0.0);
    double t = 1.0 - fresnel_dielectric(glm::dot(wo_local_, m), eta_);
    return transmit_ * (t * glass_ggx_.f_transmit(wo_local_, wi, eta_));
  }
  if (wi.z <= 0.0) return Rgb(0.0);
  Rgb f = diffuse_ * kInvPi;
  if (p_glossy_ > 0.0) f += glossy_ * glossy_ggx_.f_reflect(wo_local_, wi);
  if (!reflect_delta_ && p_reflect_ > 0.0) f += reflect_ * reflect_ggx_.f_reflect(wo_local_, wi);
  if (rough_glass_) {
    double r = fresnel_dielectric(glm::dot(wo_local_, glm::normalize(wo_local_ + wi)), eta_);
    f += glass_reflect_ * (r * glass_ggx_.f_reflect(wo_local_, wi));
  }
  return f;
}

double Bsdf::pdf(const Vec3& wi_world) const {
  Vec3 wi = frame_.to_local(wi_world);
  if (glm::dot(wi_world, ng_) <= 0.0) {
    Vec3 m;
    if (!rough_glass_ || wi.z >= 0.0 || !Ggx::half_transmit(wo_local_, wi, eta_, m)) return 0.0;
    double t = 1.0 - fresnel_dielectric(glm::dot(wo_local_, m), eta_);
    return p_transmit_ * t * glass_ggx_.pdf_transmit(wo_local_, wi, eta_);
  }
  if (wi.z <= 0.0) return 0.0;
  double p = p_diffuse_ * wi.z * kInvPi;
  if (p_glossy_ > 0.0) p += p_glossy_ * glossy_ggx_.pdf_reflect(wo_local_, wi);
  if (!reflect_delta_ && p_reflect_ > 0.0) p += p_reflect_ * reflect_ggx_.pdf_reflect(wo_local_, wi);
  if (rough_glass_) {
    double r = fresnel_dielectric(glm::dot(wo_local_, glm::normalize(wo_local_ + wi)), eta_);
    p += p_transmit_ * r * glass_ggx_.pdf_reflect(wo_local_, wi);
  }
  return p;
}

bool Bsdf::sample(double u_lobe, glm::dvec2 u, BsdfSample& out) const {
  if (total_ <= 0.0) return false;
  // The delta lobes first: each is sampled exactly, its weight divided by its probability.
  double edge = p_transmit_;
  if (u_lobe < edge && rough_glass_) {
    // Rough glass: a facet seen from wo, which reflects with its Fresnel probability (always
    // on total internal reflection) and refracts otherwise. The estimate uses the mixture's
    // f and pdf, as for the other smooth lobes.
    const Vec3 m = glass_ggx_.sample_visible(wo_local_, u);
    const double r = fresnel_dielectric(glm::dot(wo_local_, m), eta_);
    Vec3 wi;
    if (u_lobe < edge * r) {
      wi = reflect_local(wo_local_, m);
      if (wi.z <= 0.0) return false;
    } else if (!refract_local(wo_local_, m, eta_, wi) || wi.z >= 0.0) {
      return false;
    }
    out.wi = glm::normalize(frame_.to_world(wi));
    out.transmitted = wi.z < 0.0;
    if ((glm::dot(out.wi, ng_) < 0.0) != out.transmitted) return false;
    out.pdf = pdf(out.wi);
    if (!(out.pdf > 0.0)) return false;
    out.weight = f(out.wi) * std::abs(glm::dot(out.wi, frame_.n)) / out.pdf;
    out.delta = false;
    return true;
  }
  if (u_lobe < edge) {
    Vec3 wo = wo_local_;
    double sin2_t = eta_ * eta_ * std::max(0.0, 1.0 - wo.z * wo.z);
    if (sin2_t >= 1.0) return false;  // total internal reflection: transmit_ is 0 there anyway
    double cos_t = std::sqrt(1.0 - sin2_t);
    Vec3 wi(-eta_ * wo.x, -eta_ * wo.y, -cos_t);
    out.wi = glm::normalize(frame_.to_world(wi));
    if (glm::dot(out.wi, ng_) >= 0.0) return false;
    // Radiance is compressed entering a denser medium: (n_from / n_to)^2 (pbrt-v4, Radiance mode).
    out.weight = transmit_ * (eta_ * eta_) / p_transmit_;
    out.pdf = 0.0;
    out.delta = true;
    out.transmitted = true;
    return true;
  }
  if (reflect_delta_) {
    edge += p_reflect_;
    if (u_lobe < edge) {
      Vec3 wi(-wo_local_.x, -wo_local_.y, wo_local_.z);
      out.wi = glm::normalize(frame_.to_world(wi));
      if (glm::dot(out.wi, ng_) <= 0.0) return false;
      out.weight = reflect_ / p_reflect_;
      out.pdf = 0.0;
      out.delta = true;
      out.transmitted = false;
      return true;
    }
  }
  // A smooth lobe, chosen by its share; the estimate uses the whole mixture's f and pdf.
  Vec3 wi;
  double smooth_u = u_lobe - edge;
  if (smooth_u < p_diffuse_) {
    wi = cosine_hemisphere(u);
  } else if (smooth_u < p_diffuse_ + p_glossy_) {
    wi = reflect_local(wo_local_, glossy_ggx_.sample_visible(wo_local_, u));
  } else {
    wi = reflect_local(wo_local_, reflect_ggx_.sample_visible(wo_local_, u));
  }
  if (wi.z <= 0.0) return false;
  out.wi = glm::normalize(frame_.to_world(wi));
  out.pdf = pdf(out.wi);
  if (!(out.pdf > 0.0)) return false;
  out.weight = f(out.wi) * std::abs(glm::dot(out.wi, frame_.n)) / out.pdf;
  out.delta = false;
  out.transmitted = false;
  return true;
}

}  // namespace rts::render::path
