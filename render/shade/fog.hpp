// Fog in the Whitted integrator (POV-Ray's `fog`): light travelling a distance s through fog
// keeps exp(-tau) of itself and gains the fog's colour for the rest, tau being the optical depth
// along the way. Constant fog has density 1 everywhere: tau = s / distance. Ground fog
// (altitude > 0) has density 1 at or below `offset` and 1 / (1 + Y^2) above it, Y = (y -
// offset) / altitude: POV-Ray's ground-fog profile (its source's ground_fog, whose antiderivative
// is atan Y); the optical depth along a straight ray has that closed form, so no marching. Applied to every ray segment, camera
// and secondary alike; shadow rays are not fogged (as in POV-Ray).
//
// Turbulent fog (POV-Ray's): each segment's optical depth is thinned by the noise read once,
// at the segment's middle scaled by `turbulence`: tau *= 1 - k min(1, T(p) turb_depth), with T
// POV-Ray's turbulence (the sum of omega^i noise01(lambda^i p) over the octaves) and
// k = exp(-s / distance), so the farther a surface the less the turbulence shows; a ray to
// infinity is not thinned.
#pragma once

#include <cmath>
#include <limits>

#include "render/geometry/function/noise.hpp"
#include "render/geometry/tolerances.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

struct Fog {
  double distance = 0.0;  // > 0: the distance over which constant fog leaves 1/e of the light
  double offset = 0.0;    // ground fog: the height below which the density is 1
  double altitude = 0.0;  // > 0: ground fog, the height scale of its fall-off above `offset`
  Vec3 turbulence{0.0};   // non-zero: turbulent
  double turb_depth = 0.5;
  int octaves = 6;
  double omega = 0.5, lambda = 2.0;
  double least = 0.0;     // the transmittance never falls below it (POV-Ray's fog transmit)

  static Fog from(const Settings& s) {
    return Fog{s.fog_distance, s.fog_offset,  s.fog_altitude, s.fog_turbulence, s.fog_turb_depth,
               s.fog_octaves,  s.fog_omega,   s.fog_lambda,   s.fog_transmit};
  }

  // Fraction of the light leaving origin + t * direction that reaches `origin` (t may be
  // infinite: a ray that leaves the scene).
  double transmittance(const Vec3& origin, const Vec3& direction, double t) const {
    const double len = std::sqrt(glm::dot(direction, direction));
    const double s = t * len;  // path length
    double tau = optical_depth(origin, direction / len, s);
    if (turbulence != Vec3(0.0) && std::isfinite(s)) tau *= thinning(origin + (0.5 * t) * direction, s);
    return std::max(std::exp(-tau), least);
  }

  // The turbulent factor of a segment of length s whose middle is `middle`, in [0, 1].
  double thinning(const Vec3& middle, double s) const {
    const Vec3 p = middle * turbulence;
    double sum = 0.0, weight = 1.0, scale = 1.0;
    for (int i = 0; i < octaves; ++i, weight *= omega, scale *= lambda) sum += weight * pattern::noise01(scale * p);
    return 1.0 - std::exp(-s / distance) * std::min(1.0, sum * turb_depth);
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  // Along unit direction u for a length s (infinite: to the end of the scene).
  double optical_depth(const Vec3& origin, const Vec3& u, double s) const {
    if (altitude <= 0.0) return s / distance;
    const double y0 = origin.y;
    if (std::abs(u.y) < tol::kFogLevelRay) return s * density(y0) / distance;
    const double y1 = std::isinf(s) ? (u.y > 0 ? kInf : -kInf) : y0 + s * u.y;
    return (height_integral(y1) - height_integral(y0)) / u.y / distance;
  }
  double density(double y) const {
    if (y <= offset) return 1.0;
    const double q = (y - offset) / altitude;
    return 1.0 / (1.0 + q * q);
  }
  // An antiderivative of density(y): y below the offset, offset + altitude atan(Y) above
  // (which tends to offset + altitude pi / 2 as y grows: fog above the ground fog thins out).
  double height_integral(double y) const {
    if (y <= offset) return y;
    return offset + altitude * std::atan((y - offset) / altitude);  // atan(inf) = pi / 2
  }
};

}  // namespace rts::render
