#include "render/sample/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/geometry/tolerances.hpp"

namespace rts::render {

// Field of view limits in degrees: tan() blows up at 180.
constexpr double kMinFov = 1e-6;
constexpr double kMaxFov = 179.999;

glm::dvec2 concentric_disc(glm::dvec2 u) {
  glm::dvec2 o = 2.0 * u - 1.0;
  if (o.x == 0.0 && o.y == 0.0) return {0.0, 0.0};
  double r, theta;
  if (std::abs(o.x) > std::abs(o.y)) {
    r = o.x;
    theta = std::numbers::pi / 4 * (o.y / o.x);
  } else {
    r = o.y;
    theta = std::numbers::pi / 2 - std::numbers::pi / 4 * (o.x / o.y);
  }
  return {r * std::cos(theta), r * std::sin(theta)};
}

Camera::Camera(const CameraDesc& desc, int width, int height)
    : projection_(desc.projection), position_(desc.position) {
  Vec3 fwd = desc.look_at - desc.position;
  forward_ = glm::length(fwd) > tol::kTinyLength ? glm::normalize(fwd) : Vec3(0, 0, 1);
  Vec3 up = glm::length(desc.up) > tol::kTinyLength ? desc.up : Vec3(0, 1, 0);
  Vec3 right = glm::cross(up, forward_);
  if (glm::length(right) <= tol::kParallelVectors * glm::length(up)) {
    // up parallel to forward: pick any up that is not.
    right = glm::cross(std::abs(forward_.y) < tol::kReferenceAxisCosine ? Vec3(0, 1, 0) : Vec3(0, 0, 1), forward_);
  }
  right_ = glm::normalize(right);
  up_ = glm::cross(forward_, right_);
  if (desc.right_handed) right_ = -right_;  // OpenGL's convention: the image is mirrored left-right
  double aspect = static_cast<double>(height) / std::max(1, width);
  if (projection_ == Projection::Perspective) {
    double fov = std::clamp(desc.fov, kMinFov, kMaxFov);
    double half = std::tan(fov * std::numbers::pi / 360.0);
    // A vertical fov fixes the height; the width follows from the aspect ratio.
    half_width_ = desc.fov_vertical ? half / aspect : half;
  } else {
    half_width_ = std::abs(desc.view_width) / 2.0;
  }
  half_height_ = half_width_ * aspect;
  inv_width_ = 1.0 / std::max(1, width);
  inv_height_ = 1.0 / std::max(1, height);
  if (desc.aperture > 0.0) {
    lens_radius_ = desc.aperture / 2.0;
    focus_distance_ = desc.focus_distance > 0.0 ? desc.focus_distance
                                                 : glm::length(desc.look_at - desc.position);
    if (!(focus_distance_ > tol::kTinyLength)) lens_radius_ = 0.0;
  }
}

Ray Camera::generate(double px, double py, glm::dvec2 lens) const {
  double sx = (2.0 * px * inv_width_ - 1.0) * half_width_;
  double sy = (1.0 - 2.0 * py * inv_height_) * half_height_;
  if (projection_ == Projection::Orthographic) {
    Vec3 origin = position_ + sx * right_ + sy * up_;
    if (lens_radius_ > 0.0) {
      glm::dvec2 d = lens_radius_ * concentric_disc(lens);
      Vec3 focus = origin + focus_distance_ * forward_;
      Vec3 o = origin + d.x * right_ + d.y * up_;
      return Ray{o, glm::normalize(focus - o)};
    }
    return Ray{origin, forward_};
  }
  Vec3 dir = forward_ + sx * right_ + sy * up_;  // forward component 1: dir*f lies on the focal plane
  if (lens_radius_ > 0.0) {
    glm::dvec2 d = lens_radius_ * concentric_disc(lens);
    Vec3 focus = position_ + focus_distance_ * dir;
    Vec3 o = position_ + d.x * right_ + d.y * up_;
    return Ray{o, glm::normalize(focus - o)};
  }
  return Ray{position_, glm::normalize(dir)};
}

}  // namespace rts::render
