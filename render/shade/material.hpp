// The material model: how a surface point of a MaterialDesc (already resolved for textures and
// vertex values by shading.hpp) answers light. The Whitted integrator asks it for the
// emitted + ambient term, the Phong response to one light, the reflect/transmit weights at an
// interface (Schlick's Fresnel, total internal reflection) and the glossy lobe's direction;
// the integrator keeps only the recursion, shadow rays and light loops.
//
// The `Bsdf` seam (render/shade/bsdf.hpp) is what a physically based integrator
// (render/shade/path/) implements its scattering functions against; the Whitted functions above it are not BSDFs
// (Phong is not energy-conserving, and `reflect`/`transmit` are weights, not reflectances).
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <numbers>

#include <glm/glm.hpp>

#include "render/geometry/tolerances.hpp"
#include "render/shade/bsdf.hpp"
#include "render/sample/sampler.hpp"
#include "render/scene/scene.hpp"
#include "render/shade/lights.hpp"

namespace rts::render {

inline Rgb to_rgb(const Color& c) { return Rgb(c.r, c.g, c.b); }
inline double max_channel(const Rgb& c) { return std::max({c.x, c.y, c.z}); }
inline bool is_black(const Rgb& c) { return !(max_channel(c) > 0.0); }

// Snell refraction of unit `incident` through unit normal `n` (facing the incident side) with
// relative index eta = n_from / n_to. Returns false on total internal reflection.
inline bool refract(const Vec3& incident, const Vec3& n, double eta, Vec3& refracted) {
  double cos_i = -glm::dot(incident, n);
  double sin2_t = eta * eta * std::max(0.0, 1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) return false;
  double cos_t = std::sqrt(1.0 - sin2_t);
  refracted = glm::normalize(eta * incident + (eta * cos_i - cos_t) * n);
  return true;
}

// Schlick's approximation of Fresnel reflectance for reflectance at normal incidence f0.
inline double schlick(double cos_theta, double f0) {
  double m = std::clamp(1.0 - cos_theta, 0.0, 1.0);
  double m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

// A surface that may only let light through, unchanged: transmit 1 in every channel, ior 1,
// and nothing reflected, emitted or diffused (the container of a medium, POV-Ray's `hollow`
// object with a clear pigment). Where the indices on its two sides are also equal (always for
// ior_relative; for an absolute ior 1, when the medium around is air: an air bubble in glass
// still refracts), both integrators cross it as if it were not there, keeping the medium stack:
// its ambient and fresnel have nothing to act on.
inline bool passes_through(const MaterialDesc& m) {
  return m.transmit.r == 1.0 && m.transmit.g == 1.0 && m.transmit.b == 1.0 && m.transmit_texture == kNoId &&
         m.ior == 1.0 && m.diffuse == 0.0 && m.diffuse_texture == kNoId && m.specular == 0.0 &&
         m.specular_texture == kNoId && is_black(to_rgb(m.reflect)) && m.reflect_texture == kNoId &&
         is_black(to_rgb(m.emission)) && m.emission_texture == kNoId && m.bump == kNoId && m.normal_map == kNoId;
}

// ---- Whitted (Phong) evaluation ------------------------------------------------------------

// What the surface sends back without any light: emission + ambient * base * ambient light.
// kColored: times the ambient's colour (MaterialDesc::ambient_color; only scenes with one,
// which take the generic path, pay for it).
template <bool kColored = false>
[[gnu::always_inline]] inline Rgb emitted_and_ambient(const MaterialDesc& m, const Rgb& base, const Rgb& ambient_light) {
  if constexpr (kColored) return to_rgb(m.emission) + m.ambient * (base * to_rgb(m.ambient_color)) * ambient_light;
  return to_rgb(m.emission) + m.ambient * base * ambient_light;
}

// POV-Ray's `metallic` highlight colour: the light's colour turned towards the surface's by
// metallic * (1 - F), F POV-Ray's empirical Fresnel curve of the light's angle x = acos(n · l)
// / (pi / 2): 0 facing the light, 1 at grazing (its lighting code, [DB 9/94]).
inline Rgb metallic_tint(const MaterialDesc& m, const Rgb& surface, double n_dot_l) {
  const double x = std::acos(std::clamp(n_dot_l, -1.0, 1.0)) / (0.5 * std::numbers::pi);
  const double f = std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
  return Rgb(1.0) + m.metallic * (1.0 - f) * (surface - Rgb(1.0));
}

// The Phong response to one light from unit direction `to_light` with n_dot_l = n · to_light
// > 0: diffuse * n_dot_l * diffuse_color, plus (when kSpecular) the highlight
// specular * (r · view)^shininess * specular_color, r being to_light mirrored about n. The
// caller multiplies it by the light's radiance and shadow transmittance.
template <bool kSpecular>
inline Rgb phong(const MaterialDesc& m, const Rgb& diffuse_color, const Vec3& n, const Vec3& to_light,
                 double n_dot_l, const Vec3& view) {
  // POV-Ray's brilliance: a steeper fall-off of the diffuse term (1 is Lambert's).
  const double lambert = m.brilliance == 1.0 ? n_dot_l : std::pow(n_dot_l, m.brilliance);
  Rgb shade = m.diffuse * lambert * diffuse_color;
  if (kSpecular && m.specular > 0.0) {
    double lobe = 0.0;
    if (m.blinn) {
      // POV-Ray's `specular`: the half-vector between light and eye against the normal.
      Vec3 h = to_light + view;
      double len = glm::length(h);
      double n_dot_h = len > 0.0 ? glm::dot(n, h) / len : 0.0;
      if (n_dot_h > 0.0) lobe = std::pow(n_dot_h, m.shininess);
    } else {
      Vec3 r = 2.0 * n_dot_l * n - to_light;  // mirror of the light direction
      double r_dot_v = glm::dot(r, view);
      if (r_dot_v > 0.0) lobe = std::pow(r_dot_v, m.shininess);
    }
    if (lobe > 0.0) {
      Rgb highlight = m.specular * lobe * to_rgb(m.specular_color);
      if (m.metallic > 0.0) highlight *= metallic_tint(m, diffuse_color, n_dot_l);
      shade += highlight;
    }
  }
  return shade;
}

// The unpolarised Fresnel reflectance of a dielectric interface for cos_i = cos of the incidence
// angle and eta = n_to / n_from (the textbook form, Cook and Torrance 1982): 1 under total
// internal reflection, 0 for eta = 1.
inline double fresnel_dielectric(double cos_i, double eta) {
  const double c = std::clamp(cos_i, 0.0, 1.0);
  const double g2 = eta * eta + c * c - 1.0;
  if (!(g2 > 0.0)) return 1.0;
  const double g = std::sqrt(g2);
  const double a = (g - c) / (g + c);
  const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
  return std::clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
}

// POV-Ray's variable reflection (MaterialDesc::has_reflect_min): reflect_min head-on to
// `reflect` at grazing angles, by the Fresnel reflectance for the interface's eta (with
// `fresnel`) or by (1 - cos_i)^reflect_falloff. Total internal reflection keeps what
// specular_weights gave (everything reflects).
inline Rgb variable_reflection(const MaterialDesc& m, double cos_i, double eta) {
  const double t = m.fresnel ? fresnel_dielectric(cos_i, eta) : std::pow(std::max(0.0, 1.0 - cos_i), m.reflect_falloff);
  return to_rgb(m.reflect) * t + to_rgb(m.reflect_min) * (1.0 - t);
}

// POV-Ray's reflection { metallic }: the reflection turned towards the surface colour by
// metallic * (1 - F), F the same empirical curve of the viewing angle (cos_i = n · view).
inline Rgb metallic_reflection(const MaterialDesc& m, const Rgb& surface, double cos_i) {
  const double x = std::acos(std::clamp(cos_i, -1.0, 1.0)) / (0.5 * std::numbers::pi);
  const double f = std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
  return Rgb(1.0) + m.reflect_metallic * (1.0 - f) * (surface - Rgb(1.0));
}

// The reflect and transmit weights of a hit, and the refracted direction when light passes.
struct SpecularWeights {
  Rgb reflect{0.0}, transmit{0.0};
  Vec3 refracted{0.0};  // valid when `transmit` is not black
};

// `m`'s reflect and transmit weights at a hit seen along unit `incident`, with unit shading
// normal `n` facing the incident side and cos_i = clamp(n · -incident, 0, 1); n_from and n_to
// are the indices on the two sides (used only when m transmits). With fresnel, the interface
// splits one budget, max(reflect, transmit) per channel, between the two directions: a
// fraction F reflects, 1 - F (filtered by `transmit`) passes, so reflect + transmit never
// exceeds the larger weight (1 for clear glass, whatever `reflect` adds). Without fresnel the
// two weights simply add, as documented. Total internal reflection reflects the transmitted
// energy (F = 1). An opaque fresnel material's `reflect` is its reflectance at normal
// incidence, rising to 1 at grazing angles.
inline SpecularWeights specular_weights(const MaterialDesc& m, const Vec3& incident, const Vec3& n, double cos_i,
                                        double n_from, double n_to) {
  SpecularWeights w;
  w.reflect = to_rgb(m.reflect);
  w.transmit = to_rgb(m.transmit);
  if (!is_black(w.transmit)) {
    if (!refract(incident, n, n_from / n_to, w.refracted)) {
      w.reflect = m.fresnel ? glm::max(w.reflect, w.transmit) : w.reflect + w.transmit;
      w.transmit = Rgb(0.0);
    } else if (m.fresnel) {
      double f0 = (n_from - n_to) / (n_from + n_to);
      f0 *= f0;
      // Schlick uses the angle on the less dense side.
      double cos_thin = n_from <= n_to ? cos_i : -glm::dot(w.refracted, n);
      double fr = schlick(std::abs(cos_thin), f0);
      w.reflect = glm::max(w.reflect, w.transmit) * fr;
      w.transmit *= (1.0 - fr);
    }
  } else if (m.fresnel && !is_black(w.reflect)) {
    double f = schlick(cos_i, 0.0);
    w.reflect = w.reflect + (Rgb(1.0) - w.reflect) * f;
  }
  return w;
}

// The cube root of u in [0, 1), inline: libm's cbrt (a call, frexp and scalbn inside) was 7%
// of the glossy race scene's render. A bit-trick start (within ~3%) and two Halley steps
// (cubic convergence) leave it within 64 ulps (1.5e-14 relative) of libm's; a third, Newton
// step to within 4 ulps cost 3% of the glossy render and changed no image byte.
inline double unit_cbrt(double u) {
  if (!(u > 0.0)) return 0.0;
  double y = std::bit_cast<double>(std::bit_cast<uint64_t>(u) / 3 + 0x2A9F7893782DA1CEull);
  for (int i = 0; i < 2; ++i) {
    const double y3 = y * y * y;
    y *= (y3 + 2.0 * u) / (2.0 * y3 + u);
  }
  return y;
}

// Uniform point in the unit ball from three uniforms (the glossy lobe's perturbation).
inline Vec3 in_unit_ball(Sampler& s) {
  const glm::dvec3 u = s.next3();
  double z = 2.0 * u.x - 1.0;
  double phi = 2.0 * std::numbers::pi * u.y;
  double r = unit_cbrt(u.z);
  double xy = std::sqrt(std::max(0.0, 1.0 - z * z));
  return r * Vec3(xy * std::cos(phi), xy * std::sin(phi), z);
}

// The reflected ray's direction: the mirror direction, or with roughness > 0 the mirror
// perturbed by roughness times a point in the unit ball (one sampler draw of three values),
// falling back to the mirror when the perturbation goes below the surface (geometric normal
// `ng`, facing the incident side).
inline Vec3 reflected_direction(const MaterialDesc& m, const Vec3& mirror, const Vec3& ng, Sampler& sampler) {
  if (!(m.roughness > 0.0)) return mirror;
  Vec3 glossy = mirror + m.roughness * in_unit_ball(sampler);
  if (glm::dot(glossy, ng) > 0.0 && glm::length(glossy) > tol::kTinyLength) return glm::normalize(glossy);
  return mirror;
}

// The BSDF seam (Bsdf, BsdfSample) is render/shade/bsdf.hpp, included here: the path
// tracer's path::Bsdf implements it.

}  // namespace rts::render
