// Each primitive family, in its own object space: hits, misses, grazing rays, rays starting
// inside, and degenerate parameters.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/geometry/shapes/box.hpp"
#include "render/geometry/shapes/cone.hpp"
#include "render/geometry/shapes/cylinder.hpp"
#include "render/geometry/shapes/disc.hpp"
#include "render/geometry/shapes/plane.hpp"
#include "render/geometry/shapes/sphere.hpp"
#include "render/geometry/shapes/triangle.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using rts::render::test::triangle;

namespace {
const Interval kAll = Interval::positive();
Ray ray(Vec3 o, Vec3 d) { return Ray{o, d}; }
void check_vec(const Vec3& a, const Vec3& b, double eps = 1e-9) {
  CHECK(a.x == Approx(b.x).margin(eps));
  CHECK(a.y == Approx(b.y).margin(eps));
  CHECK(a.z == Approx(b.z).margin(eps));
}
}  // namespace

TEST_CASE("sphere: hit from outside, normal and point", "[primitives]") {
  Sphere s{Vec3(0, 0, 5), 2.0};
  SurfaceHit h;
  REQUIRE(intersect(s, ray(Vec3(0), Vec3(0, 0, 1)), kAll, h));
  CHECK(h.t == Approx(3.0));
  check_vec(h.point, Vec3(0, 0, 3));
  check_vec(h.normal, Vec3(0, 0, -1));
}

TEST_CASE("sphere UVs: v runs from the south pole (0) to the north pole (1)", "[primitives]") {
  CHECK(sphere_uv(Vec3(0, 1, 0)).y == Approx(1.0));
  CHECK(sphere_uv(Vec3(0, -1, 0)).y == Approx(0.0));
  CHECK(sphere_uv(Vec3(1, 0, 0)).y == Approx(0.5));
  CHECK(sphere_uv(Vec3(1, 0, 0)).x == Approx(0.5));
  CHECK(sphere_uv(Vec3(0, 0, 1)).x == Approx(0.75));
}

TEST_CASE("sphere: non-unit direction keeps the ray parameter", "[primitives]") {
  Sphere s{Vec3(0, 0, 5), 2.0};
  SurfaceHit h;
  REQUIRE(intersect(s, ray(Vec3(0), Vec3(0, 0, 2)), kAll, h));
  CHECK(h.t == Approx(1.5));
  check_vec(h.point, Vec3(0, 0, 3));
}

TEST_CASE("sphere: miss, behind the origin, and outside the interval", "[primitives]") {
  Sphere s{Vec3(0, 0, 5), 1.0};
  SurfaceHit h;
  CHECK_FALSE(intersect(s, ray(Vec3(0, 2, 0), Vec3(0, 0, 1)), kAll, h));
  CHECK_FALSE(intersect(s, ray(Vec3(0), Vec3(0, 0, -1)), kAll, h));
  CHECK_FALSE(intersect(s, ray(Vec3(0), Vec3(0, 0, 1)), Interval(0.0, 3.9), h));
}

TEST_CASE("sphere: ray starting inside hits the far side with the outward normal", "[primitives]") {
  Sphere s{Vec3(0), 1.0};
  SurfaceHit h;
  REQUIRE(intersect(s, ray(Vec3(0), Vec3(1, 0, 0)), kAll, h));
  CHECK(h.t == Approx(1.0));
  check_vec(h.normal, Vec3(1, 0, 0));
}

TEST_CASE("sphere: grazing ray touches at the tangent point or misses", "[primitives]") {
  Sphere s{Vec3(0), 1.0};
  SurfaceHit h;
  bool hit = intersect(s, ray(Vec3(-5, 1.0, 0), Vec3(1, 0, 0)), kAll, h);
  if (hit) {
    CHECK(h.t == Approx(5.0).margin(1e-6));
    CHECK(std::isfinite(h.normal.x));
  }
  CHECK_FALSE(intersect(s, ray(Vec3(-5, 1.0 + 1e-9, 0), Vec3(1, 0, 0)), kAll, h));
}

TEST_CASE("sphere: zero radius is never hit", "[primitives]") {
  Sphere s{Vec3(0), 0.0};
  SurfaceHit h;
  CHECK_FALSE(intersect(s, ray(Vec3(0, 0, -1), Vec3(0, 0, 1)), kAll, h));
}

TEST_CASE("plane: hit from either side, parallel misses", "[primitives]") {
  Plane p{Vec3(0, 2, 0), 2.0};  // unnormalised: y = 1
  SurfaceHit h;
  REQUIRE(intersect(p, ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), kAll, h));
  CHECK(h.t == Approx(4.0));
  check_vec(h.normal, Vec3(0, 1, 0));
  REQUIRE(intersect(p, ray(Vec3(3, -1, 0), Vec3(0, 1, 0)), kAll, h));
  CHECK(h.t == Approx(2.0));
  check_vec(h.normal, Vec3(0, 1, 0));  // outward normal regardless of side
  CHECK_FALSE(intersect(p, ray(Vec3(0, 5, 0), Vec3(1, 0, 0)), kAll, h));
  CHECK_FALSE(intersect(p, ray(Vec3(0, 5, 0), Vec3(0, 1, 0)), kAll, h));
}

