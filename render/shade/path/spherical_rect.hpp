// Sampling a rectangular emitter uniformly by the solid angle it subtends (Ureña, Fajardo and
// King 2013, "An Area-Preserving Parametrization for Spherical Rectangles"; written after
// pbrt-v4's SampleSphericalRectangle). Sampling a quad light by area makes its 1/r^2 and
// cosine factors part of the estimate, which is noisy on surfaces near the light; sampling the
// solid angle leaves only the BSDF's cosine. The set-up (four normalisations and four angles)
// is shared by sample() and by the density a BSDF ray's MIS weight needs.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "render/shade/path/warp.hpp"

namespace rts::render::path {

// The angle between two unit vectors without acos's loss of precision near 0 and pi.
inline double angle_between(const Vec3& a, const Vec3& b) {
  if (glm::dot(a, b) < 0.0) return kPi - 2.0 * std::asin(std::min(1.0, glm::length(a + b) * 0.5));
  return 2.0 * std::asin(std::min(1.0, glm::length(b - a) * 0.5));
}

// The rectangle s + [0,1] ex + [0,1] ey (ex and ey orthogonal) seen from p.
class SphericalRect {
 public:
  SphericalRect(const Vec3& p, const Vec3& s, const Vec3& ex, const Vec3& ey) : p_(p) {
    const double exl = glm::length(ex), eyl = glm::length(ey);
    x_ = ex / exl;
    y_ = ey / eyl;
    z_ = glm::cross(x_, y_);
    const Vec3 d = s - p;
    x0_ = glm::dot(d, x_);
    y0_ = glm::dot(d, y_);
    z0_ = glm::dot(d, z_);
    if (z0_ > 0.0) {  // z points away from the rectangle
      z_ = -z_;
      z0_ = -z0_;
    }
    // How far p is from the rectangle's plane against its distance from the rectangle.
    height_ratio_ = -z0_ / (glm::length(d + 0.5 * (ex + ey)) + 0.5 * (exl + eyl));
    x1_ = x0_ + exl;
    y1_ = y0_ + eyl;
    const Vec3 v00(x0_, y0_, z0_), v01(x0_, y1_, z0_), v10(x1_, y0_, z0_), v11(x1_, y1_, z0_);
    n0_ = unit_vector(glm::cross(v00, v10));
    n1_ = unit_vector(glm::cross(v10, v11));
    n2_ = unit_vector(glm::cross(v11, v01));
    n3_ = unit_vector(glm::cross(v01, v00));
    g0_ = angle_between(-n0_, n1_);
    g1_ = angle_between(-n1_, n2_);
    g2_ = angle_between(-n2_, n3_);
    g3_ = angle_between(-n3_, n0_);
    solid_angle_ = g0_ + g1_ + g2_ + g3_ - 2.0 * kPi;
    if (!std::isfinite(solid_angle_)) solid_angle_ = 0.0;
  }

  double solid_angle() const { return solid_angle_; }
  // p's height above the rectangle's plane over its distance from it (0 in the plane). A point
  // on the emitter itself is in the plane only up to rounding: just off it, the rectangle fills
  // its hemisphere and solid-angle sampling sends "light" from the surface it stands on.
  double height_ratio() const { return height_ratio_; }

  // A point on the rectangle, uniform in solid angle from p (density 1 / solid_angle()).
  Vec3 sample(glm::dvec2 u) const {
    const double b0 = n0_.z, b1 = n2_.z;
    const double au = u.x * (g0_ + g1_ - 2.0 * kPi) + (u.x - 1.0) * (g2_ + g3_);
    const double fu = (std::cos(au) * b0 - b1) / std::sin(au);
    double cu = std::copysign(1.0 / std::sqrt(fu * fu + b0 * b0), fu);
    cu = std::clamp(cu, -kOneMinusEpsilon, kOneMinusEpsilon);
    double xu = -(cu * z0_) / std::sqrt(std::max(0.0, 1.0 - cu * cu));
    xu = std::clamp(std::isfinite(xu) ? xu : x0_, x0_, x1_);
    const double dd = std::sqrt(xu * xu + z0_ * z0_);
    const double h0 = y0_ / std::sqrt(dd * dd + y0_ * y0_);
    const double h1 = y1_ / std::sqrt(dd * dd + y1_ * y1_);
    const double hv = h0 + u.y * (h1 - h0), hv2 = hv * hv;
    double yv = hv2 < 1.0 - 1e-12 ? hv * dd / std::sqrt(1.0 - hv2) : y1_;
    yv = std::clamp(yv, y0_, y1_);
    return p_ + xu * x_ + yv * y_ + z0_ * z_;
  }

 private:
  static constexpr double kOneMinusEpsilon = 1.0 - 1e-15;
  Vec3 p_, x_, y_, z_;
  double x0_, y0_, z0_, x1_, y1_;
  Vec3 n0_, n1_, n2_, n3_;
  double g0_, g1_, g2_, g3_, solid_angle_, height_ratio_;
};

}  // namespace rts::render::path
