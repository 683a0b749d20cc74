// Participating media (MediumDesc, render/scene/scene.hpp) as both integrators read them: the
// coefficients per unit length, the density at a point, transmittance along a segment, the
// Henyey-Greenstein phase function, and the path tracer's free-flight walk.
//
// Units: a ray segment is given by its origin, a unit direction and its length in world units
// (infinite for a ray that leaves the scene). Extinction sigma_t = absorption + scattering.
//
// A homogeneous medium (no density texture) is computed in closed form wherever it can be:
// transmittance exp(-sigma_t s), emission eps (1 - exp(-sigma_t s)) / sigma_t; the path tracer
// samples its scattering distances exactly (one channel's extinction, the three averaged in the
// density). A heterogeneous
// one (density in [0, 1] from a texture) is walked with null collisions against the majorant
// max(sigma_t) (Woodcock/delta tracking; ratio tracking for transmittance), and the channels are
// weighted as in spectral tracking (Kutz et al. 2017), so every estimate is unbiased.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/accel/world.hpp"
#include "render/scene/scene.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/texture.hpp"
#include "render/sample/sampler.hpp"
#include "render/shade/medium_stack.hpp"

namespace rts::render {

// A stream of uniforms for the walks whose length varies (null collisions, ratio tracking):
// counter-based, seeded from one sampler value, so a path's other dimensions do not shift.
class MediumRng {
 public:
  explicit MediumRng(double seed) : state_(mix64(static_cast<uint64_t>(seed * 0x1.0p53))) {}
  double next() { return to_unit(mix64(state_ += 0x9e3779b97f4a7c15ULL)); }

 private:
  uint64_t state_;
};

// Henyey-Greenstein: the density of scattering from propagation direction d_in into d_out,
// as a function of cos = d_in · d_out (g > 0 scatters forward). Normalised over the sphere.
double hg_phase(double cos_theta, double g);
// A direction scattered from unit d_in, distributed as hg_phase; `pdf` is its density.
Vec3 hg_sample(const Vec3& d_in, double g, glm::dvec2 u, double& pdf);

class CompiledMedium {
 public:
  CompiledMedium(const MediumDesc& desc, const CompiledTexture* density);

  bool homogeneous() const { return density_ == nullptr; }
  bool scatters() const { return scatters_; }
  bool emits() const { return emits_; }
  double eccentricity() const { return g_; }
  const Rgb& sigma_s() const { return sigma_s_; }
  const Rgb& sigma_t() const { return sigma_t_; }
  const Rgb& emission() const { return emission_; }
  // The largest extinction over the channels: the bound on sigma_t * density everywhere.
  double majorant() const { return majorant_; }

  // The density at world point p: 1 when homogeneous, else the texture's mean channel clamped
  // to [0, 1].
  double density(const Vec3& p) const;

  // Transmittance over `length` of a homogeneous medium (exact; 0 where sigma_t > 0 and the
  // length is infinite), times POV-Ray's fade over it when the medium has one.
  Rgb transmittance(double length) const;
  // POV-Ray's fade over a crossing of `length` (MediumDesc::fade_distance); 1 without one.
  bool fades() const { return fade_distance_ > 0.0; }
  Rgb fade(double length) const;
  // The light a homogeneous medium emits along a segment of `length` that reaches its start:
  // the integral of exp(-sigma_t s) eps ds.
  Rgb emitted(double length) const;

  // Transmittance along a segment: closed form when homogeneous, else ratio tracking (an
  // unbiased estimate drawing from `rng`).
  Rgb transmittance(const Vec3& origin, const Vec3& dir, double length, MediumRng& rng) const;

  // The Whitted integrator's deterministic version for heterogeneous media: the optical depth
  // by the midpoint rule over `steps` intervals (closed form when homogeneous). `shadow`: for a
  // shadow ray, which skips a fade of power 0 as POV-Ray's do.
  Rgb transmittance_marched(const Vec3& origin, const Vec3& dir, double length, int steps, bool shadow = false) const;

  // The path tracer's free flight along a segment of `length`: adds to `radiance` (times
  // `beta`) the emission found, updates `beta` for what survives, and returns true with the
  // distance `t` of a real scattering event before the segment's end (false: the path reaches
  // the end, with `beta` weighted accordingly; beta may become black).
  bool free_flight(const Vec3& origin, const Vec3& dir, double length, MediumRng& rng, Rgb& beta,
                   Rgb& radiance, double& t) const;

 private:
  Rgb absorbed(double length) const;  // exp(-sigma_t length): transmittance without the fade
  Rgb sigma_a_{0.0}, sigma_s_{0.0}, sigma_t_{0.0}, emission_{0.0};
  double g_ = 0.0;
  double majorant_ = 0.0;
  double fade_distance_ = 0.0, fade_power_ = 0.0;
  Rgb fade_color_{0.0};
  bool scatters_ = false, emits_ = false;
  const CompiledTexture* density_ = nullptr;
};

// The media stack of a path that starts at `point` (the camera): the transmissive objects
// around it, outermost first, found by walking one ray from it to infinity (an object whose
// first crossing is an exit holds the point). A camera inside a clear box of haze sees the haze.
MediumStack media_around(const World& world, const std::vector<MaterialDesc>& materials, const Vec3& point);

// The scene's media compiled against its textures (by MediumId).
std::vector<CompiledMedium> compile_media(const SceneDesc& scene, const std::vector<CompiledTexture>& textures);

}  // namespace rts::render
