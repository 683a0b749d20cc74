// POV-Ray's camera: direction, right and up taken as given (CameraDesc::given_vectors), against
// closed-form rays: the ray through image position (x, y), each from -1/2 to 1/2, points along
// direction + x·right + y·up, whatever the vectors' lengths and angles.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "render/sample/camera.hpp"

using namespace rts::render;

namespace {

CameraDesc given(Vec3 direction, Vec3 right, Vec3 up) {
  CameraDesc c;
  c.position = Vec3(1, 2, 3);
  c.given_vectors = true;
  c.direction = direction;
  c.right = right;
  c.up = up;
  return c;
}

// The expected ray direction through pixel (px, py) of a w x h image.
Vec3 expected(const CameraDesc& c, double px, double py, int w, int h) {
  double x = px / w - 0.5, y = 0.5 - py / h;
  return glm::normalize(c.direction + x * c.right + y * c.up);
}

void check_dir(Vec3 got, Vec3 want) {
  CHECK(got.x == Approx(want.x).margin(1e-12));
  CHECK(got.y == Approx(want.y).margin(1e-12));
  CHECK(got.z == Approx(want.z).margin(1e-12));
}

}  // namespace

TEST_CASE("given vectors: perpendicular ones reproduce the look_at camera", "[camera]") {
  const int w = 80, h = 60;
  CameraDesc look;
  look.position = Vec3(0, 0, -5);
  look.look_at = Vec3(0.0);
  look.fov = 50;
  const double t = std::tan(25.0 * std::numbers::pi / 180.0);
  // POV-Ray: fov = 2·atan(|right| / (2·|direction|)); the height follows from |up| (here the
  // image's aspect, as the look_at camera makes it).
  CameraDesc pov = given(Vec3(0, 0, 1), Vec3(2 * t, 0, 0), Vec3(0, 2 * t * h / w, 0));
  pov.position = look.position;
  Camera a(look, w, h), b(pov, w, h);
  for (auto [px, py] : {std::pair{0.0, 0.0}, {40.0, 30.0}, {79.5, 12.25}, {3.0, 59.0}}) {
    Ray ra = a.generate(px, py, {}), rb = b.generate(px, py, {});
    check_dir(rb.direction, ra.direction);
    CHECK(rb.origin == ra.origin);
  }
}

TEST_CASE("given vectors: lengths set the field of view and the aspect", "[camera]") {
  const int w = 200, h = 100;
  // |direction| = 2 with |right| = 1: the left edge's middle is atan(1/4) off the axis.
  CameraDesc c = given(Vec3(0, 0, 2), Vec3(1, 0, 0), Vec3(0, 1, 0));
  Camera cam(c, w, h);
  Ray left = cam.generate(0, h / 2.0, {});
  CHECK(std::acos(glm::dot(left.direction, Vec3(0, 0, 1))) == Approx(std::atan(0.25)));
  // A square right/up on a 2:1 image is not adjusted: the top edge is as far off the axis as
  // the left edge (the picture is stretched, as in POV-Ray).
  Ray top = cam.generate(w / 2.0, 0, {});
  CHECK(top.direction.y == Approx(-left.direction.x));
  check_dir(cam.generate(17, 83, {}).direction, expected(c, 17, 83, w, h));
  CHECK(cam.generate(17, 83, {}).origin == c.position);
}

TEST_CASE("given vectors: an up not perpendicular to direction shears the image", "[camera]") {
  const int w = 64, h = 64;
  CameraDesc c = given(Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0.5));
  Camera cam(c, w, h);
  // The top centre looks along direction + up/2 = (0, 0.5, 1.25), not (0, 0.5, 1).
  check_dir(cam.generate(w / 2.0, 0, {}).direction, glm::normalize(Vec3(0, 0.5, 1.25)));
  check_dir(cam.generate(w / 2.0, h, {}).direction, glm::normalize(Vec3(0, -0.5, 0.75)));
  // A right that leans towards direction shears the other way; any pixel is the closed form.
  c.right = Vec3(1, 0, -0.25);
  Camera lean(c, w, h);
  for (auto [px, py] : {std::pair{0.0, 0.0}, {5.5, 60.0}, {63.0, 31.0}})
    check_dir(lean.generate(px, py, {}).direction, expected(c, px, py, w, h));
}

TEST_CASE("given vectors: orthographic rays start on the plane right and up span", "[camera]") {
  CameraDesc c = given(Vec3(0, 0, 3), Vec3(4, 0, 0), Vec3(0, 2, 1));
  c.projection = Projection::Orthographic;
  const int w = 40, h = 20;
  Camera cam(c, w, h);
  Ray corner = cam.generate(0, 0, {});  // top-left: position - right/2 + up/2
  CHECK(corner.origin.x == Approx(1 - 2));
  CHECK(corner.origin.y == Approx(2 + 1));
  CHECK(corner.origin.z == Approx(3 + 0.5));
  check_dir(corner.direction, Vec3(0, 0, 1));
}

TEST_CASE("given vectors: depth of field focuses at |direction| by default", "[camera]") {
  CameraDesc c = given(Vec3(0, 0, 2), Vec3(1, 0, 0), Vec3(0, 1, 0));
  c.aperture = 0.5;
  const int w = 32, h = 32;
  Camera cam(c, w, h);
  REQUIRE(cam.has_depth_of_field());
  // Every lens sample through the image centre passes through position + direction.
  for (glm::dvec2 lens : {glm::dvec2(0.1, 0.9), glm::dvec2(0.7, 0.3)}) {
    Ray r = cam.generate(w / 2.0, h / 2.0, lens);
    double t = (c.position.z + 2 - r.origin.z) / r.direction.z;
    Vec3 p = r.origin + t * r.direction;
    CHECK(p.x == Approx(c.position.x));
    CHECK(p.y == Approx(c.position.y));
    CHECK(glm::length(r.origin - c.position) <= 0.25 + 1e-12);
  }
}
