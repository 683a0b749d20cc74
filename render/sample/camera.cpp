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
  angle_ = desc.fov * std::numbers::pi / 180.0;
  vertical_angle_ = desc.vertical_fov * std::numbers::pi / 180.0;
  if (desc.given_vectors && scaled_length(desc.direction) > tol::kTinyLength) {
    given_vectors(desc);
    pov_direction_ = desc.direction;
    pov_right_ = desc.right;
    pov_up_ = desc.up;
    set_pov_vectors();
    return;
  }
  Vec3 fwd = desc.look_at - desc.position;
  // Lengths and directions scaled first: a camera 1e200 units from its look_at is a camera.
  forward_ = scaled_length(fwd) > tol::kTinyLength ? unit_vector(fwd) : Vec3(0, 0, 1);
  Vec3 up = scaled_length(desc.up) > tol::kTinyLength ? desc.up : Vec3(0, 1, 0);
  if (!squares_in_range(up)) up = unit_vector(up);
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
  // POV-Ray's camera types with look_at: its default vectors turned towards it, right as long
  // as the image is wide against up (POV-Ray's right x*image_width/image_height).
  pov_direction_ = forward_;
  pov_right_ = right_ / std::max(aspect, 1e-300);
  pov_up_ = up_;
  set_pov_vectors();
  if (desc.aperture > 0.0) {
    lens_radius_ = desc.aperture / 2.0;
    focus_distance_ = desc.focus_distance > 0.0 ? desc.focus_distance
                                                 : scaled_length(desc.look_at - desc.position);
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
  const double scale = projection_ == Projection::Perspective ? 1.0 / scaled_length(desc.direction) : 1.0;
  forward_ = unit_vector(desc.direction);
  right_ = desc.right * scale;
  up_ = desc.up * scale;
  lens_right_ = scaled_length(desc.right) > tol::kTinyLength ? unit_vector(desc.right) : Vec3(1, 0, 0);
  lens_up_ = scaled_length(desc.up) > tol::kTinyLength ? unit_vector(desc.up) : Vec3(0, 1, 0);
  if (desc.aperture > 0.0) {
    lens_radius_ = desc.aperture / 2.0;
    focus_distance_ = desc.focus_distance > 0.0 ? desc.focus_distance : scaled_length(desc.direction);
  }
}

// POV-Ray's camera types read their vectors' lengths (an aspect ratio, a scale) and then use
// them normalised, except the panoramic and spherical cameras, which take them as they are.
void Camera::set_pov_vectors() {
  right_length_ = scaled_length(pov_right_);
  up_length_ = scaled_length(pov_up_);
  if (!pov_projection(projection_)) return;
  if (projection_ != Projection::Panoramic && projection_ != Projection::Spherical) {
    if (right_length_ > tol::kTinyLength) pov_right_ /= right_length_;
    if (up_length_ > tol::kTinyLength) pov_up_ /= up_length_;
    if (scaled_length(pov_direction_) > tol::kTinyLength) pov_direction_ = unit_vector(pov_direction_);
  }
}

namespace {
// `v` turned by `angle` radians about unit `axis` (right-handed about the axis, as a rotation
// matrix acts on column vectors).
Vec3 turned(const Vec3& v, const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}
}  // namespace

