// The prism against closed forms: a square block, a square with a square hole (even-odd), and
// the rays that break naive polygon tests: through a vertex, touching one, along a wall, in a
// cap's plane, through the rim where a wall meets a cap, and from a million units away.
#include <cmath>

#include <catch2/catch.hpp>

#include "render/geometry/shapes/prism.hpp"

using namespace rts::render;

namespace {

PrismData make(std::vector<Vec3> pts, double h1 = 0.0, double h2 = 2.0, bool open = false) {
  PrismData p;
  p.points = std::move(pts);
  p.height1 = h1;
  p.height2 = h2;
  p.open = open;
  prism_setup(p);
  return p;
}

// [-1, 1] x [0, 2] x [-1, 1], counter-clockwise seen from +y... either way: normals are tested.
PrismData block() { return make({Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 0)}); }

// [-2, 2]^2 with the hole [-1, 1]^2: two sub-polygons, the second clockwise like the first.
PrismData framed() {
  return make({Vec3(-2, -2, 0), Vec3(2, -2, 0), Vec3(2, 2, 0), Vec3(-2, 2, 0), Vec3(-2, -2, 0),
               Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 0)});
}

int crossings(const PrismData& p, const Ray& r, PrismCrossing* c) { return prism_crossings(p, r, c, 8); }

}  // namespace

TEST_CASE("prism: POV-Ray's sub-polygons, the last closed, and tight bounds", "[prism]") {
  CHECK(block().edges.size() == 4);
  CHECK(framed().edges.size() == 8);
  // Not closed: closed by an edge back to the first point, as POV-Ray does (with a warning).
  PrismData open_list = make({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, 1.0, -1.0);
  REQUIRE(open_list.edges.size() == 3);
  CHECK(open_list.edges[2].x0 == 0.0);
  CHECK(open_list.edges[2].z0 == 1.0);
  CHECK(open_list.edges[2].x1 == 0.0);
  CHECK(open_list.edges[2].z1 == 0.0);
  AABB b = bounds(open_list);
  CHECK(b.lo == Vec3(0, -1, 0));
  CHECK(b.hi == Vec3(1, 1, 1));
  CHECK(prism_inside(framed(), Vec3(1.5, 1, 0)));
  CHECK(!prism_inside(framed(), Vec3(0.5, 1, 0)));
  CHECK(!prism_inside(framed(), Vec3(1.5, 2.5, 0)));
}

TEST_CASE("prism: walls and caps where the closed form says, normals out", "[prism]") {
  PrismData p = block();
  PrismCrossing c[8];
  Ray side{Vec3(-5, 1.25, 0.3), Vec3(1, 0, 0)};
  REQUIRE(crossings(p, side, c) == 2);
  CHECK(c[0].t == 4.0);
  CHECK(c[1].t == 6.0);
  SurfaceHit h;
  REQUIRE(intersect(p, side, Interval::positive(), h));
  CHECK(h.normal == Vec3(-1, 0, 0));
  CHECK(h.point.x == -1.0);
  REQUIRE(intersect(p, Ray{Vec3(0.2, 1, 5), Vec3(0, 0, -2)}, Interval::positive(), h));
  CHECK(h.t == 2.0);
  CHECK(h.normal == Vec3(0, 0, 1));

  // Down through both caps, and up.
  Ray down{Vec3(0.1, 10, 0.2), Vec3(0, -2, 0)};
  REQUIRE(crossings(p, down, c) == 2);
  CHECK(c[0].part == PrismPart::Top);
  CHECK(c[0].t == 4.0);
  CHECK(c[1].part == PrismPart::Bottom);
  CHECK(c[1].t == 5.0);
  REQUIRE(intersect(p, down, Interval::positive(), h));
  CHECK(h.normal == Vec3(0, 1, 0));
  CHECK(h.point.y == 2.0);
  REQUIRE(intersect(p, Ray{Vec3(0.1, -10, 0.2), Vec3(0, 1, 0)}, Interval::positive(), h));
  CHECK(h.normal == Vec3(0, -1, 0));
  CHECK(crossings(p, Ray{Vec3(1.5, 10, 0.2), Vec3(0, -1, 0)}, c) == 0);

  // Slanted: in through the top cap, out through the wall x = 1.
  REQUIRE(crossings(p, Ray{Vec3(0, 3, 0), Vec3(1, -1, 0)}, c) == 2);
  CHECK(c[0].part == PrismPart::Top);
  CHECK(c[0].t == Approx(1.0).epsilon(1e-15));
  CHECK(c[1].part == PrismPart::Wall);
  CHECK(c[1].t == Approx(1.0).epsilon(1e-15));  // the rim (1, 2): in and out at once
  REQUIRE(crossings(p, Ray{Vec3(0, 2.5, 0), Vec3(1, -1, 0)}, c) == 2);
  CHECK(c[0].t == Approx(0.5).epsilon(1e-15));
  CHECK(c[1].t == Approx(1.0).epsilon(1e-15));
  CHECK(c[1].part == PrismPart::Wall);

  // Open: only the walls.
  PrismData o = make({Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)}, 0.0, 2.0, true);
  CHECK(crossings(o, down, c) == 0);
  CHECK(crossings(o, side, c) == 2);
}

