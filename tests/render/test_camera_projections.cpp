// POV-Ray's camera types (Projection::Fisheye ... Spherical, render/sample/camera.cpp) against
// their geometry: the image centre looks along the direction; a fisheye's rim is half its angle
// off the axis and its corners send no ray; a cylinder sweeps its angle across the image and the
// cylinder 3 and 4 cameras move their viewpoint instead of turning; the spherical camera turns
// by longitude and latitude. The whole pictures match POV-Ray 3.7's renders of its own camera
// demos (docs/rendering.md#cameras).
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "render/sample/camera.hpp"

using namespace rts::render;

namespace {

constexpr int kW = 80, kH = 60;

// POV-Ray's default vectors: direction z, right 1.33 x, up y, at the origin.
CameraDesc pov(Projection p, double angle) {
  CameraDesc c;
  c.projection = p;
  c.position = Vec3(0);
  c.given_vectors = true;
  c.direction = Vec3(0, 0, 1);
  c.right = Vec3(1.33, 0, 0);
  c.up = Vec3(0, 1, 0);
  c.fov = angle;
  c.vertical_fov = angle / 2;
  return c;
}

double degrees_off_axis(const Vec3& d) { return std::acos(std::clamp(d.z, -1.0, 1.0)) * 180.0 / std::numbers::pi; }

}  // namespace

TEST_CASE("projections: the image centre looks along the direction", "[camera]") {
  for (Projection p : {Projection::Fisheye, Projection::UltraWideAngle, Projection::Omnimax, Projection::Cylinder1,
                       Projection::Cylinder2, Projection::Cylinder3, Projection::Cylinder4, Projection::Spherical}) {
    INFO(projection_name(p));
    const Camera cam(pov(p, 120), kW, kH);
    Ray r;
    REQUIRE(cam.generate(kW / 2.0, kH / 2.0, glm::dvec2(0.5), r));
    if (p != Projection::Omnimax) CHECK(degrees_off_axis(r.direction) == Approx(0.0).margin(1e-9));
    CHECK(glm::length(r.direction) == Approx(1.0));
  }
}

TEST_CASE("projections: a fisheye's rim is half its angle off the axis; its corners send no ray", "[camera]") {
  // The circle spans the image's height (up's length 1 against right's 1.33).
  const Camera cam(pov(Projection::Fisheye, 180), kW, kH);
  Ray r;
  REQUIRE(cam.generate(kW / 2.0, 1e-9, glm::dvec2(0.5), r));
  CHECK(degrees_off_axis(r.direction) == Approx(90.0).margin(1e-4));
  CHECK(r.direction.y > 0.99);  // the top of the image looks up
  CHECK_FALSE(cam.generate(0.5, 0.5, glm::dvec2(0.5), r));
}

TEST_CASE("projections: a cylinder sweeps its angle; types 3 and 4 move the viewpoint", "[camera]") {
  Ray r;
  // Cylinder 1 (axis up): the left edge is half the angle to the left, level.
  const Camera c1(pov(Projection::Cylinder1, 90), kW, kH);
  REQUIRE(c1.generate(0.0, kH / 2.0, glm::dvec2(0.5), r));
  CHECK(std::atan2(r.direction.x, r.direction.z) * 180 / std::numbers::pi == Approx(-45.0));
  CHECK(r.direction.y == Approx(0.0).margin(1e-12));
  // Cylinder 3: the top row starts half of up's length above the camera, looking level.
  const Camera c3(pov(Projection::Cylinder3, 90), kW, kH);
  REQUIRE(c3.generate(kW / 2.0, 0.0, glm::dvec2(0.5), r));
  CHECK(r.origin.y == Approx(0.5));
  CHECK(r.direction.y == Approx(0.0).margin(1e-12));
  // Cylinder 4 (axis right): the viewpoint moves along right; the top looks half the angle up.
  const Camera c4(pov(Projection::Cylinder4, 90), kW, kH);
  REQUIRE(c4.generate(0.0, 0.0, glm::dvec2(0.5), r));
  CHECK(r.origin.x == Approx(-0.5 * 1.33));
  CHECK(std::atan2(r.direction.y, r.direction.z) * 180 / std::numbers::pi == Approx(45.0));
}

TEST_CASE("projections: the spherical camera turns by longitude and latitude", "[camera]") {
  const Camera cam(pov(Projection::Spherical, 360), kW, kH);  // 360 across, 180 up and down
  Ray r;
  REQUIRE(cam.generate(0.75 * kW, kH / 2.0, glm::dvec2(0.5), r));  // a quarter turn right
  CHECK(r.direction.x == Approx(1.0));
  REQUIRE(cam.generate(kW / 2.0, 0.25 * kH, glm::dvec2(0.5), r));  // 45 degrees up
  CHECK(r.direction.y == Approx(std::sqrt(0.5)));
  CHECK(r.direction.z == Approx(std::sqrt(0.5)));
}

TEST_CASE("projections: the panoramic camera spans half a turn, right to left", "[camera]") {
  const Camera cam(pov(Projection::Panoramic, 90), kW, kH);
  Ray r;
  REQUIRE(cam.generate(1e-9, kH / 2.0, glm::dvec2(0.5), r));  // left edge: along -right
  CHECK(r.direction.x == Approx(-1.0));
  REQUIRE(cam.generate(kW - 1e-9, kH / 2.0, glm::dvec2(0.5), r));
  CHECK(r.direction.x == Approx(1.0));
}
