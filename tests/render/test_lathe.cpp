// The lathe (linear_spline) against closed forms: a closed square profile is a thick tube
// (cylinder walls and flat rings), a profile from the axis to the axis through one slanted
// segment is a double cone; crossings alternate in and out, normals point out whichever way
// the profile runs, rays from far away stay on the surface, joints are counted once.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/geometry/shapes/lathe.hpp"

using namespace rts::render;

namespace {

LatheData make(std::vector<Vec3> pts) {
  LatheData l;
  l.points = std::move(pts);
  lathe_setup(l);
  return l;
}

// A tube: radii 1 to 2, heights 0 to 1, the profile's square run counter-clockwise or not.
LatheData tube(bool ccw) {
  std::vector<Vec3> p = {Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0), Vec3(1, 0, 0)};
  if (!ccw) std::reverse(p.begin(), p.end());
  return make(p);
}

}  // namespace

TEST_CASE("lathe: a closed square profile is a tube, whichever way it runs", "[lathe]") {
  for (bool ccw : {true, false}) {
    LatheData l = tube(ccw);
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
  LatheData l = make({Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)});
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

// Splines (POV-Ray's quadratic_spline, cubic_spline, bezier_spline).
namespace {

LatheData make_spline(SplineKind k, std::vector<Vec3> pts) {
  LatheData l;
  l.spline = k;
  l.points = std::move(pts);
  lathe_setup(l);
  return l;
}

// Rays at a target near the middle of the shape, from `dist` away, in many directions (some
// nearly horizontal: dy of 1e-3 down to 0).
Ray probe(int i, double dist) {
  Vec3 target(0.2 * std::sin(i), 0.5 * std::cos(2.1 * i), 0.2 * std::cos(3 * i));
  double climb = i % 5 == 0 ? 0.0 : i % 5 == 1 ? 1e-9 : i % 5 == 2 ? 3e-5 : 0.7 * std::sin(2.3 * i);
  Vec3 dir = glm::normalize(Vec3(std::cos(1.7 * i), climb, std::sin(1.7 * i)));
  return Ray{target - dist * dir, dir};
}

// The double cone r = 1 - |y| as two bezier segments whose control points lie on the lines.
std::vector<Vec3> cone_bezier() {
  return {Vec3(0, -1, 0), Vec3(1.0 / 3, -2.0 / 3, 0), Vec3(2.0 / 3, -1.0 / 3, 0), Vec3(1, 0, 0),
          Vec3(1, 0, 0),  Vec3(2.0 / 3, 1.0 / 3, 0),  Vec3(1.0 / 3, 2.0 / 3, 0),  Vec3(0, 1, 0)};
}

// A vase: a cubic spline from the axis at y = -1 to the axis at y = 1 (the first and last
// points only set the end tangents).
std::vector<Vec3> vase() {
  return {Vec3(0.5, -1.5, 0), Vec3(0, -1, 0),  Vec3(0.8, -0.5, 0), Vec3(0.6, 0.3, 0),
          Vec3(1.0, 0.8, 0),  Vec3(0, 1, 0),   Vec3(0.5, 1.5, 0)};
}

}  // namespace

TEST_CASE("lathe splines: segments follow POV-Ray's conventions", "[lathe]") {
  std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 1, 0), Vec3(1, 2, 0), Vec3(0, 3, 0)};
  // Quadratic: N - 2 segments from P[1]; cubic: N - 3 segments from P[1] to P[N-2].
  std::vector<SplineSegment> q = spline_segments(SplineKind::Quadratic, p);
  REQUIRE(q.size() == 3);
  CHECK(spline_eval(q[0].x, 0.0) == 1.0);
  CHECK(spline_eval(q[0].x, 1.0) == Approx(2.0).epsilon(1e-15));
  CHECK(spline_eval(q[2].y, 1.0) == Approx(3.0).epsilon(1e-15));
  std::vector<SplineSegment> c = spline_segments(SplineKind::Cubic, p);
  REQUIRE(c.size() == 2);
  CHECK(spline_eval(c[0].x, 0.0) == 1.0);
  CHECK(spline_eval(c[1].x, 1.0) == Approx(1.0).epsilon(1e-15));
  CHECK(spline_eval(c[1].y, 1.0) == Approx(2.0).epsilon(1e-15));
  // Catmull-Rom tangent at P[1]: (P[2] - P[0]) / 2.
  CHECK(spline_slope(c[0].x, 0.0) == 1.0);
  CHECK(spline_slope(c[0].y, 0.0) == 0.5);
  std::vector<SplineSegment> b = spline_segments(SplineKind::Bezier, cone_bezier());
  REQUIRE(b.size() == 2);
  CHECK(spline_eval(b[0].x, 1.0) == Approx(1.0).epsilon(1e-15));
  CHECK(spline_eval(b[0].x, 0.5) == Approx(0.5).epsilon(1e-15));  // on the line: uniform speed
  // Bounds from the turning points: the bulge between P[1] and P[2] reaches past both.
  CHECK(c[0].x_hi > 2.0);
  CHECK(c[0].x_hi < 2.1);
  CHECK(spline_count_problem(SplineKind::Bezier, 6, 2).find("multiple of 4") != std::string::npos);
  CHECK(spline_count_problem(SplineKind::Cubic, 3, 2).find("at least 4") != std::string::npos);
  CHECK(spline_count_problem(SplineKind::Quadratic, 3, 2).empty());
}

