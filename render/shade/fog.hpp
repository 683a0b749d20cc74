// Fog in the Whitted integrator (POV-Ray's `fog`): light travelling a distance s through fog
// keeps exp(-tau) of itself and gains the fog's colour for the rest, tau being the optical depth
// along the way. Constant fog has density 1 everywhere: tau = s / distance. Ground fog
// (altitude > 0) has density 1 at or below `offset` and 1 / (1 + (y - offset) / altitude)^2
// above it, POV-Ray's ground-fog profile; its optical depth along a straight ray has a closed
// form (the density's antiderivative in y), so no marching. Applied to every ray segment, camera
// and secondary alike; shadow rays are not fogged (as in POV-Ray).
#pragma once

#include <cmath>
#include <limits>

#include "render/geometry/tolerances.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

struct Fog {
  double distance = 0.0;  // > 0: the distance over which constant fog leaves 1/e of the light
  double offset = 0.0;    // ground fog: the height below which the density is 1
  double altitude = 0.0;  // > 0: ground fog, the height scale of its fall-off above `offset`

  // Fraction of the light leaving origin + t * direction that reaches `origin` (t may be
  // infinite: a ray that leaves the scene).
  double transmittance(const Vec3& origin, const Vec3& direction, double t) const {
    const double len = std::sqrt(glm::dot(direction, direction));
    const double s = t * len;  // path length
    if (altitude <= 0.0) return std::exp(-s / distance);
    const double uy = direction.y / len;
    const double y0 = origin.y;
    if (std::abs(uy) < tol::kFogLevelRay) return std::exp(-s * density(y0) / distance);
    const double y1 = std::isinf(s) ? (uy > 0 ? kInf : -kInf) : y0 + s * uy;
    const double tau = (height_integral(y1) - height_integral(y0)) / uy / distance;
    return std::exp(-tau);
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  double density(double y) const {
    if (y <= offset) return 1.0;
    double q = 1.0 + (y - offset) / altitude;
    return 1.0 / (q * q);
  }
  // An antiderivative of density(y): y below the offset, offset + altitude (1 - 1/q) above
  // (which tends to offset + altitude as y grows: fog above the ground fog thins to nothing).
  double height_integral(double y) const {
    if (y <= offset) return y;
    if (std::isinf(y)) return offset + altitude;
    return offset + altitude * (1.0 - 1.0 / (1.0 + (y - offset) / altitude));
  }
};

}  // namespace rts::render
