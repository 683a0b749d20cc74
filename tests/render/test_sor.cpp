// The sor against closed forms: a cone (r linear in h, so r^2 quadratic) and a cylinder are
// fitted exactly by POV-Ray's cubic (its slopes are central differences, exact for linear r); crossings alternate in and out with the caps; normals point out; uv as POV-Ray's;
// rays from far away and grazing rays stay finite; bad points are located errors.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/geometry/shapes/sor.hpp"

using namespace rts::render;

namespace {

SorData make(std::vector<Vec3> pts, bool open = false) {
  SorData s;
  s.points = std::move(pts);
  s.open = open;
  sor_setup(s);
  return s;
}

// r = 1 + h / 2 for h in [0, 2] (points 0 and N-1 on the same line): a cone frustum.
double cone_r(double h) { return 1.0 + 0.5 * h; }
SorData cone() {
  std::vector<Vec3> p;
  for (double h : {-0.5, 0.0, 1.0, 2.0, 2.5}) p.emplace_back(cone_r(h), h, 0.0);
  return make(p);
}

}  // namespace

TEST_CASE("sor: POV-Ray's fit reproduces a cone's r^2 = (1 + h/2)^2, and its bounds", "[sor]") {
  SorData s = cone();
  REQUIRE(s.segments.size() == 2);
  for (const SorSegment& seg : s.segments) {
    CHECK(seg.c[0] == Approx(cone_r(seg.h0) * cone_r(seg.h0)).epsilon(1e-12));
    CHECK(seg.c[1] == Approx(cone_r(seg.h0)).epsilon(1e-12));
    CHECK(seg.c[2] == Approx(0.25).epsilon(1e-12));
    CHECK(seg.c[3] == Approx(0.0).margin(1e-12));
  }
  CHECK(s.radius == Approx(2.0).epsilon(1e-12));
  CHECK(s.h_min == 0.0);
  CHECK(s.h_max == 2.0);
  AABB b = bounds(s);
  CHECK(b.lo.y == 0.0);
  CHECK(b.hi.x == Approx(2.0).epsilon(1e-6));
}

TEST_CASE("sor: crossings of a cone match the closed form, caps included, normals out", "[sor]") {
  SorData s = cone();
  // Horizontal ray at height 1.25: |x| = 1.625.
  SorCrossing c[8];
  int n = sor_crossings(s, Ray{Vec3(-5, 1.25, 0), Vec3(1, 0, 0)}, c, 8);
  REQUIRE(n == 2);
  CHECK(c[0].t == Approx(3.375).epsilon(1e-13));
  CHECK(c[1].t == Approx(6.625).epsilon(1e-13));
  SurfaceHit h;
  REQUIRE(intersect(s, Ray{Vec3(-5, 1.25, 0), Vec3(1, 0, 0)}, Interval::positive(), h));
  // Gradient of x^2 + z^2 - (1 + y/2)^2: (2x, -(1 + y/2), 2z) = (-3.25, -1.625, 0).
  CHECK(h.normal.x == Approx(-2.0 / std::sqrt(5.0)).epsilon(1e-12));
  CHECK(h.normal.y == Approx(-1.0 / std::sqrt(5.0)).epsilon(1e-12));
  CHECK(h.error > 0.0);
  CHECK(h.has_uv);
  CHECK(h.uv.x == Approx(0.5).epsilon(1e-12));             // at -x: half way round
  CHECK(h.uv.y == Approx((0.25 + 1.0) / 2.0).epsilon(1e-12));  // segment 1, a quarter up

  // Down the axis from above: the top disc at y = 2, the bottom disc at y = 0.
  n = sor_crossings(s, Ray{Vec3(0.1, 10, 0.2), Vec3(0, -2, 0)}, c, 8);
  REQUIRE(n == 2);
  CHECK(c[0].part == SorPart::Cap);
  CHECK(c[0].t == Approx(4.0).epsilon(1e-13));
  CHECK(c[1].part == SorPart::Base);
  CHECK(c[1].t == Approx(5.0).epsilon(1e-13));
  REQUIRE(intersect(s, Ray{Vec3(0.1, 10, 0.2), Vec3(0, -2, 0)}, Interval::positive(), h));
  CHECK(h.normal == Vec3(0, 1, 0));
  CHECK(h.point.y == 2.0);
  REQUIRE(intersect(s, Ray{Vec3(0.1, -10, 0.2), Vec3(0, 1, 0)}, Interval::positive(), h));
  CHECK(h.normal == Vec3(0, -1, 0));

  // Open: only the curved surface; the axis ray meets nothing.
  SorData o = cone();
  o.open = true;
  CHECK(sor_crossings(o, Ray{Vec3(0.1, 10, 0.2), Vec3(0, -1, 0)}, c, 8) == 0);
  CHECK(sor_crossings(o, Ray{Vec3(-5, 1.25, 0), Vec3(1, 0, 0)}, c, 8) == 2);
}