TEST_CASE("plane: planar UVs are the x and z coordinates for a y-up plane", "[primitives]") {
  Plane p{Vec3(0, 1, 0), 0.0};
  SurfaceHit h;
  REQUIRE(intersect(p, ray(Vec3(2.5, 1, -3), Vec3(0, -1, 0)), kAll, h));
  CHECK(h.uv.x == Approx(2.5));
  CHECK(h.uv.y == Approx(-3.0));
}

TEST_CASE("plane: zero normal is never hit", "[primitives]") {
  Plane p{Vec3(0), 0.0};
  SurfaceHit h;
  CHECK_FALSE(intersect(p, ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), kAll, h));
}

TEST_CASE("triangle: inside, outside, edge-on and degenerate", "[primitives]") {
  Triangle tri = triangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
  SurfaceHit h;
  REQUIRE(intersect(tri, ray(Vec3(0.25, 0.25, -1), Vec3(0, 0, 1)), kAll, h));
  CHECK(h.t == Approx(1.0));
  check_vec(h.normal, Vec3(0, 0, 1));
  CHECK_FALSE(intersect(tri, ray(Vec3(0.75, 0.75, -1), Vec3(0, 0, 1)), kAll, h));
  CHECK_FALSE(intersect(tri, ray(Vec3(-1, 0.25, 0), Vec3(1, 0, 0)), kAll, h));  // in its plane
  Triangle flat = triangle(Vec3(0), Vec3(1, 1, 1), Vec3(2, 2, 2));  // zero area
  CHECK_FALSE(intersect(flat, ray(Vec3(1, 1, 0), Vec3(0, 0, 1)), kAll, h));
  Triangle point = triangle(Vec3(1), Vec3(1), Vec3(1));
  CHECK_FALSE(intersect(point, ray(Vec3(1, 1, 0), Vec3(0, 0, 1)), kAll, h));
}

TEST_CASE("triangle: vertex normals are interpolated", "[primitives]") {
  Triangle tri{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
               Boxed<TriangleNormals>(TriangleNormals{Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 0, 1)})};
  SurfaceHit h;
  REQUIRE(intersect(tri, ray(Vec3(0.5, 0.0, -1), Vec3(0, 0, 1)), kAll, h));
  check_vec(h.shading_normal, glm::normalize(Vec3(0.5, 0, 0.5)), 1e-6);
  check_vec(h.normal, Vec3(0, 0, 1));
}

TEST_CASE("box: entering face normals on every axis", "[primitives]") {
  Box b{Vec3(-1), Vec3(1)};
  SurfaceHit h;
  REQUIRE(intersect(b, ray(Vec3(-5, 0, 0), Vec3(1, 0, 0)), kAll, h));
  CHECK(h.t == Approx(4.0));
  check_vec(h.normal, Vec3(-1, 0, 0));
  REQUIRE(intersect(b, ray(Vec3(0, 5, 0.5), Vec3(0, -1, 0)), kAll, h));
  check_vec(h.normal, Vec3(0, 1, 0));
  REQUIRE(intersect(b, ray(Vec3(0.2, 0.3, 9), Vec3(0, 0, -2)), kAll, h));
  CHECK(h.t == Approx(4.0));
  check_vec(h.normal, Vec3(0, 0, 1));
}

TEST_CASE("box: from inside hits the exit face, misses and axis-parallel rays", "[primitives]") {
  Box b{Vec3(-1), Vec3(1)};
  SurfaceHit h;
  REQUIRE(intersect(b, ray(Vec3(0), Vec3(0, 1, 0)), kAll, h));
  CHECK(h.t == Approx(1.0));
  check_vec(h.normal, Vec3(0, 1, 0));
  CHECK_FALSE(intersect(b, ray(Vec3(-5, 2, 0), Vec3(1, 0, 0)), kAll, h));
  CHECK_FALSE(intersect(b, ray(Vec3(-5, 0, 0), Vec3(-1, 0, 0)), kAll, h));
  REQUIRE(intersect(b, ray(Vec3(-5, -5, 0), Vec3(1, 1, 0)), kAll, h));  // through an edge region
  CHECK(h.t == Approx(4.0));
}