TEST_CASE("prism: even-odd with a hole, normals facing out of the solid into the hole", "[prism]") {
  PrismData p = framed();
  PrismCrossing c[8];
  Ray r{Vec3(-5, 1, 0.25), Vec3(1, 0, 0)};
  REQUIRE(crossings(p, r, c) == 4);
  const double want[] = {3, 4, 6, 7};
  const double nx[] = {-1, 1, -1, 1};
  for (int i = 0; i < 4; ++i) {
    CHECK(c[i].t == want[i]);
    SurfaceHit h;
    prism_hit_at(p, r, c[i], h);
    CHECK(h.normal == Vec3(nx[i], 0, 0));
  }
  CHECK(crossings(p, Ray{Vec3(0.5, 10, 0.5), Vec3(0, -1, 0)}, c) == 0);  // down the hole
  CHECK(crossings(p, Ray{Vec3(1.5, 10, 0.5), Vec3(0, -1, 0)}, c) == 2);
  // Slanted down into the hole from above the frame: top cap, then the hole's wall.
  REQUIRE(crossings(p, Ray{Vec3(1.5, 3, 0), Vec3(-1, -4, 0)}, c) == 2);
  CHECK(c[0].part == PrismPart::Top);
  CHECK(c[0].t == Approx(0.25).epsilon(1e-15));
  CHECK(c[1].part == PrismPart::Wall);
  CHECK(c[1].t == Approx(0.5).epsilon(1e-15));
  // Through the hole's rim (1, 2): in through the cap and out through the wall at once.
  CHECK(crossings(p, Ray{Vec3(1.5, 3, 0), Vec3(-1, -2, 0)}, c) % 2 == 0);
}

TEST_CASE("prism: rays through a vertex, touching one, along a wall and in a cap's plane pair up", "[prism]") {
  PrismData sq = block();
  PrismCrossing c[8];
  // Diagonally through two corners.
  REQUIRE(crossings(sq, Ray{Vec3(-3, 1, -3), Vec3(1, 0, 1)}, c) == 2);
  CHECK(c[0].t == 2.0);
  CHECK(c[1].t == 4.0);
  // A diamond touched at its tip: no crossing or two, never one.
  PrismData diamond = make({Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(1, 0, 0)});
  for (double dir : {1.0, -1.0}) {
    CHECK(crossings(diamond, Ray{Vec3(-3 * dir, 1, 1), Vec3(dir, 0, 0)}, c) % 2 == 0);
    CHECK(crossings(diamond, Ray{Vec3(-3 * dir, 1, -1), Vec3(dir, 0, 0)}, c) % 2 == 0);
  }
  // Through the diamond's two side tips: in at one, out at the other.
  CHECK(crossings(diamond, Ray{Vec3(-3, 1, 0), Vec3(1, 0, 0)}, c) == 2);
  // Along the walls x = 1 and x = -1, and the cap planes y = 0 and y = 2: pairs, finite.
  for (double x : {-1.0, 1.0})
    for (double y : {0.0, 1.0, 2.0}) {
      for (Vec3 dir : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(0, 0.5, 1)}) {
        int n = crossings(sq, Ray{Vec3(x, y, -5 * dir.z), dir}, c);
        CHECK(n % 2 == 0);
        for (int i = 0; i < n; ++i) CHECK(std::isfinite(c[i].t));
      }
    }
  for (double y : {0.0, 2.0}) CHECK(crossings(sq, Ray{Vec3(-5, y, 0.3), Vec3(1, 0, 0)}, c) == 2);
  for (double y : {-1e-12, 2.0 + 1e-12}) CHECK(crossings(sq, Ray{Vec3(-5, y, 0.3), Vec3(1, 0, 0)}, c) == 0);
  // Nearly vertical: the caps, not the walls far away along the line.
  REQUIRE(crossings(sq, Ray{Vec3(0.3, 5, 0.3), Vec3(1e-170, -1, 1e-170)}, c) == 2);
  CHECK(c[0].part == PrismPart::Top);
}

