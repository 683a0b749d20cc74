// The torus and its quartic: the polynomial root isolation on known polynomials, crossings
// against closed forms (rays along the axes), thin tori (minor/major 1e-4 .. 1), tori far from
// the origin (through a transform) and grazing rays.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/geometry/shapes/poly_roots.hpp"
#include "render/geometry/shapes/torus.hpp"

using namespace rts::render;

TEST_CASE("poly_roots: every sign change of a quartic, ascending", "[torus]") {
  // (s-1)(s-2)(s-3)(s-4) = s^4 - 10 s^3 + 35 s^2 - 50 s + 24
  double c[5] = {24, -50, 35, -10, 1};
  double r[4];
  REQUIRE(poly_roots(c, 4, 0, 10, r) == 4);
  for (int i = 0; i < 4; ++i) CHECK(r[i] == Approx(i + 1).epsilon(1e-14));
  REQUIRE(poly_roots(c, 4, 1.5, 3.5, r) == 2);
  CHECK(r[0] == Approx(2.0));
  // Roots 1e-6 apart are still separated.
  double a = 1.0, b = 1.0 + 1e-6;  // (s-a)(s-b)(s^2+1)
  double q[5] = {a * b, -(a + b), a * b + 1, -(a + b), 1};
  REQUIRE(poly_roots(q, 4, 0, 2, r) == 2);
  CHECK(r[0] == Approx(a).epsilon(1e-9));  // the pair is ill-conditioned: 1e-16 / 1e-6
  CHECK(r[1] == Approx(b).epsilon(1e-9));
  // A double root has no sign change: not reported.
  double dbl[5] = {1, -2, 1, 0, 0};  // (s-1)^2 as a quadratic
  CHECK(poly_roots(dbl, 2, 0, 2, r) == 0);
}

TEST_CASE("torus: crossings along x match R +- r, normals point out", "[torus]") {
  Torus tor{2.0, 0.5};
  double t[4];
  Ray ray{Vec3(-5, 0, 0), Vec3(1, 0, 0)};
  REQUIRE(torus_crossings(tor, ray, t) == 4);
  CHECK(t[0] == Approx(5 - 2.5));
  CHECK(t[1] == Approx(5 - 1.5));
  CHECK(t[2] == Approx(5 + 1.5));
  CHECK(t[3] == Approx(5 + 2.5));
  SurfaceHit h;
  REQUIRE(intersect(tor, ray, Interval::positive(), h));
  CHECK(h.t == Approx(2.5));
  CHECK(h.normal.x == Approx(-1.0));
  // Down the y axis: through the hole.
  CHECK(torus_crossings(tor, Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}, t) == 0);
  // Down at x = R: top and bottom of the tube.
  REQUIRE(torus_crossings(tor, Ray{Vec3(2, 5, 0), Vec3(0, -1, 0)}, t) == 2);
  CHECK(t[0] == Approx(4.5));
  CHECK(t[1] == Approx(5.5));
  REQUIRE(intersect(tor, Ray{Vec3(2, 5, 0), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.normal.y == Approx(1.0));
  CHECK(h.has_uv);
}

TEST_CASE("torus: thin tubes from minor/major 1 down to 1e-4 keep their precision", "[torus]") {
  for (double ratio : {1.0, 0.3, 1e-2, 1e-3, 1e-4}) {
    Torus tor{1.0, ratio};
    double t[4];
    // Straight down through the tube at radius R + r/2 from various heights and slopes.
    for (double slope : {0.0, 0.3, 2.0}) {
      Vec3 d = glm::normalize(Vec3(slope * 1e-3 * ratio, -1, 0));
      double x = 1.0 + 0.5 * ratio;
      Ray ray{Vec3(x, 0, 0) - 3.0 * d, d};  // through (x, 0, 0), from 3 units up
      int n = torus_crossings(tor, ray, t);
      INFO("ratio " << ratio << " slope " << slope);
      REQUIRE(n == 2);
      for (int i = 0; i < n; ++i) {
        Vec3 p = ray.at(t[i]);
        CHECK(std::abs(torus_distance(tor, p)) <= 1e-12);
      }
      if (slope == 0.0) CHECK(t[1] - t[0] == Approx(2 * std::sqrt(0.75) * ratio).epsilon(1e-9));
    }
  }
}

TEST_CASE("torus: far from the origin (1e6) through a transform", "[torus]") {
  // The world → object transform of a torus at 1e6: the object-space ray starts 1e6 away.
  Torus tor{1.0, 1e-3};
  Vec3 start(1e6, 1e6, -1e6);
  Vec3 target(1.0, 0.0, 0.0);  // the tube's top... centre of the tube at x = R
  Vec3 d = glm::normalize(target - start);
  double t[4];
  int n = torus_crossings(tor, Ray{start, d}, t);
  REQUIRE(n >= 2);
  for (int i = 0; i < n; ++i) CHECK(std::abs(torus_distance(tor, start + t[i] * d)) <= 1e-9);
}

TEST_CASE("torus: grazing rays are either clean crossings or misses, never NaN", "[torus]") {
  Torus tor{1.0, 0.25};
  double t[4];
  // Rays tangent to the top of the tube (y = r), nudged up and down.
  for (double dy : {-1e-9, -1e-12, 0.0, 1e-12, 1e-9}) {
    Ray ray{Vec3(-5, 0.25 + dy, 0), Vec3(1, 0, 0)};
    int n = torus_crossings(tor, ray, t);
    CHECK(n % 2 == 0);
    for (int i = 0; i < n; ++i) {
      CHECK(std::isfinite(t[i]));
      CHECK(std::abs(torus_distance(tor, ray.at(t[i]))) <= 1e-6);
    }
    if (dy > 0) CHECK(n == 0);
  }
  // Tangent to the outer equator.
  Ray ray{Vec3(-5, 0, 1.25 - 1e-10), Vec3(1, 0, 0)};
  int n = torus_crossings(tor, ray, t);
  CHECK(n % 2 == 0);
  for (int i = 0; i < n; ++i) CHECK(std::isfinite(t[i]));
}
