// The BSDF seam of the material unit (render/shade/material.hpp): what a physically based
// integrator scatters with. A BSDF is built per hit from the resolved MaterialDesc (shading.hpp
// gives the same per-point values Whitted uses) and the point's shading frame, which it keeps
// (pbrt-v4's BSDF does the same), and answers
//   f(wi)                  the BSDF value for light arriving from unit wi (no cosine),
//   pdf(wi)                the density sample() draws wi with (solid angle; 0 for delta lobes),
//   sample(u_lobe, u, s)   a direction from uniforms (u_lobe picks the lobe, u in [0,1)^2 the
//                          direction) into s; false when the sample carries nothing.
// Directions are world-space unit vectors pointing away from the surface. The type is a
// template parameter or a closed std::variant of BSDF types, never a virtual call per ray.
// render/shade/path/bsdf.hpp's path::Bsdf (the path tracer's) is one.
#pragma once

#include <concepts>

#include <glm/glm.hpp>

namespace rts::render {

struct BsdfSample {
  glm::dvec3 wi{0.0};      // world, unit, towards the light
  glm::dvec3 weight{0.0};  // f cos / pdf (for a delta lobe: its throughput over its probability)
  double pdf = 0.0;        // solid-angle density of the smooth lobes' mixture (0 for a delta lobe)
  bool delta = false;      // a mirror or refraction lobe
  bool transmitted = false;
};

template <class B>
concept Bsdf = requires(const B& b, const glm::dvec3& wi, double u_lobe, glm::dvec2 u, BsdfSample& s) {
  { b.f(wi) } -> std::same_as<glm::dvec3>;
  { b.pdf(wi) } -> std::same_as<double>;
  { b.sample(u_lobe, u, s) } -> std::same_as<bool>;
};

}  // namespace rts::render
