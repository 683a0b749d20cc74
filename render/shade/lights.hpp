// Lights in world space, precomputed for shading: point, spot (smooth falloff between the
// `radius` and `falloff` half-angles), directional, and area (rectangle or inscribed disc,
// sampled with stratified samples for soft shadows).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "render/sample/sampler.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

using Rgb = glm::dvec3;

struct CompiledLight {
  LightKind kind = LightKind::Point;
  Rgb power{1.0};              // color * intensity
  Vec3 position{0.0};
  Vec3 direction{0, -1, 0};    // directional: unit, the direction light travels
  Vec3 spot_axis{0, -1, 0};    // spot: unit, from position towards point_at
  double cos_inner = 1.0, cos_outer = 1.0;  // spot: cosines of radius / falloff half-angles
  Vec3 attenuation{1, 0, 0};
  bool attenuation_clamp = false;  // factor min(1, ...): never brighter than power
  Vec3 u{1, 0, 0}, v{0, 0, 1};
  bool disc = false;
  bool area_spot = false;      // area: the spot cone (cos_inner, cos_outer, spot_axis) from position
  int samples = 1;             // shading samples (area lights; 1 otherwise)
  uint32_t strata_side = 1;    // square_side(samples): grid strata, or 0 for N-rooks
  double inv_strata = 1.0;     // 1 / strata_side, or 1 / samples for N-rooks
  bool constant_attenuation = true;  // attenuation = <c, 0, 0>: no distance falloff
  Rgb sample_power{1.0};       // power / samples, times the attenuation when constant
  bool shadows = true;
};

struct LightSample {
  Vec3 direction{0, 1, 0};     // unit, from the shaded point towards the light
  double distance = 0.0;       // to the light sample; infinity for directional lights
  Rgb radiance{0.0};           // arriving light, already weighted by 1/samples
};

// Area lights' sample count is clamped to [1, kMaxAreaSamples].
inline constexpr int kMaxAreaSamples = 4096;

// An area light without `samples` gets this many shadow samples per pixel, spread over the
// pixel samples: ceil(16 / spp) per shading point (16 at 1 spp, as before; 4 at 4 spp; 1 from
// 16 spp). Each pixel sample draws its light samples from its own sampler dimensions, so the
// pixel's samples together cover the light (a scrambled Sobol sequence stratifies them).
inline constexpr int kAutoAreaSamplesPerPixel = 16;

// Light samples per shading point for an area light written without `samples`.
inline int auto_area_samples(int pixel_samples) {
  int spp = pixel_samples < 1 ? 1 : pixel_samples;
  return (kAutoAreaSamplesPerPixel + spp - 1) / spp;
}

// `pixel_samples` (the scene's samples per pixel, the cap under adaptive sampling) resolves
// the area lights written without `samples` (LightDesc::auto_samples).
std::vector<CompiledLight> compile_lights(const std::vector<LightDesc>& world_lights, int pixel_samples = 1);

// The light seen from `point` through the light position `on_light` in [0,1)^2 (area lights:
// across u and v; ignored by the others).
LightSample sample_light(const CompiledLight& light, const Vec3& point, glm::dvec2 on_light);

// A spot light's smooth falloff towards the unit `light_to_point`: 1 inside the inner cone, 0
// outside the outer one, smoothstep between.
double spot_factor(const CompiledLight& light, const Vec3& light_to_point);
// An area spot light's (area_spot) cone factor at `point`, from the light's centre.
double area_spot_factor(const CompiledLight& light, const Vec3& point);

// 1 / (c + l d + q d^2), guarded against non-positive denominators; with `clamp`,
// min(1, 1 / (c + l d + q d^2)) (UW CSE 457's point lights).
double attenuation_factor(const Vec3& coefficients, double distance, bool clamp = false);

}  // namespace rts::render
