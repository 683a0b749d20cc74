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
  inv_width_ = 1.0 / std::max(1, width);
  inv_height_ = 1.0 / std::max(1, height);
  if (desc.given_vectors && glm::length(desc.direction) > tol::kTinyLength) {
    given_vectors(desc);
    return;
  }
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
  lens_right_ = right_;
  lens_up_ = up_;
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
  if (desc.aperture > 0.0) {
    lens_radius_ = desc.aperture / 2.0;
    focus_distance_ = desc.focus_distance > 0.0 ? desc.focus_distance
                                                 : glm::length(desc.look_at - desc.position);
    if (!(focus_distance_ > tol::kTinyLength)) lens_radius_ = 0.0;
  }
}

// POV-Ray's camera: the ray through image position (x, y), each from -1/2 to 1/2, is
// direction + x·right + y·up with the vectors as given. generate() computes
// forward + sx·right + sy·up with sx, sy from -half to half, so half = 1/2 and the vectors go in
// unchanged; a perspective camera divides them by |direction| (the ray's direction is the same)
// so that forward is a unit vector and a sample at the image centre is one unit away, as
// depth of field assumes. The lens spans the unit right and up.
void Camera::given_vectors(const CameraDesc& desc) {
  half_width_ = half_height_ = 0.5;
  const double scale = projection_ == Projection::Perspective ? 1.0 / glm::length(desc.direction) : 1.0;
  forward_ = glm::normalize(desc.direction);
  right_ = desc.right * scale;
  up_ = desc.up * scale;
  lens_right_ = glm::length(desc.right) > tol::kTinyLength ? glm::normalize(desc.right) : Vec3(1, 0, 0);
  lens_up_ = glm::length(desc.up) > tol::kTinyLength ? glm::normalize(desc.up) : Vec3(0, 1, 0);
  if (desc.aperture > 0.0) {
    lens_radius_ = desc.aperture / 2.0;
    focus_distance_ = desc.focus_distance > 0.0 ? desc.focus_distance : glm::length(desc.direction);
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
      Vec3 o = origin + d.x * lens_right_ + d.y * lens_up_;
      return Ray{o, glm::normalize(focus - o)};
    }
    return Ray{origin, forward_};
  }
  Vec3 dir = forward_ + sx * right_ + sy * up_;  // forward component 1: dir*f lies on the focal plane
  if (lens_radius_ > 0.0) {
    glm::dvec2 d = lens_radius_ * concentric_disc(lens);
    Vec3 focus = position_ + focus_distance_ * dir;
    Vec3 o = position_ + d.x * lens_right_ + d.y * lens_up_;
    return Ray{o, glm::normalize(focus - o)};
  }
  return Ray{position_, glm::normalize(dir)};
}

}  // namespace rts::render
