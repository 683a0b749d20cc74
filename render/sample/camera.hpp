// Pinhole / thin-lens perspective and orthographic cameras (left-handed view, POV-Ray's):
// right = normalize(cross(up, forward)), or its opposite for a right-handed camera (OpenGL's,
// the courses'). Image aspect comes from width/height; fov spans the width, or the height.
// Or POV-Ray's camera: direction, right and up as given (CameraDesc::given_vectors).
#pragma once

#include <glm/glm.hpp>

#include "render/geometry/ray.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

class Camera {
 public:
  Camera(const CameraDesc& desc, int width, int height);

  // The ray through image position (px, py) in pixels (0,0 = top-left corner of the image;
  // pixel centres at +0.5). `lens` in [0,1)^2 samples the aperture (ignored without DOF).
  // False where the projection sends no ray (outside a fisheye's circle, below an omnimax
  // dome's edge): that sample is black, as in POV-Ray.
  bool generate(double px, double py, glm::dvec2 lens, Ray& out) const {
    if (pov_projection(projection_)) return pov_ray(px, py, out);
    out = generate(px, py, lens);
    return true;
  }
  // The same for the perspective and orthographic cameras (and a projection's ray where it
  // has one, else one along the camera's direction).
  Ray generate(double px, double py, glm::dvec2 lens) const;
  bool has_depth_of_field() const { return lens_radius_ > 0.0; }
  // POV-Ray's camera types may send no ray through a point: callers then use the bool form.
  bool may_miss() const { return pov_projection(projection_); }
  Vec3 forward() const { return forward_; }

 private:
  void given_vectors(const CameraDesc& desc);  // POV-Ray's direction/right/up, as given
  // POV-Ray's other camera types, from its direction, right and up (render/sample/camera.cpp).
  bool pov_ray(double px, double py, Ray& out) const;
  void set_pov_vectors();

  Projection projection_;
  Vec3 position_, forward_, right_, up_;
  Vec3 lens_right_, lens_up_;        // unit vectors spanning the lens (depth of field)
  double half_width_, half_height_;  // perspective: at distance 1; orthographic: scene units
  double inv_width_, inv_height_;
  double lens_radius_ = 0.0;
  double focus_distance_ = 1.0;
  // POV-Ray's camera types: its direction, right and up as it holds them (unit or not as its
  // projection reads them), their lengths, and its angles in radians.
  Vec3 pov_direction_{0, 0, 1}, pov_right_{1, 0, 0}, pov_up_{0, 1, 0};
  double right_length_ = 1.0, up_length_ = 1.0;
  double angle_ = 0.0, vertical_angle_ = 0.0;
};

// Uniform point on the unit disc from a unit-square sample (Shirley's concentric mapping:
// preserves stratification).
glm::dvec2 concentric_disc(glm::dvec2 u);

}  // namespace rts::render