// POV-Ray 3.7's camera types (its documented projections; x0, y0 the image position from
// -1/2 to 1/2, y upwards): each gives a direction (or origin) from direction D, right R, up U.
bool Camera::pov_ray(double px, double py, Ray& out) const {
  double x0 = px * inv_width_ - 0.5, y0 = 0.5 - py * inv_height_;
  const Vec3 &D = pov_direction_, &R = pov_right_, &U = pov_up_;
  Vec3 origin = position_, dir;
  switch (projection_) {
    case Projection::Fisheye:
    case Projection::Omnimax: {
      // Polar coordinates of the image position in the unit circle; no ray outside it.
      double x = 2.0 * x0, y = 2.0 * y0;
      if (projection_ == Projection::Fisheye) {
        x *= right_length_;
        y *= up_length_;
      } else {
        // The dome film's aspect (1.283458 across) against the image's (right : up).
        const double aspect = right_length_ / up_length_;
        constexpr double kDome = 1.283458;
        if (aspect > 1.0) {
          if (aspect > kDome) {
            x *= aspect / kDome;
            y = (y - 1.0) / kDome + 1.0;
          } else {
            y = (y - 1.0) / aspect + 1.0;
          }
        } else {
          y /= aspect;
        }
      }
      const double rad = std::sqrt(x * x + y * y);
      if (rad > 1.0) return false;
      const double phi = rad == 0.0 ? 0.0 : x < 0.0 ? std::numbers::pi - std::asin(y / rad) : std::asin(y / rad);
      // The angle from the axis: half the fisheye's angle at the rim; the omnimax lens's curve.
      const double theta = projection_ == Projection::Fisheye
                               ? rad * angle_ / 2.0
                               : 1.411269 * rad - 0.09439 * rad * rad * rad + 0.25674 * std::pow(rad, 5);
      const double cx = std::cos(phi), sx = std::sin(phi), cy = std::cos(theta), sy = std::sin(theta);
      // The omnimax dome sees no further than 45 degrees below its axis.
      if (projection_ == Projection::Omnimax && sx * sy < std::tan(135.0 * std::numbers::pi / 180.0) * cy) return false;
      dir = (cx * sy) * R + (sx * sy) * U + cy * D;
      break;
    }
    case Projection::UltraWideAngle: {
      const double ax = x0 * angle_, ay = y0 * angle_ * (up_length_ / right_length_);
      dir = std::sin(ax) * R + std::sin(ay) * U + (std::cos(ax) * std::cos(ay)) * D;
      break;
    }
    case Projection::Panoramic: {
      // Half a turn across the image; up and down to the poles (tan: a huge step there).
      const double ax = (1.0 - px * inv_width_) * std::numbers::pi, ay = std::numbers::pi * y0;
      const double ty = std::abs(std::numbers::pi / 2 - std::abs(ay)) < 1e-10 ? std::copysign(1e10, ay) : std::tan(ay);
      dir = std::cos(ax) * R + ty * U + std::sin(ax) * D;
      break;
    }
    case Projection::Cylinder1:  // a vertical cylinder's sweep, a single viewpoint
    case Projection::Cylinder3:  // the same sweep, the viewpoint moving up the axis
      x0 *= angle_;
      y0 *= up_length_;
      if (projection_ == Projection::Cylinder1) {
        dir = std::sin(x0) * R + y0 * U + std::cos(x0) * D;
      } else {
        dir = std::sin(x0) * R + std::cos(x0) * D;
        origin = position_ + y0 * U;
      }
      break;
    case Projection::Cylinder2:  // a horizontal cylinder's sweep, a single viewpoint
    case Projection::Cylinder4:  // the same sweep, the viewpoint moving along the axis
      y0 *= angle_;
      x0 *= right_length_;
      if (projection_ == Projection::Cylinder2) {
        dir = x0 * R + std::sin(y0) * U + std::cos(y0) * D;
      } else {
        dir = std::sin(y0) * U + std::cos(y0) * D;
        origin = position_ + x0 * R;
      }
      break;
    case Projection::Spherical: {
      // Latitude: direction turned about right; longitude: then about up.
      const Vec3 r = glm::length(R) > tol::kTinyLength ? glm::normalize(R) : Vec3(1, 0, 0);
      const Vec3 u = glm::length(U) > tol::kTinyLength ? glm::normalize(U) : Vec3(0, 1, 0);
      dir = turned(turned(D, r, -y0 * vertical_angle_), u, x0 * angle_);
      break;
    }
    default:
      out = generate(px, py, glm::dvec2(0.5));
      return true;
  }
  const double len = glm::length(dir);
  if (!(len > 0.0) || !std::isfinite(len)) return false;
  out = Ray{origin, dir / len};
  return true;
}

Ray Camera::generate(double px, double py, glm::dvec2 lens) const {
  if (pov_projection(projection_)) {
    Ray r{position_, forward_};
    pov_ray(px, py, r);
    return r;
  }
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
