#include "render/shade/lights.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "render/sample/camera.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

double attenuation_factor(const Vec3& k, double d, bool clamp) {
  double denom = k.x + k.y * d + k.z * d * d;
  if (clamp) return denom > 1.0 ? 1.0 / denom : 1.0;  // also covers a zero denominator at d = 0
  return denom > tol::kTinyLength ? 1.0 / denom : 0.0;
}

std::vector<CompiledLight> compile_lights(const std::vector<LightDesc>& world_lights, int pixel_samples) {
  std::vector<CompiledLight> out;
  for (const LightDesc& d : world_lights) {
    CompiledLight l;
    l.kind = d.kind;
    // color * intensity may overflow (1e200 * 1e200): saturate, so the light stays the
    // brightest finite light instead of infinity (and 0 * inf = NaN further on).
    l.power = glm::min(Rgb(d.color.r, d.color.g, d.color.b) * d.intensity, Rgb(tol::kMaxRadiance));
    l.position = d.position;
    // scaled_length, so a spot 1e-160 from what it points at keeps its axis (glm::length
    // rounded it to 0); inside the squares' range it is glm::length, bit for bit.
    const double dl = scaled_length(d.direction);
    l.direction = dl > 0.0 ? d.direction / dl : Vec3(0, -1, 0);
    const Vec3 axis = d.point_at - d.position;
    const double al = scaled_length(axis);
    l.spot_axis = al > 0.0 ? axis / al : Vec3(0, -1, 0);
    double inner = std::clamp(d.radius, 0.0, 180.0), outer = std::clamp(d.falloff, 0.0, 180.0);
    if (outer < inner) outer = inner;
    l.cos_inner = std::cos(inner * std::numbers::pi / 180.0);
    l.cos_outer = std::cos(outer * std::numbers::pi / 180.0);
    l.attenuation = d.attenuation;
    l.attenuation_clamp = d.attenuation_clamp;
    l.u = d.u;
    l.v = d.v;
    l.disc = d.disc;
    l.area_spot = d.kind == LightKind::Area && d.area_spot;
    int asked = d.auto_samples ? auto_area_samples(pixel_samples) : d.samples;
    l.samples = d.kind == LightKind::Area ? std::clamp(asked, 1, kMaxAreaSamples) : 1;
    l.strata_side = square_side(static_cast<uint32_t>(l.samples));
    l.inv_strata = 1.0 / (l.strata_side > 0 ? l.strata_side : l.samples);
    l.constant_attenuation = d.attenuation.y == 0.0 && d.attenuation.z == 0.0;
    l.sample_power = l.power / static_cast<double>(l.samples);
    if (l.constant_attenuation)
      l.sample_power = glm::min(l.sample_power * attenuation_factor(l.attenuation, 0.0, l.attenuation_clamp),
                                Rgb(tol::kMaxRadiance));
    l.shadows = d.shadows;
    out.push_back(l);
  }
  return out;
}

double spot_factor(const CompiledLight& l, const Vec3& light_to_point) {
  double c = glm::dot(light_to_point, l.spot_axis);
  if (c >= l.cos_inner) return 1.0;
  if (c <= l.cos_outer) return 0.0;
  double t = (c - l.cos_outer) / (l.cos_inner - l.cos_outer);
  return t * t * (3.0 - 2.0 * t);
}

double area_spot_factor(const CompiledLight& l, const Vec3& point) {
  const Vec3 d = point - l.position;
  const double length = glm::length(d);
  return length > tol::kTinyLength ? spot_factor(l, d / length) : 1.0;
}

namespace {

// Radiance arriving from one light sample at `distance`.
// Saturated: a tiny attenuation (1e-10) near the light multiplies the power by up to 1e300.
Rgb sample_radiance(const CompiledLight& l, double distance) {
  return l.constant_attenuation
             ? l.sample_power
             : glm::min(l.sample_power * attenuation_factor(l.attenuation, distance, l.attenuation_clamp),
                        Rgb(tol::kMaxRadiance));
}

LightSample toward(const Vec3& light_pos, const Vec3& point) {
  LightSample s;
  Vec3 d = light_pos - point;
  s.distance = glm::length(d);
  s.direction = s.distance > tol::kTinyLength ? d * (1.0 / s.distance) : Vec3(0, 1, 0);
  return s;
}

// An area light's sample, out of line: inlined, its disc mapping and spot cone gave
// sample_light a stack frame that every point light's sample paid for (callgrind,
// bench/leave_out_a.rts: sample_light +12% once the spot cone was added).
[[gnu::noinline]] LightSample sample_area(const CompiledLight& l, const Vec3& point, glm::dvec2 on_light) {
  glm::dvec2 p = l.disc ? 0.5 * concentric_disc(on_light) : on_light - 0.5;  // in [-0.5, 0.5]^2
  LightSample s = toward(l.position + p.x * l.u + p.y * l.v, point);
  s.radiance = sample_radiance(l, s.distance);
  if (l.area_spot) s.radiance *= area_spot_factor(l, point);
  return s;
}

}  // namespace

LightSample sample_light(const CompiledLight& l, const Vec3& point, glm::dvec2 on_light) {
  switch (l.kind) {
    case LightKind::Directional: {
      LightSample s;
      s.direction = -l.direction;
      s.distance = std::numeric_limits<double>::infinity();
      s.radiance = l.power;
      return s;
    }
    case LightKind::Point: {
      LightSample s = toward(l.position, point);
      s.radiance = sample_radiance(l, s.distance);
      return s;
    }
    case LightKind::Spot: {
      LightSample s = toward(l.position, point);
      s.radiance = sample_radiance(l, s.distance) * spot_factor(l, -s.direction);
      return s;
    }
    case LightKind::Area: return sample_area(l, point, on_light);
  }
  return {};
}

}  // namespace rts::render
