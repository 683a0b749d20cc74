// poly (POV-Ray's poly, quartic, cubic): a sphere and a torus written as polynomials give the
// hits of the sphere and torus shapes; the crossings of a line alternate in and out of the
// solid F < 0 as its sign says (CSG's parity); a sextic with six crossings; the builder's
// located errors.
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "render/builder/scene_builder.hpp"
#include "render/geometry/csg/leaf_crossings.hpp"
#include "render/geometry/shapes/poly.hpp"
#include "render/geometry/shapes/sphere.hpp"
#include "render/geometry/shapes/torus.hpp"

using namespace rts::render;

namespace {

// A poly from POV-Ray's list of coefficients.
Poly make_poly(int order, const std::vector<double>& coefficients) {
  REQUIRE(static_cast<int>(coefficients.size()) == poly_coefficient_count(order));
  Poly p;
  p.order = order;
  for_each_poly_term(order, [&](int index, int i, int j, int k) {
    if (coefficients[index] != 0.0)
      p.terms.push_back(PolyTerm{coefficients[index], static_cast<uint8_t>(i), static_cast<uint8_t>(j),
                                 static_cast<uint8_t>(k)});
  });
  return p;
}

// The coefficient list with `c` at the term x^i y^j z^k, added to `list`.
void set_term(int order, std::vector<double>& list, int i, int j, int k, double c) {
  bool found = false;
  for_each_poly_term(order, [&](int index, int a, int b, int d) {
    if (a == i && b == j && d == k) {
      list[index] += c;
      found = true;
    }
  });
  REQUIRE(found);
}

// (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), POV-Ray's torus in the x-z plane.
Poly torus_poly(double R, double r) {
  std::vector<double> c(poly_coefficient_count(4), 0.0);
  const double k = R * R - r * r;
  set_term(4, c, 4, 0, 0, 1);
  set_term(4, c, 0, 4, 0, 1);
  set_term(4, c, 0, 0, 4, 1);
  set_term(4, c, 2, 2, 0, 2);
  set_term(4, c, 2, 0, 2, 2);
  set_term(4, c, 0, 2, 2, 2);
  set_term(4, c, 2, 0, 0, 2 * k - 4 * R * R);
  set_term(4, c, 0, 2, 0, 2 * k);
  set_term(4, c, 0, 0, 2, 2 * k - 4 * R * R);
  set_term(4, c, 0, 0, 0, k * k);
  return make_poly(4, c);
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(Vec3(n(rng), n(rng), n(rng)));
}

}  // namespace

TEST_CASE("poly: POV-Ray's order of the coefficients", "[poly]") {
  std::vector<std::array<int, 3>> terms;
  for_each_poly_term(4, [&](int, int i, int j, int k) { terms.push_back({i, j, k}); });
  REQUIRE(terms.size() == 35);
  CHECK(terms[0] == std::array<int, 3>{4, 0, 0});
  CHECK(terms[3] == std::array<int, 3>{3, 0, 0});   // piriform: 4 x^4 - 4 x^3 + y^2 + z^2
  CHECK(terms[25] == std::array<int, 3>{0, 2, 0});
  CHECK(terms[32] == std::array<int, 3>{0, 0, 2});
  CHECK(terms[34] == std::array<int, 3>{0, 0, 0});
  for (int order = 2; order <= 6; ++order) {
    int n = 0;
    for_each_poly_term(order, [&](int, int, int, int) { ++n; });
    CHECK(n == poly_coefficient_count(order));
  }
}

TEST_CASE("poly: a sphere written as x^2 + y^2 + z^2 - r^2 gives the sphere's hits", "[poly]") {
  const double r = 1.3;
  std::vector<double> c(poly_coefficient_count(2), 0.0);
  set_term(2, c, 2, 0, 0, 1);
  set_term(2, c, 0, 2, 0, 1);
  set_term(2, c, 0, 0, 2, 1);
  set_term(2, c, 0, 0, 0, -r * r);
  const Poly p = make_poly(2, c);
  const Sphere s{Vec3(0.0), r};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 origin = random_unit(rng) * (1.5 + 50.0 * std::abs(u(rng)));
    const Vec3 target = Vec3(u(rng), u(rng), u(rng)) * 1.6;
    const Ray ray{origin, (target - origin) * (0.5 + std::abs(u(rng)))};
    SurfaceHit hp, hs;
    const bool a = intersect(p, ray, Interval::positive(), hp), b = intersect(s, ray, Interval::positive(), hs);
    if (a != b) {  // only a graze may differ: the line then passes the sphere at its radius
      const Vec3 d = glm::normalize(ray.direction);
      const Vec3 closest = ray.origin - glm::dot(ray.origin, d) * d;
      CHECK(std::abs(glm::length(closest) - r) < 1e-6 * r);
      continue;
    }
    if (!a) continue;
    ++hits;
    CHECK(hp.t == Approx(hs.t).epsilon(1e-9));
    CHECK(glm::dot(hp.normal, hs.normal) > 1.0 - 1e-9);
    CHECK(std::abs(poly_value(p, hp.point)) < 1e-9 * (1.0 + glm::dot(hp.point, hp.point)));
  }
  CHECK(hits > 1000);
}