TEST_CASE("lathe splines: a bezier lathe along straight lines is the linear lathe", "[lathe]") {
  LatheData lin = make({Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)});
  LatheData bez = make_spline(SplineKind::Bezier, cone_bezier());
  CHECK(bez.closed);
  CHECK(bez.radius == Approx(1.0).epsilon(1e-8));
  for (double dist : {3.0, 1e3, 1e6}) {
    for (int i = 0; i < 60; ++i) {
      Ray ray = probe(i, dist);
      LatheCrossing a[8], b[8];
      int na = lathe_crossings(lin, ray, a, 8), nb = lathe_crossings(bez, ray, b, 8);
      INFO("dist " << dist << " ray " << i);
      REQUIRE(na == nb);
      for (int k = 0; k < na; ++k) {
        CHECK(std::abs(a[k].t - b[k].t) < 1e-9 * dist);
        SurfaceHit ha, hb;
        lathe_hit_at(lin, ray, a[k], ha);
        lathe_hit_at(bez, ray, b[k], hb);
        CHECK(glm::length(ha.normal - hb.normal) < 1e-6);
      }
    }
  }
}

TEST_CASE("lathe splines: hits lie on the surface of revolution, normals unit and outward, near and far",
          "[lathe]") {
  struct Case {
    SplineKind kind;
    std::vector<Vec3> pts;
  };
  std::vector<Case> cases = {
      {SplineKind::Cubic, vase()},
      {SplineKind::Quadratic, {Vec3(0.3, -1.4, 0), Vec3(0, -1, 0), Vec3(0.9, -0.4, 0), Vec3(0.7, 0.5, 0), Vec3(0, 1, 0)}},
      {SplineKind::Bezier,
       {Vec3(0, -1, 0), Vec3(1.4, -1, 0), Vec3(0.2, 0, 0), Vec3(0.8, 0.2, 0), Vec3(0.8, 0.2, 0), Vec3(1.3, 0.5, 0),
        Vec3(0.9, 1, 0), Vec3(0, 1, 0)}},
  };
  for (const Case& cs : cases) {
    for (bool reversed : {false, true}) {
      std::vector<Vec3> pts = cs.pts;
      if (reversed) {
        std::reverse(pts.begin(), pts.end());
        // A quadratic's first point is its control point: the reversed curve needs a new one.
        if (cs.kind == SplineKind::Quadratic) {
          pts.insert(pts.begin(), Vec3(0.3, 1.4, 0));
          pts.pop_back();
        }
      }
      LatheData l = make_spline(cs.kind, pts);
      REQUIRE(l.closed);
      int hits = 0;
      for (double dist : {3.0, 1e3, 1e6}) {
        for (int i = 0; i < 80; ++i) {
          Ray ray = probe(i, dist);
          LatheCrossing c[8];
          int n = lathe_crossings(l, ray, c, 8);
          INFO("kind " << int(cs.kind) << " reversed " << reversed << " dist " << dist << " ray " << i);
          CHECK(n % 2 == 0);
          hits += n;
          for (int k = 0; k < n; ++k) {
            REQUIRE(std::isfinite(c[k].t));
            const SplineSegment& g = l.segments[c[k].segment];
            Vec3 p = ray.at(c[k].t);
            // On the profile at the crossing's own w, to the ray's own rounding.
            double tolerance = 1e-9 + 1e-15 * dist;
            CHECK(std::abs(std::sqrt(p.x * p.x + p.z * p.z) - std::abs(spline_eval(g.x, c[k].w))) < tolerance);
            CHECK(std::abs(p.y - spline_eval(g.y, c[k].w)) < tolerance);
            SurfaceHit h;
            lathe_hit_at(l, ray, c[k], h);
            CHECK(std::abs(glm::length(h.normal) - 1.0) < 1e-12);
            CHECK(glm::dot(h.normal, ray.direction) * (k % 2 == 0 ? 1 : -1) < 0.0);  // in against it, out along it
            CHECK(h.error >= 0.0);
            CHECK(h.error < 1e-6 + 1e-12 * dist);
          }
          if (n >= 2) {
            SurfaceHit h;
            REQUIRE(intersect(l, ray, Interval::positive(), h));
            CHECK(h.t == c[0].t);
          }
        }
      }
      CHECK(hits > 150);  // most probes go through
    }
  }
}

