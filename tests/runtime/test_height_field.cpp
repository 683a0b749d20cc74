// height_field from the language: closed-form hits on a grid that is exactly a plane, an
// image's orientation (POV-Ray's: the bottom row at z = 0), the solid's crossings for CSG
// (walls, surface, water), a CSG block through World, the block-and-cell walk against every
// triangle tested one by one, and bad parameters as located errors.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "eval_helpers.hpp"
#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"
#include "render/geometry/csg/leaf_crossings.hpp"
#include "render/geometry/shapes/height_field.hpp"
#include "render/image/image.hpp"

using namespace rts;
using rts::test::eval_diagnostic;
using rts::test::eval_text;
using render::Interval;
using render::Ray;
using render::Vec3;

namespace {
const render::HeightField& only_height_field(const render::SceneDesc& s) {
  for (const render::ShapeDesc& d : s.shapes)
    if (const auto* g = shape_if<render::HeightField>(d.geometry)) return *g;
  FAIL("no height_field in the scene");
  throw 0;
}

// The ramp h = 0.25 + 0.5 x: linear, so the grid's triangles are exactly its plane.
const char* kRamp = "macro ramp(p) { return 0.25 + 0.5 * p.x }\n";
}  // namespace

TEST_CASE("a height field of a linear function is its plane: closed-form hits and normals", "[shapes][height_field]") {
  render::SceneDesc s = eval_text(std::string(kRamp) + "height_field { function = ramp  resolution = [9, 6] }\n");
  const render::HeightField& f = only_height_field(s);
  REQUIRE(f.data->nx == 9);
  REQUIRE(f.data->nz == 6);
  render::SurfaceHit h;
  // Straight down at x = 0.3: the surface is at 0.4.
  REQUIRE(intersect(f, Ray{Vec3(0.3, 5, 0.6), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.t == Approx(4.6).epsilon(1e-12));
  Vec3 n = glm::normalize(h.normal);
  CHECK(n.x == Approx(-0.5 / std::sqrt(1.25)).epsilon(1e-9));
  CHECK(n.y == Approx(1.0 / std::sqrt(1.25)).epsilon(1e-9));
  CHECK(n.z == Approx(0.0).margin(1e-12));
  CHECK(h.uv.x == Approx(0.3));
  CHECK(h.uv.y == Approx(0.6));
  // Level along +x at y = 0.5: the plane is met at x = 0.5, after crossing four cells.
  REQUIRE(intersect(f, Ray{Vec3(-1, 0.5, 0.37), Vec3(1, 0, 0)}, Interval::positive(), h));
  CHECK(h.t == Approx(1.5).epsilon(1e-12));
  // A slanted ray: origin (0, 1, 0.5) towards (1, 0, 0.5): y = 1 - x meets 0.25 + 0.5 x at x = 0.5.
  REQUIRE(intersect(f, Ray{Vec3(0, 1, 0.5), glm::normalize(Vec3(1, -1, 0))}, Interval::positive(), h));
  CHECK(h.point.x == Approx(0.5).epsilon(1e-12));
  // Outside the unit square, and above the surface everywhere: misses.
  CHECK_FALSE(intersect(f, Ray{Vec3(1.2, 5, 0.5), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK_FALSE(intersect(f, Ray{Vec3(-1, 0.8, 0.5), Vec3(1, 0, 0)}, Interval::positive(), h));
  // The bounds hold the drawn surface.
  render::AABB b = bounds(f);
  CHECK(b.lo.y == Approx(0.25));
  CHECK(b.hi.y == Approx(0.75));
}

TEST_CASE("a height field image is read as POV-Ray reads it: bottom row at z = 0, grey level is height",
          "[shapes][height_field]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("rts_hf_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // 3 x 2: the top row white, the bottom row black but for a grey middle pixel.
  render::Image img(3, 2);
  for (int x = 0; x < 3; ++x)
    for (int k = 0; k < 3; ++k) img.at(x, 0)[k] = 1.0f;
  for (int k = 0; k < 3; ++k) img.at(1, 1)[k] = 0.5f;
  render::write_png((dir / "t.png").string(), img, 16, render::Encoding::Linear);
  render::SceneDesc s = eval_text("height_field { file = \"t.png\" }\n", {}, (dir / "scene.rts").string());
  const render::HeightField& f = only_height_field(s);
  REQUIRE(f.data->nx == 3);
  REQUIRE(f.data->nz == 2);
  render::SurfaceHit h;
  // At (x, z) = (0.5, 0): the grey pixel, 0.5; at z = 1 everything is 1; between, linear.
  REQUIRE(intersect(f, Ray{Vec3(0.5, 5, 0.0), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.point.y == Approx(0.5).margin(1e-4));
  REQUIRE(intersect(f, Ray{Vec3(0.0, 5, 1.0), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.point.y == Approx(1.0).margin(1e-4));
  REQUIRE(intersect(f, Ray{Vec3(0.0, 5, 0.25), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.point.y == Approx(0.25).margin(1e-4));
  fs::remove_all(dir);
}

TEST_CASE("a height field's solid is the column under its surface: walls, surface and water cross",
          "[shapes][height_field]") {
  render::SceneDesc s = eval_text(std::string(kRamp) + "height_field { function = ramp  resolution = 7  water_level = 0.4 }\n");
  const render::HeightField& f = only_height_field(s);
  render::CsgLeafCrossings c;
  // Under the surface everywhere (y = 0.1): in through the wall x = 0, out through x = 1.
  leaf_crossings(f, Ray{Vec3(-1, 0.1, 0.5), Vec3(1, 0, 0)}, c);
  REQUIRE(c.count == 2);
  CHECK_FALSE(c.inside_at_start);
  CHECK(c.t[0] == Approx(1.0));
  CHECK(c.t[1] == Approx(2.0));
  render::SurfaceHit h;
  REQUIRE(leaf_hit(f, Ray{Vec3(-1, 0.1, 0.5), Vec3(1, 0, 0)}, c, 0, h));
  CHECK(h.normal.x == Approx(-1.0));
  // At y = 0.5 the surface (0.25 + 0.5 x) is met at x = 0.5, then the wall x = 1.
  leaf_crossings(f, Ray{Vec3(-1, 0.5, 0.5), Vec3(1, 0, 0)}, c);
  REQUIRE(c.count == 2);
  CHECK(c.t[0] == Approx(1.5).margin(1e-7));
  CHECK(c.t[1] == Approx(2.0));
  // Straight up at x = 0.1, where the surface (0.3) is under the water (0.4): the line starts
  // inside and leaves through the water plane.
  leaf_crossings(f, Ray{Vec3(0.1, -5, 0.5), Vec3(0, 1, 0)}, c);
  REQUIRE(c.count == 1);
  CHECK(c.inside_at_start);
  CHECK(c.t[0] == Approx(5.4).margin(1e-7));
  // Drawn alone, the surface under the water is not there: straight down at x = 0.1 misses;
  // at x = 0.6 (surface 0.55) it hits.
  CHECK_FALSE(intersect(f, Ray{Vec3(0.1, 5, 0.5), Vec3(0, -1, 0)}, Interval::positive(), h));
  REQUIRE(intersect(f, Ray{Vec3(0.6, 5, 0.5), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.t == Approx(4.45).margin(1e-7));  // heights are stored as floats
}

TEST_CASE("a height field in an intersection: the box's walls under the terrain, the terrain inside the box",
          "[shapes][height_field][csg]") {
  render::SceneDesc s = eval_text(
      "macro ramp(p) { return 0.5 * p.x }\n"
      "let green = material { color = rgb(0, 1, 0) }\n"
      "intersection {\n"
      "  height_field { function = ramp  resolution = 5 }\n"
      "  box { min = <0.2, -1, 0.2>  max = <0.8, 0.3, 0.8>  material = green }\n"
      "}\n");
  render::FlatScene flat = render::flatten_scene(s);
  render::World world(s, flat);
  render::WorldHit hit;
  // Into the box's wall z = 0.2 at y = 0.1, under the terrain (0.25 at x = 0.5).
  REQUIRE(world.intersect(Ray{Vec3(0.5, 0.1, -3), Vec3(0, 0, 1)}, Interval::positive(), hit));
  CHECK(hit.t == Approx(3.2).epsilon(1e-12));
  CHECK(glm::normalize(hit.normal).z == Approx(-1.0));
  // Down at x = 0.7: the terrain (0.35) is above the box's top (0.3): the box's top.
  REQUIRE(world.intersect(Ray{Vec3(0.7, 5, 0.5), Vec3(0, -1, 0)}, Interval::positive(), hit));
  CHECK(hit.t == Approx(4.7).epsilon(1e-12));
  // Down at x = 0.3: the terrain (0.15) is inside the box: the terrain.
  REQUIRE(world.intersect(Ray{Vec3(0.3, 5, 0.5), Vec3(0, -1, 0)}, Interval::positive(), hit));
  CHECK(hit.t == Approx(4.85).epsilon(1e-12));
  CHECK(glm::normalize(hit.normal).y > 0.8);
  // Beside the box, under the terrain: nothing (the intersection is inside the box only).
  CHECK_FALSE(world.intersect(Ray{Vec3(0.1, 0.01, -3), Vec3(0, 0, 1)}, Interval::positive(), hit));
}

TEST_CASE("the height field's block-and-cell walk finds the nearest of all its triangles", "[shapes][height_field]") {
  // 37 x 29 random heights: partial blocks at both far edges.
  const int nx = 37, nz = 29;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<float> h(static_cast<std::size_t>(nx) * nz);
  for (float& v : h) v = static_cast<float>(u01(rng));
  render::HeightField f;
  f.data = render::make_height_field_data(nx, nz, h, false);
  auto H = [&](int ix, int iz) { return static_cast<double>(h[static_cast<std::size_t>(iz) * nx + ix]); };
  auto P = [&](int ix, int iz) { return Vec3(static_cast<double>(ix) / (nx - 1), H(ix, iz), static_cast<double>(iz) / (nz - 1)); };
  // Every triangle, one by one (Moller-Trumbore): the nearest t.
  auto brute = [&](const Ray& r) {
    double best = INFINITY;
    auto tri = [&](Vec3 a, Vec3 b, Vec3 c) {
      Vec3 e1 = b - a, e2 = c - a, pv = glm::cross(r.direction, e2);
      double det = glm::dot(e1, pv);
      if (std::abs(det) < 1e-15) return;
      Vec3 tv = r.origin - a;
      double uu = glm::dot(tv, pv) / det;
      if (uu < 0 || uu > 1) return;
      Vec3 qv = glm::cross(tv, e1);
      double vv = glm::dot(r.direction, qv) / det;
      if (vv < 0 || uu + vv > 1) return;
      double t = glm::dot(e2, qv) / det;
      if (t > 0 && t < best) best = t;
    };
    for (int iz = 0; iz + 1 < nz; ++iz)
      for (int ix = 0; ix + 1 < nx; ++ix) {
        tri(P(ix, iz), P(ix + 1, iz), P(ix, iz + 1));
        tri(P(ix + 1, iz + 1), P(ix, iz + 1), P(ix + 1, iz));
      }
    return best;
  };
  int hits = 0, agree = 0, n = 400;
  for (int i = 0; i < n; ++i) {
    Vec3 o(u01(rng) * 3 - 1, 0.3 + u01(rng) * 2, u01(rng) * 3 - 1);
    Vec3 target(u01(rng), u01(rng), u01(rng));
    Ray r{o, glm::normalize(target - o)};
    double expect = brute(r);
    render::SurfaceHit hit;
    bool got = intersect(f, r, Interval::positive(), hit);
    hits += got;
    if (got == std::isfinite(expect) && (!got || std::abs(hit.t - expect) < 1e-9 * (1 + expect))) ++agree;
  }
  CHECK(hits > 100);
  CHECK(agree == n);
}

TEST_CASE("bad height_field parameters are located errors", "[shapes][height_field]") {
  Diagnostic d = eval_diagnostic("height_field { smooth = true }");
  CHECK(d.message.find("height_field needs property 'file' (an image) or 'function'") == 0);
  d = eval_diagnostic(std::string(kRamp) + "height_field { function = ramp  file = \"x.png\" }");
  CHECK(d.message == "height_field takes either 'file' or 'function', not both");
  d = eval_diagnostic(std::string(kRamp) + "height_field { function = ramp\n  water_level = 2 }");
  CHECK(d.message == "property 'water_level' of height_field must be from 0 to 1, got 2");
  CHECK(d.loc.line() == 3);
  d = eval_diagnostic(std::string(kRamp) + "height_field { function = ramp  resolution = 1 }");
  CHECK(d.message.find("property 'resolution' of height_field must be a whole number from 2 to 16384") == 0);
  d = eval_diagnostic(std::string(kRamp) + "height_field { function = ramp  resolution = [4, 2.5] }");
  CHECK(d.message.find("got 2.5") != std::string::npos);
  d = eval_diagnostic("height_field { function = 3 }");
  CHECK(d.message == "property 'function' of height_field expects a macro of one point, got a number");
  // A missing image is located at `file` (it escaped evaluation as an unlocated internal error
  // until fuzz_eval met an imported scene without its image).
  d = eval_diagnostic("height_field {\n  file = \"no_such_height_field.png\" }");
  CHECK(d.message.find("cannot read image 'no_such_height_field.png'") == 0);
  CHECK(d.loc.line() == 2);
  CHECK(d.loc.col() == 3);
}
