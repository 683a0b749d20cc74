// The GGX (Trowbridge-Reitz) microfacet distribution, isotropic, in a local frame with the
// macro normal along +z, with Heitz's (2018) sampling of the normals visible from wo; its
// reflection lobe and its transmission lobe (rough glass).
#pragma once

#include <algorithm>
#include <cmath>

#include "render/shade/path/warp.hpp"

namespace rts::render::path {

struct Ggx {
  double alpha = 1.0;

  // Normal distribution D(h) for a unit local half vector h.
  double d(const Vec3& h) const {
    double a2 = alpha * alpha, c2 = h.z * h.z;
    if (c2 <= 0.0) return 0.0;
    double k = (a2 - 1.0) * c2 + 1.0;
    return a2 / (kPi * k * k);
  }
  // Smith's Lambda(w): the shadowed fraction's auxiliary function.
  double lambda(const Vec3& w) const {
    double c2 = w.z * w.z;
    if (c2 <= 0.0) return 0.0;
    double tan2 = std::max(0.0, 1.0 - c2) / c2;
    return 0.5 * (std::sqrt(1.0 + alpha * alpha * tan2) - 1.0);
  }
  double g1(const Vec3& w) const { return 1.0 / (1.0 + lambda(w)); }
  // Height-correlated masking-shadowing.
  double g2(const Vec3& wo, const Vec3& wi) const { return 1.0 / (1.0 + lambda(wo) + lambda(wi)); }

  // A microfacet normal seen from wo (local, wo.z > 0), distributed as G1(wo) max(0, wo.h) D(h) / wo.z.
  Vec3 sample_visible(const Vec3& wo, glm::dvec2 u) const {
    Vec3 vh = glm::normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
    double len2 = vh.x * vh.x + vh.y * vh.y;
    Vec3 t1 = len2 > 0.0 ? Vec3(-vh.y, vh.x, 0.0) / std::sqrt(len2) : Vec3(1.0, 0.0, 0.0);
    Vec3 t2 = glm::cross(vh, t1);
    double r = std::sqrt(u.x), phi = 2.0 * kPi * u.y;
    double p1 = r * std::cos(phi), p2 = r * std::sin(phi);
    double s = 0.5 * (1.0 + vh.z);
    p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * p2;
    Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
    return glm::normalize(Vec3(alpha * nh.x, alpha * nh.y, std::max(1e-12, nh.z)));
  }

  // Density of the reflected direction wi when h is sampled with sample_visible(wo):
  // G1(wo) D(h) / (4 wo.z), h the half vector of (wo, wi).
  double pdf_reflect(const Vec3& wo, const Vec3& wi) const {
    Vec3 h = wo + wi;
    double len = glm::length(h);
    if (!(len > 0.0) || wo.z <= 0.0) return 0.0;
    h /= len;
    return g1(wo) * d(h) / (4.0 * wo.z);
  }
  // The BRDF value D G2 / (4 cos_o cos_i) (no Fresnel: the lobe's weight stands for it).
  double f_reflect(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    Vec3 h = wo + wi;
    double len = glm::length(h);
    if (!(len > 0.0)) return 0.0;
    h /= len;
    return d(h) * g2(wo, wi) / (4.0 * wo.z * wi.z);
  }

  // ---- transmission (Walter et al. 2007, in pbrt-v4's form) ----
  // wo above (wo.z > 0), wi below (wi.z < 0); eta = n_from / n_to (the side of wo over the
  // side of wi). The microfacet normal that refracts wo into wi, facing +z; false when the
  // pair cannot come from one refraction (either direction on the wrong side of it).
  static bool half_transmit(const Vec3& wo, const Vec3& wi, double eta, Vec3& m) {
    if (wo.z <= 0.0 || wi.z >= 0.0) return false;
    m = wi + eta * wo;  // Snell: wi + eta wo is along the normal that refracts wo into wi
    double len = glm::length(m);
    if (!(len > 0.0)) return false;
    m /= len;
    if (m.z < 0.0) m = -m;
    return glm::dot(m, wo) > 0.0 && glm::dot(m, wi) < 0.0;
  }
  // The Jacobian |d m / d wi| of the refraction's half vector: |wi.m| / (wi.m + eta wo.m)^2.
  static double transmit_jacobian(const Vec3& wo, const Vec3& wi, const Vec3& m, double eta) {
    double denom = glm::dot(wi, m) + eta * glm::dot(wo, m);
    return std::abs(glm::dot(wi, m)) / (denom * denom);
  }
  // Density of wi when m is sampled with sample_visible(wo) and wo refracted through it.
  double pdf_transmit(const Vec3& wo, const Vec3& wi, double eta) const {
    Vec3 m;
    if (!half_transmit(wo, wi, eta, m)) return 0.0;
    return g1(wo) * d(m) * glm::dot(wo, m) / wo.z * transmit_jacobian(wo, wi, m, eta);
  }
  // The BTDF's shape D G2 |wi.m| |wo.m| / (|wi.z| wo.z (wi.m + eta wo.m)^2) times eta^2 (radiance
  // is compressed entering a denser medium, as the smooth lobe's weight has it); no Fresnel:
  // the lobe's weight stands for it, as for f_reflect.
  double f_transmit(const Vec3& wo, const Vec3& wi, double eta) const {
    Vec3 m;
    if (!half_transmit(wo, wi, eta, m)) return 0.0;
    return eta * eta * d(m) * g2(wo, wi) * glm::dot(wo, m) / (std::abs(wi.z) * wo.z) *
           transmit_jacobian(wo, wi, m, eta);
  }
};

// wo refracted through the facet of normal m (both local, wo.m > 0), eta = n_from / n_to;
// false on total internal reflection.
inline bool refract_local(const Vec3& wo, const Vec3& m, double eta, Vec3& wi) {
  double cos_i = glm::dot(wo, m);
  double sin2_t = eta * eta * std::max(0.0, 1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) return false;
  double cos_t = std::sqrt(1.0 - sin2_t);
  wi = -eta * wo + (eta * cos_i - cos_t) * m;
  return true;
}

}  // namespace rts::render::path