TEST_CASE("prism: slanted rays from near and far cross where the closed form says", "[prism]") {
  PrismData p = framed();
  for (double dist : {6.0, 1e3, 1e6}) {
    for (int i = 0; i < 60; ++i) {
      Vec3 target(1.5 * std::sin(i), 0.1 + 1.8 * (i % 7) / 6.0, 1.5 * std::cos(3 * i));
      Vec3 dir = glm::normalize(Vec3(std::cos(1.7 * i), 0.8 * std::sin(2.3 * i), std::sin(1.7 * i)));
      Ray ray{target - dist * dir, dir};
      PrismCrossing c[8];
      int n = crossings(p, ray, c);
      INFO("dist " << dist << " ray " << i);
      REQUIRE(n % 2 == 0);
      for (int k = 0; k < n; ++k) {
        Vec3 q = ray.at(c[k].t);
        double tol = 1e-12 * dist + 1e-12;
        if (c[k].part == PrismPart::Wall) {
          double ax = std::abs(q.x), az = std::abs(q.z);
          bool on = (std::abs(ax - 2) < tol && az <= 2 + tol) || (std::abs(az - 2) < tol && ax <= 2 + tol) ||
                    (std::abs(ax - 1) < tol && az <= 1 + tol) || (std::abs(az - 1) < tol && ax <= 1 + tol);
          CHECK(on);
          CHECK(q.y >= -tol);
          CHECK(q.y <= 2 + tol);
        } else {
          CHECK(std::abs(q.y - (c[k].part == PrismPart::Bottom ? 0.0 : 2.0)) < tol);
        }
      }
      // Inside between each pair, as the even-odd test says.
      for (int k = 0; k + 1 < n; k += 2)
        if (c[k + 1].t - c[k].t > 1e-6) CHECK(prism_inside(p, ray.at(0.5 * (c[k].t + c[k + 1].t))));
    }
  }
}

// Spline outlines (POV-Ray's quadratic_spline, cubic_spline, bezier_spline).
namespace {

PrismData make_spline(SplineKind k, std::vector<Vec3> pts, double h1 = 0.0, double h2 = 2.0) {
  PrismData p;
  p.spline = k;
  p.points = std::move(pts);
  p.height1 = h1;
  p.height2 = h2;
  prism_setup(p);
  return p;
}

// The block's square as bezier segments whose control points lie on its sides.
PrismData block_bezier() {
  std::vector<Vec3> c = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 0)};
  std::vector<Vec3> pts;
  for (int i = 0; i < 4; ++i) {
    Vec3 a = c[i], b = c[i + 1];
    pts.insert(pts.end(), {a, a + (b - a) / 3.0, a + 2.0 * (b - a) / 3.0, b});
  }
  return make_spline(SplineKind::Bezier, pts);
}

// A rounded blob with a round hole, as a cubic spline: each sub-outline a control point, the
// loop, its first point again and a control point (POV-Ray's rule).
PrismData blob_with_hole(bool reverse_hole) {
  std::vector<Vec3> outer = {Vec3(1.5, 0.2, 0), Vec3(0.8, -1.1, 0), Vec3(-1.2, -1, 0), Vec3(-1.4, 0.9, 0),
                             Vec3(0.3, 1.3, 0)};
  std::vector<Vec3> hole = {Vec3(0.4, 0, 0), Vec3(0, 0.4, 0), Vec3(-0.4, 0, 0), Vec3(0, -0.4, 0)};
  if (reverse_hole) std::reverse(hole.begin(), hole.end());
  std::vector<Vec3> pts;
  auto loop = [&](const std::vector<Vec3>& l) {
    pts.push_back(l.back());
    pts.insert(pts.end(), l.begin(), l.end());
    pts.push_back(l[0]);
    pts.push_back(l[1]);
  };
  loop(outer);
  loop(hole);
  return make_spline(SplineKind::Cubic, pts);
}

}  // namespace