TEST_CASE("cylinder: side, caps, inside and uncapped", "[primitives]") {
  Cylinder c{Vec3(0, 0, 0), Vec3(0, 2, 0), 1.0, true};
  SurfaceHit h;
  REQUIRE(intersect(c, ray(Vec3(-5, 1, 0), Vec3(1, 0, 0)), kAll, h));
  CHECK(h.t == Approx(4.0));
  check_vec(h.normal, Vec3(-1, 0, 0));
  REQUIRE(intersect(c, ray(Vec3(0.5, 5, 0), Vec3(0, -1, 0)), kAll, h));
  CHECK(h.t == Approx(3.0));
  check_vec(h.normal, Vec3(0, 1, 0));
  REQUIRE(intersect(c, ray(Vec3(0, 1, 0), Vec3(0, 0, 1)), kAll, h));  // from inside
  CHECK(h.t == Approx(1.0));
  check_vec(h.normal, Vec3(0, 0, 1));
  CHECK_FALSE(intersect(c, ray(Vec3(-5, 3, 0), Vec3(1, 0, 0)), kAll, h));  // above it
  Cylinder open{Vec3(0, 0, 0), Vec3(0, 2, 0), 1.0, false};
  REQUIRE(intersect(open, ray(Vec3(0.5, 5, 0), Vec3(0, -1, 0)), kAll, h) == false);
  Cylinder slanted{Vec3(0), Vec3(2, 2, 0), 0.5, true};
  REQUIRE(intersect(slanted, ray(Vec3(1, 1, -5), Vec3(0, 0, 1)), kAll, h));
  CHECK(h.t == Approx(4.5));
}

TEST_CASE("cylinder and cone: degenerate axis or radius never hit", "[primitives]") {
  SurfaceHit h;
  CHECK_FALSE(intersect(Cylinder{Vec3(1), Vec3(1), 1.0, true}, ray(Vec3(1, 1, -5), Vec3(0, 0, 1)), kAll, h));
  CHECK_FALSE(intersect(Cylinder{Vec3(0), Vec3(0, 1, 0), 0.0, true}, ray(Vec3(0, 0.5, -5), Vec3(0, 0, 1)), kAll, h));
  CHECK_FALSE(intersect(Cone{Vec3(0), Vec3(0, 1, 0), 0.0, 0.0, true}, ray(Vec3(0, 0.5, -5), Vec3(0, 0, 1)), kAll, h));
}

TEST_CASE("cone: side radius varies linearly along the axis; normal tilts", "[primitives]") {
  Cone c{Vec3(0, 0, 0), Vec3(0, 2, 0), 1.0, 0.0, true};
  SurfaceHit h;
  // At height 1 the radius is 0.5.
  REQUIRE(intersect(c, ray(Vec3(-5, 1, 0), Vec3(1, 0, 0)), kAll, h));
  CHECK(h.t == Approx(4.5));
  check_vec(h.normal, glm::normalize(Vec3(-1, 0.5, 0)), 1e-9);
  // Base cap.
  REQUIRE(intersect(c, ray(Vec3(0.5, -3, 0), Vec3(0, 1, 0)), kAll, h));
  CHECK(h.t == Approx(3.0));
  check_vec(h.normal, Vec3(0, -1, 0));
  // Above the apex: nothing (the mirrored nappe is excluded).
  CHECK_FALSE(intersect(c, ray(Vec3(-5, 2.5, 0), Vec3(1, 0, 0)), kAll, h));
}

TEST_CASE("disc and annulus", "[primitives]") {
  Disc d{Vec3(0, 1, 0), Vec3(0, 1, 0), 2.0, 0.5};
  SurfaceHit h;
  REQUIRE(intersect(d, ray(Vec3(1, 5, 0), Vec3(0, -1, 0)), kAll, h));
  CHECK(h.t == Approx(4.0));
  CHECK_FALSE(intersect(d, ray(Vec3(0.2, 5, 0), Vec3(0, -1, 0)), kAll, h));  // the hole
  CHECK_FALSE(intersect(d, ray(Vec3(2.5, 5, 0), Vec3(0, -1, 0)), kAll, h));  // outside
  CHECK_FALSE(intersect(Disc{Vec3(0), Vec3(0, 1, 0), 0.0, 0.0}, ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), kAll, h));
}

TEST_CASE("bounds enclose the shapes", "[primitives]") {
  AABB s = bounds(Sphere{Vec3(1, 2, 3), 0.5});
  check_vec(s.lo, Vec3(0.5, 1.5, 2.5));
  check_vec(s.hi, Vec3(1.5, 2.5, 3.5));
  AABB c = bounds(Cylinder{Vec3(0), Vec3(0, 2, 0), 1.0, true});
  check_vec(c.lo, Vec3(-1, 0, -1));
  check_vec(c.hi, Vec3(1, 2, 1));
  AABB d = bounds(Disc{Vec3(0), Vec3(0, 1, 0), 2.0, 0.0});
  check_vec(d.lo, Vec3(-2, 0, -2));
  check_vec(d.hi, Vec3(2, 0, 2));
  AABB t = bounds(triangle(Vec3(0), Vec3(1, 0, 0), Vec3(0, 0, 3)));
  check_vec(t.hi, Vec3(1, 0, 3));
}
