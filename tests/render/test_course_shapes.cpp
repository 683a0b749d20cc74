// The quad primitive and per-vertex mesh materials (issue 11, items 3 and 9), analytically.
#include <memory>

#include <catch2/catch.hpp>

#include "render/accel/mesh_accel.hpp"
#include "render/geometry/shapes/quad.hpp"

using namespace rts::render;

TEST_CASE("a quad is hit inside its parallelogram with uv = (s, t)", "[primitives]") {
  Quad q;   // UW's square: corner <-0.5,-0.5,0>, edges +x and +y
  SurfaceHit hit;
  REQUIRE(intersect(q, Ray{{0.25, -0.25, -5}, {0, 0, 1}}, Interval::positive(), hit));
  CHECK(hit.t == Approx(5.0));
  CHECK(hit.uv.x == Approx(0.75));
  CHECK(hit.uv.y == Approx(0.25));
  CHECK(hit.has_uv);
  CHECK(hit.normal.z == Approx(1.0));   // cross(edge_u, edge_v)
  CHECK(hit.dpdu == Vec3(1, 0, 0));
  CHECK(hit.dpdv == Vec3(0, 1, 0));
  // From behind too, and not outside the edges or parallel to the plane.
  CHECK(intersect(q, Ray{{0, 0, 5}, {0, 0, -1}}, Interval::positive(), hit));
  CHECK_FALSE(intersect(q, Ray{{0.51, 0, -5}, {0, 0, 1}}, Interval::positive(), hit));
  CHECK_FALSE(intersect(q, Ray{{0, 0, -5}, {1, 0, 0}}, Interval::positive(), hit));
  CHECK_FALSE(intersect(q, Ray{{0, 0, -5}, {0, 0, 1}}, Interval(0, 4.9), hit));
}

TEST_CASE("a sheared quad solves for its own edge coordinates", "[primitives]") {
  Quad q{{0, 0, 0}, {2, 0, 0}, {1, 1, 0}};   // a parallelogram leaning right
  SurfaceHit hit;
  // The point corner + 0.5 * edge_u + 0.5 * edge_v = (1.5, 0.5, 0).
  REQUIRE(intersect(q, Ray{{1.5, 0.5, -1}, {0, 0, 1}}, Interval::positive(), hit));
  CHECK(hit.uv.x == Approx(0.5));
  CHECK(hit.uv.y == Approx(0.5));
  // (0.2, 0.9) is inside the bounding box but left of the leaning edge.
  CHECK_FALSE(intersect(q, Ray{{0.2, 0.9, -1}, {0, 0, 1}}, Interval::positive(), hit));
  AABB b = bounds(q);
  CHECK(b.lo == Vec3(0, 0, 0));
  CHECK(b.hi == Vec3(3, 1, 0));
  Quad degenerate{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  CHECK_FALSE(intersect(degenerate, Ray{{0.5, 0, -1}, {0, 0, 1}}, Interval::positive(), hit));
}

TEST_CASE("per-vertex material values interpolate with the hit's barycentrics", "[primitives]") {
  auto data = std::make_shared<MeshData>();
  data->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  data->indices = {0, 1, 2};
  data->colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  data->shininess = {10, 20, 40};
  MeshAccel mesh(data);
  SurfaceHit hit;
  REQUIRE(mesh.intersect(Ray{{0.25, 0.5, -1}, {0, 0, 1}}, Interval::positive(), hit, false));
  CHECK(hit.bary.x == Approx(0.25));
  CHECK(hit.bary.y == Approx(0.5));
  VertexMaterial vm;
  REQUIRE(mesh.vertex_material(hit.triangle, hit.bary, vm));
  CHECK(vm.has_color);
  CHECK(vm.color.r == Approx(0.25));
  CHECK(vm.color.g == Approx(0.25));
  CHECK(vm.color.b == Approx(0.5));
  CHECK(vm.has_shininess);
  CHECK(vm.shininess == Approx(0.25 * 10 + 0.25 * 20 + 0.5 * 40));
  CHECK_FALSE(vm.has_diffuse);
  CHECK_FALSE(vm.has_specular);
  // At a vertex the value is that vertex's.
  REQUIRE(mesh.intersect(Ray{{1e-9, 1e-9, -1}, {0, 0, 1}}, Interval::positive(), hit, false));
  REQUIRE(mesh.vertex_material(hit.triangle, hit.bary, vm));
  CHECK(vm.color.r == Approx(1.0).margin(1e-6));

  auto plain = std::make_shared<MeshData>(*data);
  plain->colors.clear();
  plain->shininess.clear();
  CHECK_FALSE(MeshAccel(plain).vertex_material(0, {0.3, 0.3}, vm));
}