TEST_CASE("prism splines: a bezier outline along straight sides is the linear prism", "[prism]") {
  PrismData lin = block(), bez = block_bezier();
  REQUIRE(bez.curves.size() == 4);
  CHECK(bez.x_min == Approx(-1.0).epsilon(1e-8));
  CHECK(bez.z_max == Approx(1.0).epsilon(1e-8));
  for (double dist : {3.0, 1e6}) {
    for (int i = 0; i < 60; ++i) {
      Vec3 target(0.5 * std::sin(i), 1.0 + 0.8 * std::cos(2.1 * i), 0.5 * std::cos(3 * i));
      double climb = i % 4 == 0 ? 0.0 : 0.9 * std::sin(2.3 * i);
      Vec3 dir = glm::normalize(Vec3(std::cos(1.7 * i), climb, std::sin(1.7 * i)));
      Ray ray{target - dist * dir, dir};
      PrismCrossing a[8], b[8];
      int na = crossings(lin, ray, a), nb = crossings(bez, ray, b);
      INFO("dist " << dist << " ray " << i);
      REQUIRE(na == nb);
      for (int k = 0; k < na; ++k) {
        CHECK(a[k].part == b[k].part);
        CHECK(std::abs(a[k].t - b[k].t) < 1e-9 * dist);
        SurfaceHit ha, hb;
        prism_hit_at(lin, ray, a[k], ha);
        prism_hit_at(bez, ray, b[k], hb);
        CHECK(glm::length(ha.normal - hb.normal) < 1e-9);
      }
    }
  }
}

TEST_CASE("prism splines: walls on the curve, normals unit and outward, caps by even-odd", "[prism]") {
  for (bool reverse_hole : {false, true}) {
    PrismData p = blob_with_hole(reverse_hole);
    REQUIRE(p.curves.size() == 9);  // 5 round the outside, 4 round the hole
    // Down the hole: nothing; down the body: the two caps.
    PrismCrossing c[8];
    CHECK(crossings(p, Ray{Vec3(0.05, 5, 0.02), Vec3(0, -1, 0)}, c) == 0);
    REQUIRE(crossings(p, Ray{Vec3(-0.9, 5, 0.1), Vec3(0, -1, 0)}, c) == 2);
    CHECK(c[0].part == PrismPart::Top);
    CHECK(c[0].t == Approx(3.0).epsilon(1e-14));
    int walls = 0;
    for (double dist : {3.0, 1e3, 1e6}) {
      for (int i = 0; i < 80; ++i) {
        Vec3 target(0.6 * std::sin(i), 1.0 + 0.6 * std::cos(2.1 * i), 0.6 * std::cos(3 * i));
        double climb = i % 4 == 0 ? 0.0 : 0.9 * std::sin(2.3 * i);
        Vec3 dir = glm::normalize(Vec3(std::cos(1.7 * i), climb, std::sin(1.7 * i)));
        Ray ray{target - dist * dir, dir};
        int n = crossings(p, ray, c);
        INFO("hole reversed " << reverse_hole << " dist " << dist << " ray " << i);
        CHECK(n % 2 == 0);
        for (int k = 0; k < n; ++k) {
          SurfaceHit h;
          prism_hit_at(p, ray, c[k], h);
          CHECK(std::abs(glm::length(h.normal) - 1.0) < 1e-12);
          CHECK(glm::dot(h.normal, ray.direction) * (k % 2 == 0 ? 1 : -1) < 0.0);  // in against it, out along it
          if (c[k].part != PrismPart::Wall) continue;
          ++walls;
          const SplineSegment& g = p.curves[c[k].edge];
          Vec3 q = ray.at(c[k].t);
          double tolerance = 1e-9 + 1e-15 * dist;
          CHECK(std::abs(q.x - spline_eval(g.x, c[k].w)) < tolerance);
          CHECK(std::abs(q.z - spline_eval(g.y, c[k].w)) < tolerance);
          CHECK(prism_inside(p, q - 1e-6 * h.normal));
          CHECK_FALSE(prism_inside(p, q + 1e-6 * h.normal));
        }
      }
    }
    CHECK(walls > 100);
  }
}