TEST_CASE("sor: slanted rays cross a cone where the closed form says, from near and far", "[sor]") {
  SorData s = cone();
  for (double dist : {4.0, 1e3, 1e6}) {
    for (int i = 0; i < 40; ++i) {
      Vec3 target(0.3 * std::sin(i), 0.2 + 1.6 * (i % 7) / 6.0, 0.3 * std::cos(3 * i));
      Vec3 dir = glm::normalize(Vec3(std::cos(1.7 * i), 0.6 * std::sin(2.3 * i), std::sin(1.7 * i)));
      Ray ray{target - dist * dir, dir};
      SorCrossing c[8];
      int n = sor_crossings(s, ray, c, 8);
      INFO("dist " << dist << " ray " << i);
      REQUIRE(n % 2 == 0);
      REQUIRE(n >= 2);
      for (int k = 0; k < n; ++k) {
        Vec3 p = ray.at(c[k].t);
        double tol = 1e-9 * dist + 1e-12;
        if (c[k].part == SorPart::Curve)
          CHECK(std::abs(std::sqrt(p.x * p.x + p.z * p.z) - cone_r(p.y)) < 10 * tol);
        else
          CHECK(std::abs(p.y - (c[k].part == SorPart::Base ? 0.0 : 2.0)) < 10 * tol);
      }
    }
  }
}

TEST_CASE("sor: a cylinder profile, rays grazing its rim and wall give pairs, never NaN", "[sor]") {
  SorData s = make({Vec3(1, -1, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 2, 0), Vec3(1, 3, 0)});
  SorCrossing c[8];
  for (double x : {0.999999, 1.0, 1.000001})
    for (double y : {-0.5, 0.0, 0.5, 1.0, 2.0, 2.5}) {
      int n = sor_crossings(s, Ray{Vec3(x, y, -5), Vec3(0, 0, 1)}, c, 8);
      CHECK(n % 2 == 0);
      for (int i = 0; i < n; ++i) CHECK(std::isfinite(c[i].t));
      if (x > 1.0 || y < 0.0 || y > 2.0) CHECK(n == 0);
    }
  // Across a knot (h = 1) at an angle: two crossings, not three or four.
  int n = sor_crossings(s, Ray{Vec3(-3, -1, 0.2), Vec3(1, 0.6, 0)}, c, 8);
  CHECK(n == 2);
}

TEST_CASE("sor: the waist of an hourglass is crossed four times, caps included", "[sor]") {
  SorData s = make({Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0.2, 1, 0), Vec3(1, 2, 0), Vec3(0, 3, 0)});
  SorCrossing c[8];
  // A vertical ray at radius 0.6 goes in and out of the bottom bulb, then the top one.
  int n = sor_crossings(s, Ray{Vec3(0.6, -2, 0), Vec3(0, 1, 0)}, c, 8);
  CHECK(n == 4);
  for (int i = 0; i + 1 < n; ++i) CHECK(c[i].t < c[i + 1].t);
}
