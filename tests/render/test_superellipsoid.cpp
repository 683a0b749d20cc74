// The superellipsoid against closed forms: e = n = 1 is the unit sphere, small exponents
// approach the cube, crossings along the axes at +-1, normals out, grazing rays give pairs.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/geometry/shapes/sphere.hpp"
#include "render/geometry/shapes/superellipsoid.hpp"

using namespace rts::render;

TEST_CASE("superellipsoid e = n = 1 is the unit sphere", "[superellipsoid]") {
  Superellipsoid s{1.0, 1.0};
  Sphere ball{Vec3(0), 1.0};
  for (Vec3 o : {Vec3(-3, 0.2, 0.1), Vec3(0.3, -4, 0.5), Vec3(0.1, 0.7, -5)}) {
    Ray ray{o, -o + Vec3(0.05, -0.02, 0.03)};
    SurfaceHit a, b;
    bool hit_s = intersect(s, ray, Interval::positive(), a);
    bool hit_b = intersect(ball, ray, Interval::positive(), b);
    REQUIRE(hit_s == hit_b);
    if (!hit_s) continue;
    CHECK(a.t == Approx(b.t).epsilon(1e-12));
    CHECK(glm::dot(a.normal, b.normal) == Approx(1.0).epsilon(1e-6));
  }
}

TEST_CASE("superellipsoid crossings along the axes are at +-1; small exponents approach the cube", "[superellipsoid]") {
  for (double k : {0.1, 0.5, 2.0}) {
    Superellipsoid s{k, k};
    double t[4];
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 o(0.0), d(0.0);
      o[axis] = -5;
      d[axis] = 1;
      INFO("exponent " << k << " axis " << axis);
      REQUIRE(superellipsoid_crossings(s, Ray{o, d}, t, 4) == 2);
      CHECK(t[0] == Approx(4.0).epsilon(1e-12));
      CHECK(t[1] == Approx(6.0).epsilon(1e-12));
    }
  }
  // Near the cube's edge a small exponent is nearly square: the diagonal point (0.9, 0.9, 0)
  // is inside for e = 0.1, outside for e = 1 (the sphere).
  CHECK(superellipsoid_value(Superellipsoid{0.1, 0.1}, Vec3(0.9, 0.9, 0)) < 0.0);
  CHECK(superellipsoid_value(Superellipsoid{1.0, 1.0}, Vec3(0.9, 0.9, 0)) > 0.0);
  SurfaceHit h;
  REQUIRE(intersect(Superellipsoid{0.2, 0.2}, Ray{Vec3(0.3, 5, 0.2), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.normal.y == Approx(1.0).margin(1e-3));  // on the flat top
  CHECK(h.error > 0.0);
}

TEST_CASE("superellipsoid: rays grazing or missing give pairs, never NaN", "[superellipsoid]") {
  Superellipsoid s{0.5, 0.3};
  double t[8];
  for (double y : {0.99, 0.999999, 1.0, 1.000001, 2.0}) {
    int n = superellipsoid_crossings(s, Ray{Vec3(-5, y, 0), Vec3(1, 0, 0)}, t, 8);
    CHECK(n % 2 == 0);
    for (int i = 0; i < n; ++i) CHECK(std::isfinite(t[i]));
    if (y > 1.0) CHECK(n == 0);
  }
}
