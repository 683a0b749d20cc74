// The GGX (Trowbridge-Reitz) microfacet distribution, isotropic, in a local frame with the
// macro normal along +z, with Heitz's (2018) sampling of the normals visible from wo.
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
};

}  // namespace rts::render::path
