// Group 2, watertight meshes: the camera inside closed, finely tessellated spheres and cubes
// (100k+ triangles), no light inside, looking at faces, edges, corners and poles: no pixel
// may show the background. Grids hit by rays exactly through their shared vertices and edges,
// straight and rotated: no ray may miss.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"
#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {

const Color kBackground(1.0, 0.0, 1.0);

int background_pixels_inside(std::shared_ptr<MeshData> mesh, Vec3 look, Vec3 up, const std::string& name,
                              const Mat4& placement = Mat4(1.0)) {
  SceneDesc s;
  s.settings.width = 64;
  s.settings.height = 64;
  s.settings.background = kBackground;
  s.has_camera = true;
  s.camera.position = Vec3(placement[3]);
  s.camera.look_at = s.camera.position + look;
  s.camera.up = up;
  s.camera.fov = 100;
  place(s, add_mesh(s, std::move(mesh), add_material(s, matte(Color(0.6)))), placement);
  RenderResult r = render_scene(s);
  int holes = count_color(r.color, kBackground);
  std::string file = "watertight_" + name;
  for (char& c : file)
    if (c == ' ' || c == ',') c = '_';
  record("watertight", name, "background pixels", holes, "0", save(r.color, file));
  return holes;
}

}  // namespace

TEST_CASE("inside a closed 100k-triangle sphere no background shows", "[watertight]") {
  auto sphere = uv_sphere_mesh(Vec3(0.0), 1.0, 240, 240);
  REQUIRE(sphere->indices.size() / 3 >= 100000);
  // Poles are where 224 thin triangles meet at one vertex.
  CHECK(background_pixels_inside(sphere, Vec3(0, 1, 0), Vec3(1, 0, 0), "sphere pole") == 0);
  CHECK(background_pixels_inside(sphere, Vec3(0, -1, 0), Vec3(1, 0, 0), "sphere south pole") == 0);
  CHECK(background_pixels_inside(sphere, Vec3(1, 0.02, 0.3), Vec3(0, 1, 0), "sphere equator") == 0);
  // Off-centre and far from the origin: rays meet the edges at every angle.
  CHECK(background_pixels_inside(sphere, Vec3(-1, 0.5, 0.2), Vec3(0, 1, 0), "sphere off-centre at 1e6",
                                 translate(Vec3(1e6, 0, 0)) * translate(Vec3(0.3, -0.2, 0.1))) == 0);
}

TEST_CASE("inside a closed 100k-triangle cube no background shows at faces, edges, corners", "[watertight]") {
  auto cube = grid_cube_mesh(1.0, 130);
  REQUIRE(cube->indices.size() / 3 >= 100000);
  CHECK(background_pixels_inside(cube, Vec3(0, 0, 1), Vec3(0, 1, 0), "cube face") == 0);
  CHECK(background_pixels_inside(cube, Vec3(1, 0, 1), Vec3(0, 1, 0), "cube edge") == 0);
  CHECK(background_pixels_inside(cube, Vec3(1, 1, 1), Vec3(0, 1, 0), "cube corner") == 0);
  CHECK(background_pixels_inside(cube, Vec3(1, 1, 1), Vec3(0, 1, 0), "cube corner rotated",
                                 rotate_deg(30, Vec3(0, 1, 0)) * rotate_deg(17, Vec3(1, 0, 0))) == 0);
}

TEST_CASE("the 12-triangle cube seen from inside has no cracks", "[watertight]") {
  // Issue 8 failure 2: Möller–Trumbore showed 4 background pixels at 200x150.
  auto cube = grid_cube_mesh(1.0, 1);
  REQUIRE(cube->indices.size() / 3 == 12);
  for (Vec3 look : {Vec3(1, 1, 1), Vec3(1, 0, 1), Vec3(-1, 1, 0.3)})
    CHECK(background_pixels_inside(cube, look, Vec3(0, 1, 0),
                                   fmt::format("12-triangle cube {},{},{}", look.x, look.y, look.z)) == 0);
}

namespace {

// Rays straight down onto the grid's every vertex and every edge midpoint (and along edges),
// in the grid's own frame carried by `placement`. Returns the misses.
int grid_misses(const Mat4& placement, int n, const std::string& name) {
  SceneDesc s;
  auto grid = grid_mesh(1.0, n);
  place(s, add_mesh(s, grid, kNoId), placement);
  FlatScene flat = flatten_scene(s);
  World world(s, flat);
  int misses = 0, rays = 0;
  auto shoot = [&](double x, double y) {
    Vec3 p(placement * glm::dvec4(x, y, 0.0, 1.0));
    Vec3 n = glm::normalize(Vec3(placement * glm::dvec4(0.3, 0.2, 1.0, 0.0)));  // oblique
    Ray ray{p - 5.0 * n, n};
    WorldHit hit;
    ++rays;
    if (!world.intersect(ray, Interval::positive(), hit)) ++misses;
  };
  for (int j = 0; j <= n * 2; ++j)
    for (int i = 0; i <= n * 2; ++i) {
      double x = -1.0 + 1.0 * i / n, y = -1.0 + 1.0 * j / n;  // vertices and edge midpoints
      if (std::abs(x) >= 1.0 || std::abs(y) >= 1.0) continue;  // the border has one side only
      shoot(x, y);
    }
  // Along the diagonals (the triangles' shared hypotenuses), 7 points per cell.
  for (int j = 1; j < n - 1; ++j)
    for (int i = 1; i < n - 1; ++i)
      for (int q = 1; q < 8; ++q) {
        double f = q / 8.0;
        shoot(-1.0 + 2.0 * (i + f) / n, -1.0 + 2.0 * (j + f) / n);
      }
  record("watertight", name, fmt::format("missed rays of {}", rays), misses, "0");
  return misses;
}

}  // namespace

TEST_CASE("rays through a grid's shared vertices and edges never miss", "[watertight]") {
  CHECK(grid_misses(Mat4(1.0), 64, "grid straight") == 0);
  CHECK(grid_misses(rotate_deg(30, Vec3(0, 1, 0)), 64, "grid turned 30 about y") == 0);
  CHECK(grid_misses(translate(Vec3(1e7, -3e6, 2e5)) * rotate_deg(30, Vec3(0, 1, 0)) * rotate_deg(11, Vec3(1, 0, 0)),
                    64, "grid turned and at 1e7") == 0);
}

TEST_CASE("a grid seen edge-on along its shared edges shows no holes", "[watertight]") {
  // The second crack: a tessellated grid turned 30 degrees about y, with camera rays
  // running along its shared edges (orthographic, pixel centres on the grid lines).
  SceneDesc s;
  s.settings.width = 64;
  s.settings.height = 64;
  s.settings.background = kBackground;
  s.has_camera = true;
  s.camera.projection = Projection::Orthographic;
  s.camera.view_width = 1.0;  // pixel centres at multiples of 1/64 + 1/128: on the lines below
  Mat4 turn = rotate_deg(30, Vec3(0, 1, 0));
  s.camera.position = Vec3(turn * glm::dvec4(1.0 / 128, 1.0 / 128, -5, 1));
  s.camera.look_at = Vec3(turn * glm::dvec4(1.0 / 128, 1.0 / 128, 0, 1));
  place(s, add_mesh(s, grid_mesh(1.0, 128), add_material(s, matte(Color(0.6)))), turn);
  RenderResult r = render_scene(s);
  int holes = count_color(r.color, kBackground);
  record("watertight", "grid turned 30, rays on its edges", "background pixels", holes, "0",
         save(r.color, "watertight_grid_edges"));
  CHECK(holes == 0);
}