TEST_CASE("prism splines: POV-Ray's closing rule; an unclosed outline has no curves", "[prism]") {
  // Quadratic: a control point, then the loop back to its first point.
  PrismData q = make_spline(SplineKind::Quadratic,
                        {Vec3(-1, 1, 0), Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 0)});
  CHECK(q.curves.size() == 4);
  PrismCrossing c[8];
  CHECK(crossings(q, Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}, c) == 2);
  PrismData open = make_spline(SplineKind::Quadratic,
                           {Vec3(-1, 1, 0), Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(0, 0, 0)});
  CHECK(open.curves.empty());
  CHECK(crossings(open, Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}, c) == 0);
  PrismData probe;
  probe.spline = SplineKind::Cubic;
  probe.points = {Vec3(-1, 1, 0), Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 0)};
  // The loop closes at the last point, but a cubic needs a control point after it.
  CHECK(detail::prism_spline_curves(probe).find("does not close (a later point must repeat point 2, followed by one "
                                                "control point)") != std::string::npos);
  probe.spline = SplineKind::Bezier;
  probe.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  CHECK(detail::prism_spline_curves(probe).find("does not end where it starts") != std::string::npos);
}

TEST_CASE("prism conic_sweep: a square outline swept from the apex is a pyramid's frustum", "[prism]") {
  auto square = [](bool bezier, double h1, double h2) {
    PrismData p = bezier ? block_bezier() : block();
    p.height1 = h1;
    p.height2 = h2;
    p.conic = true;
    prism_setup(p);
    return p;
  };
  for (bool bezier : {false, true}) {
    INFO("bezier " << bezier);
    PrismData p = square(bezier, 0.5, 1.0);
    CHECK(p.x_min == Approx(-1.0).epsilon(1e-8));
    CHECK(p.x_max == Approx(1.0).epsilon(1e-8));
    // Across at y = 0.75: the walls |x| = y.
    PrismCrossing c[8];
    REQUIRE(crossings(p, Ray{Vec3(-5, 0.75, 0), Vec3(1, 0, 0)}, c) == 2);
    CHECK(c[0].t == Approx(4.25).epsilon(1e-12));
    CHECK(c[1].t == Approx(5.75).epsilon(1e-12));
    SurfaceHit h;
    prism_hit_at(p, Ray{Vec3(-5, 0.75, 0), Vec3(1, 0, 0)}, c[0], h);
    CHECK(h.normal.x == Approx(-std::sqrt(0.5)).epsilon(1e-12));
    CHECK(h.normal.y == Approx(-std::sqrt(0.5)).epsilon(1e-12));  // the wall leans out: it faces down
    // Down through the middle: the top cap (y = 1) and the bottom one (y = 0.5).
    REQUIRE(crossings(p, Ray{Vec3(0.2, 5, 0.1), Vec3(0, -1, 0)}, c) == 2);
    CHECK(c[0].t == Approx(4.0).epsilon(1e-14));
    CHECK(c[1].t == Approx(4.5).epsilon(1e-14));
    // Down at x = 0.7: through the top cap, out of the leaning wall at y = 0.7.
    REQUIRE(crossings(p, Ray{Vec3(0.7, 5, 0.1), Vec3(0, -1, 0)}, c) == 2);
    CHECK(c[1].part == PrismPart::Wall);
    CHECK(c[1].t == Approx(4.3).epsilon(1e-12));
    CHECK(prism_inside(p, Vec3(0.7, 0.8, 0.1)));
    CHECK_FALSE(prism_inside(p, Vec3(0.7, 0.6, 0.1)));
    // Many rays: crossings pair up, normals face in then out, walls on the swept surface.
    for (int i = 0; i < 80; ++i) {
      Vec3 target(0.4 * std::sin(i), 0.75 + 0.2 * std::cos(2.1 * i), 0.4 * std::cos(3 * i));
      Vec3 dir = glm::normalize(Vec3(std::cos(1.7 * i), 0.9 * std::sin(2.3 * i), std::sin(1.7 * i)));
      Ray ray{target - 4.0 * dir, dir};
      int n = crossings(p, ray, c);
      INFO("ray " << i);
      CHECK(n % 2 == 0);
      for (int k = 0; k < n; ++k) {
        prism_hit_at(p, ray, c[k], h);
        CHECK(std::abs(glm::length(h.normal) - 1.0) < 1e-12);
        CHECK(glm::dot(h.normal, ray.direction) * (k % 2 == 0 ? 1 : -1) < 0.0);
        Vec3 q = ray.at(c[k].t);
        if (c[k].part == PrismPart::Wall)
          CHECK(std::abs(std::max(std::abs(q.x), std::abs(q.z)) - q.y) < 1e-12);
      }
    }
  }
}