TEST_CASE("lathe splines: grazing and horizontal rays never give NaN", "[lathe]") {
  LatheData l = make_spline(SplineKind::Cubic, vase());
  // Along the axis, through the tips, tangent to the widest circle, exactly horizontal at a
  // joint's height, and in the plane of a flat top.
  std::vector<Ray> rays = {Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)},         Ray{Vec3(0, -1, -5), Vec3(0, 0, 1)},
                           Ray{Vec3(-5, 0.3, 0.6), Vec3(1, 0, 0)},      Ray{Vec3(-5, -0.5, 0), Vec3(1, 0, 0)},
                           Ray{Vec3(-5, 1, 0), Vec3(1, 0, 0)},          Ray{Vec3(-5, 0.3, 0), Vec3(1, 1e-300, 0)},
                           Ray{Vec3(1e8, 0.2, 0), Vec3(-1, 1e-12, 0)}};
  for (double x = 0.0; x < 1.3; x += 0.01) rays.push_back(Ray{Vec3(x, 5, 0.01), Vec3(0, -1, 0)});
  for (const Ray& ray : rays) {
    LatheCrossing c[8];
    int n = lathe_crossings(l, ray, c, 8);
    for (int k = 0; k < n; ++k) {
      REQUIRE(std::isfinite(c[k].t));
      SurfaceHit h;
      lathe_hit_at(l, ray, c[k], h);
      CHECK(std::isfinite(h.normal.x));
      CHECK(std::isfinite(h.normal.y));
      CHECK(std::isfinite(h.error));
    }
  }
  // Straight down through the body: in at the top surface, out at the bottom.
  LatheCrossing c[8];
  CHECK(lathe_crossings(l, Ray{Vec3(0.3, 5, 0.01), Vec3(0, -1, 0)}, c, 8) == 2);
}

TEST_CASE("lathe splines: open and closed as POV-Ray", "[lathe]") {
  // Cubic: the curve runs from P[1] to P[N-2].
  CHECK(make_spline(SplineKind::Cubic, vase()).closed);
  CHECK_FALSE(make_spline(SplineKind::Cubic, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}).closed);
  CHECK(make_spline(SplineKind::Quadratic, {Vec3(1, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 2, 0)}).closed);
  CHECK_FALSE(make_spline(SplineKind::Bezier, {Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(1, 2, 0), Vec3(1, 3, 0)}).closed);
}

TEST_CASE("lathe splines: rays just either side of the horizontal solve agree", "[lathe]") {
  // Below kLatheFlatRay the ray is solved as horizontal first, above it by the sextic: the
  // crossings on either side of the switch are the same to the rays' own difference.
  LatheData l = make_spline(SplineKind::Cubic, vase());
  for (int i = 0; i < 40; ++i) {
    Vec3 target(0.3 * std::sin(i), 0.9 * std::cos(2.1 * i), 0.3 * std::cos(3 * i));
    double below = 0.99 * tol::kLatheFlatRay, above = 1.01 * tol::kLatheFlatRay;
    Vec3 d0 = glm::normalize(Vec3(std::cos(1.7 * i), below, std::sin(1.7 * i)));
    Vec3 d1 = glm::normalize(Vec3(std::cos(1.7 * i), above, std::sin(1.7 * i)));
    Ray r0{target - 3.0 * d0, d0}, r1{target - 3.0 * d1, d1};
    LatheCrossing a[8], b[8];
    int na = lathe_crossings(l, r0, a, 8), nb = lathe_crossings(l, r1, b, 8);
    INFO("ray " << i);
    REQUIRE(na == nb);
    for (int k = 0; k < na; ++k) {
      CHECK(std::abs(a[k].t - b[k].t) < 1e-3);
      Vec3 p = r0.at(a[k].t);
      const SplineSegment& g = l.segments[a[k].segment];
      CHECK(std::abs(p.y - spline_eval(g.y, a[k].w)) < 1e-9);
    }
  }
}