TEST_CASE("poly: POV-Ray's torus as a quartic gives the torus's crossings", "[poly]") {
  for (double ratio : {1.0, 0.25, 0.01}) {
    const double R = 2.0, r = R * ratio;
    CAPTURE(ratio);
    const Poly p = torus_poly(R, r);
    const Torus tor{R, r};
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int lines = 0;
    for (int i = 0; i < 3000; ++i) {
      const Vec3 origin = random_unit(rng) * 8.0;
      // Aim at the tube: a point of its centre circle, moved within the tube's radius.
      const double a = 3.14159 * u(rng);
      const Vec3 target = Vec3(R * std::cos(a), 0.0, R * std::sin(a)) + Vec3(u(rng), u(rng), u(rng)) * r;
      const Ray ray{origin, target - origin};
      double tp[kPolyMaxOrder], tt[4];
      bool inside;
      const int np = poly_crossings(p, ray, tp, inside);
      const int nt = torus_crossings(tor, ray, tt);
      CHECK_FALSE(inside);
      if (np != nt) continue;  // a near-tangent pair one of them resolves: rare
      ++lines;
      for (int k = 0; k < np; ++k) CHECK(tp[k] == Approx(tt[k]).epsilon(ratio < 0.1 ? 1e-6 : 1e-9));
    }
    CHECK(lines > 2900);
  }
}

TEST_CASE("poly: crossings alternate in and out of F < 0, also for a sextic", "[poly]") {
  // A sextic whose x axis meets it six times: (x^2-1)(x^2-4)(x^2-9) + y^2 + z^2.
  std::vector<double> c6(poly_coefficient_count(6), 0.0);
  set_term(6, c6, 6, 0, 0, 1);
  set_term(6, c6, 4, 0, 0, -14);
  set_term(6, c6, 2, 0, 0, 49);
  set_term(6, c6, 0, 0, 0, -36);
  set_term(6, c6, 0, 2, 0, 1);
  set_term(6, c6, 0, 0, 2, 1);
  const Poly sextic = make_poly(6, c6);
  double t[kPolyMaxOrder];
  bool inside;
  REQUIRE(poly_crossings(sextic, Ray{Vec3(-10, 0, 0), Vec3(1, 0, 0)}, t, inside) == 6);
  for (int k = 0; k < 3; ++k) {
    CHECK(t[k] == Approx(10.0 - (3 - k)).epsilon(1e-12));
    CHECK(t[5 - k] == Approx(10.0 + (3 - k)).epsilon(1e-12));
  }
  // A saddle (unbounded): x y - z, and the torus, on random lines: between crossings the sign
  // of F says inside, as the parity from inside_at_start does.
  std::vector<double> c2(poly_coefficient_count(2), 0.0);
  set_term(2, c2, 1, 1, 0, 1);
  set_term(2, c2, 0, 0, 1, -1);
  for (const Poly& p : {sextic, make_poly(2, c2), torus_poly(1.5, 0.5)}) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-4.0, 4.0);
    for (int i = 0; i < 2000; ++i) {
      const Ray ray{Vec3(u(rng), u(rng), u(rng)), random_unit(rng)};
      const int n = poly_crossings(p, ray, t, inside);
      for (int k = 0; k + 1 < n; ++k) {
        CHECK(t[k] < t[k + 1]);
        const double mid = 0.5 * (t[k] + t[k + 1]);
        const bool in = (inside != ((k + 1) % 2 == 1));
        if (t[k + 1] - t[k] > 1e-6) CHECK((poly_value(p, ray.at(mid)) < 0.0) == in);
      }
      if (n > 0) {
        const bool in_after = inside != (n % 2 == 1);
        CHECK((poly_value(p, ray.at(t[n - 1] + 1.0)) < 0.0) == in_after);
      }
      // The CSG listing from a start agrees with the whole line's.
      CsgLeafCrossings listed;
      leaf_crossings_from(p, ray, -Interval::kInfinity, listed);
      CHECK(listed.inside_at_start == inside);
      CHECK(listed.count == std::min(n, kMaxLeafCrossings));
    }
  }
}

TEST_CASE("poly: the builder's located errors", "[poly]") {
  SceneBuilder b;
  auto error_of = [&](double order, std::vector<double> coefficients) -> std::string {
    ParamSet ps("poly", SourceRef{"t.rts", 1, 1});
    ps.add("order", order, SourceRef{"t.rts", 1, 10});
    ps.add("coefficients", std::move(coefficients), SourceRef{"t.rts", 1, 20});
    try {
      b.shape("poly", ps);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  };
  std::vector<double> ten(10, 0.0);
  ten[0] = 1;
  CHECK(error_of(2, ten).empty());
  CHECK(error_of(3, ten).find("a poly of order 3 takes 20 coefficients, got 10") != std::string::npos);
  CHECK(error_of(7, ten).find("poly order must be 2 to 6, got 7") != std::string::npos);
  CHECK(error_of(2.5, ten).find("whole") != std::string::npos);
  std::vector<double> constant(10, 0.0);
  constant[9] = 1;
  CHECK(error_of(2, constant).find("poly has no surface") != std::string::npos);
}
