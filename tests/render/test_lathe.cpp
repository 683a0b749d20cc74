// The lathe (linear_spline) against closed forms: a closed square profile is a thick tube
// (cylinder walls and flat rings), a profile from the axis to the axis through one slanted
// segment is a double cone; crossings alternate in and out, normals point out whichever way
// the profile runs, rays from far away stay on the surface, joints are counted once.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/geometry/shapes/lathe.hpp"

using namespace rts::render;

namespace {

Lathe make(std::vector<Vec3> pts) {
  Lathe l;
  l.points = std::move(pts);
  lathe_setup(l);
  return l;
}

// A tube: radii 1 to 2, heights 0 to 1, the profile's square run counter-clockwise or not.
Lathe tube(bool ccw) {
  std::vector<Vec3> p = {Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 0, 0)};
  if (!ccw) std::reverse(p.begin(), p.end());
  return make(p);
}

}  // namespace

TEST_CASE("lathe: a closed square profile is a tube, whichever way it runs", "[lathe]") {
  for (bool ccw : {true, false}) {
    Lathe l = tube(ccw);
    INFO("ccw " << ccw);
    CHECK(l.closed);
    CHECK(l.radius == 2.0);
    // Across the middle: in at x = -2, out at -1, in at 1, out at 2.
    LatheCrossing c[8];
    int n = lathe_crossings(l, Ray{Vec3(-5, 0.5, 0), Vec3(1, 0, 0)}, c, 8);
    REQUIRE(n == 4);
    CHECK(c[0].t == Approx(3.0).epsilon(1e-14));
    CHECK(c[1].t == Approx(4.0).epsilon(1e-14));
    CHECK(c[2].t == Approx(6.0).epsilon(1e-14));
    CHECK(c[3].t == Approx(7.0).epsilon(1e-14));
    SurfaceHit h;
    REQUIRE(intersect(l, Ray{Vec3(-5, 0.5, 0), Vec3(1, 0, 0)}, Interval::positive(), h));
    CHECK(h.normal.x == Approx(-1.0).epsilon(1e-14));  // the outer wall faces out
    REQUIRE(intersect(l, Ray{Vec3(-5, 0.5, 0), Vec3(1, 0, 0)}, Interval(4.5, 100), h));
    CHECK(h.normal.x == Approx(-1.0).epsilon(1e-14));  // the inner wall at x = 1 faces the hole (-x)
    CHECK(h.has_uv);
    // From above onto the top ring, and down the hole: nothing.
    REQUIRE(intersect(l, Ray{Vec3(1.5, 5, 0), Vec3(0, -1, 0)}, Interval::positive(), h));
    CHECK(h.t == Approx(4.0).epsilon(1e-14));
    CHECK(h.normal.y == Approx(1.0).epsilon(1e-14));
    CHECK(h.point.y == 1.0);
    CHECK(lathe_crossings(l, Ray{Vec3(0.5, 5, 0), Vec3(0, -1, 0)}, c, 8) == 0);
    CHECK(lathe_crossings(l, Ray{Vec3(1.5, 5, 0.1), Vec3(0, -1, 0)}, c, 8) == 2);
  }
}

TEST_CASE("lathe: a double cone from the axis to the axis; slanted rays from near and far", "[lathe]") {
  // r = 1 - |y|: points (0, -1), (1, 0), (0, 1).
  Lathe l = make({Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)});
  CHECK(l.closed);
  for (double dist : {3.0, 1e3, 1e6}) {
    for (int i = 0; i < 40; ++i) {
      Vec3 target(0.2 * std::sin(i), 0.5 * std::cos(2.1 * i), 0.2 * std::cos(3 * i));
      Vec3 dir = glm::normalize(Vec3(std::cos(1.7 * i), 0.7 * std::sin(2.3 * i), std::sin(1.7 * i)));
      Ray ray{target - dist * dir, dir};
      LatheCrossing c[8];
      int n = lathe_crossings(l, ray, c, 8);
      INFO("dist " << dist << " ray " << i);
      CHECK(n == 2);
      for (int k = 0; k < n; ++k) {
        Vec3 p = ray.at(c[k].t);
        CHECK(std::abs(std::sqrt(p.x * p.x + p.z * p.z) - (1.0 - std::abs(p.y))) < 1e-8 * dist + 1e-12);
        SurfaceHit h;
        lathe_hit_at(l, ray, c[k], h);
        CHECK(glm::dot(h.normal, ray.direction) * (k == 0 ? 1 : -1) < 0.0);  // in against it, out along it
      }
    }
  }
  // Through the joint circle at y = 0 exactly: one crossing there, not two.
  LatheCrossing c[8];
  CHECK(lathe_crossings(l, Ray{Vec3(-3, 0, 0.2), Vec3(1, 0, 0)}, c, 8) == 2);
}

TEST_CASE("lathe: an unclosed profile is open; ends on the axis close it", "[lathe]") {
  CHECK_FALSE(make({Vec3(1, 0, 0), Vec3(1, 1, 0)}).closed);
  CHECK(make({Vec3(0, 0, 0), Vec3(1, 0.5, 0), Vec3(0, 1, 0)}).closed);
}
