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
  Ray generate(double px, double py, glm::dvec2 lens) const;
  bool has_depth_of_field() const { return lens_radius_ > 0.0; }
  Vec3 forward() const { return forward_; }

 private:
  void given_vectors(const CameraDesc& desc);  // POV-Ray's direction/right/up, as given

  Projection projection_;
  Vec3 position_, forward_, right_, up_;
  Vec3 lens_right_, lens_up_;        // unit vectors spanning the lens (depth of field)
  double half_width_, half_height_;  // perspective: at distance 1; orthographic: scene units
  double inv_width_, inv_height_;
  double lens_radius_ = 0.0;
  double focus_distance_ = 1.0;
};

// Uniform point on the unit disc from a unit-square sample (Shirley's concentric mapping:
// preserves stratification).
glm::dvec2 concentric_disc(glm::dvec2 u);

}  // namespace rts::render
