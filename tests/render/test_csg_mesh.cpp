// Closed meshes in CSG: which meshes bound a solid (mesh_closure), and World tracing them as
// CSG leaves: a cube mesh cut like a box gives the box's hits, rays through its edges and
// corners alike (a line through a shared edge hits two triangles, and is one crossing); a mesh
// crossed more often than one sweep lists is swept again from where it stopped.
#include <cmath>
#include <memory>
#include <random>

#include <catch2/catch.hpp>

#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"
#include "render/geometry/shapes/mesh_closure.hpp"
#include "render/geometry/shapes/prism.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

// The box [lo, hi] as 12 triangles wound counter-clockwise seen from outside. With
// `split`, every face has its own 4 vertices (as an OBJ file with per-face normals gives).
std::shared_ptr<MeshData> cube_mesh(Vec3 lo, Vec3 hi, bool split = false, MeshData* into = nullptr) {
  auto owned = std::make_shared<MeshData>();
  MeshData& m = into ? *into : *owned;
  auto corner = [&](int i) { return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
  // Each face's corners in counter-clockwise order seen from outside.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const uint32_t base = static_cast<uint32_t>(m.positions.size());
  if (!split)
    for (int i = 0; i < 8; ++i) m.positions.push_back(corner(i));
  for (const auto& f : faces) {
    uint32_t id[4];
    for (int k = 0; k < 4; ++k) {
      if (split) {
        id[k] = static_cast<uint32_t>(m.positions.size());
        m.positions.push_back(corner(f[k]));
      } else {
        id[k] = base + static_cast<uint32_t>(f[k]);
      }
    }
    for (uint32_t v : {id[0], id[1], id[2], id[0], id[2], id[3]}) m.indices.push_back(v);
  }
  return owned;
}

struct Block {
  SceneDesc scene;
  std::vector<Child> kids;
  MaterialId mat(double r, double g, double b) { return add_material(scene, emissive(Color(r, g, b))); }
  void child(ShapeGeometry g, MaterialId m) { kids.push_back(Child{add_shape(scene, std::move(g), m), Mat4(1.0), {}}); }
  void mesh_child(std::shared_ptr<MeshData> data, MaterialId m) {
    scene.meshes.push_back(std::move(data));
    child(MeshRef{static_cast<MeshId>(scene.meshes.size() - 1), false}, m);
  }
  void place_block(CsgOp op, Mat4 xf = Mat4(1.0)) {
    CsgDesc d;
    d.op = op;
    d.children = std::move(kids);
    kids.clear();
    place(scene, add_csg(scene, std::move(d)), xf);
  }
};

// One scene traced by both sweeps: with pruning (the default) and with every leaf computed.
struct BothSweeps {
  FlatScene flat;
  World pruned, full;
  explicit BothSweeps(const SceneDesc& s) : flat(flatten_scene(s)), pruned(s, flat), full(s, flat) {
    full.set_csg_pruning(false);
  }
};

}  // namespace

TEST_CASE("mesh closure: a cube is closed, with shared or split vertices", "[csg][mesh]") {
  CHECK(mesh_closure(*cube_mesh(Vec3(-1), Vec3(1))).closed);
  MeshClosure split = mesh_closure(*cube_mesh(Vec3(-1), Vec3(1), true));
  CHECK(split.closed);
  CHECK(split.triangles == 12);
  // Two cubes in one mesh, apart: still a solid (two pieces).
  auto two = cube_mesh(Vec3(-1), Vec3(1));
  cube_mesh(Vec3(2), Vec3(3), false, two.get());
  CHECK(mesh_closure(*two).closed);
}

TEST_CASE("mesh closure: a missing triangle leaves open edges, a flipped one bad winding", "[csg][mesh]") {
  auto holed = cube_mesh(Vec3(-1), Vec3(1));
  holed->indices.resize(holed->indices.size() - 3);
  MeshClosure h = mesh_closure(*holed);
  CHECK_FALSE(h.closed);
  CHECK_FALSE(h.inconsistent);
  CHECK(h.open_edges == 3);  // the missing triangle's edges, each now used once
  auto flipped = cube_mesh(Vec3(-1), Vec3(1));
  std::swap(flipped->indices[1], flipped->indices[2]);
  MeshClosure f = mesh_closure(*flipped);
  CHECK_FALSE(f.closed);
  CHECK(f.inconsistent);
  CHECK(f.open_edges == 3);
  // The reported edge is one of the mesh's own.
  CHECK(std::abs(f.edge_from.x) == 1.0);
  CHECK(mesh_closure(MeshData{}).closed == false);
}

TEST_CASE("csg mesh: a cube mesh cut by a sphere gives the box's hits, through edges and corners too",
          "[csg][mesh]") {
  for (CsgOp op : {CsgOp::Difference, CsgOp::Intersection, CsgOp::Merge, CsgOp::Union}) {
    Block with_box, with_mesh;
    for (Block* b : {&with_box, &with_mesh}) {
      MaterialId red = b->mat(1, 0, 0), green = b->mat(0, 1, 0);
      if (b == &with_box) b->child(Box{Vec3(-1), Vec3(1)}, red);
      else b->mesh_child(cube_mesh(Vec3(-1), Vec3(1), true), red);
      b->child(Sphere{Vec3(0.3, 0.2, -1), 0.7}, green);
      b->place_block(op, translate(Vec3(0.25, 0, 0)));
    }
    FlatScene fb = flatten_scene(with_box.scene), fm = flatten_scene(with_mesh.scene);
    World box_world(with_box.scene, fb), mesh_world(with_mesh.scene, fm);
    std::mt19937 rng(20261128);
    std::uniform_real_distribution<double> c(-1.5, 1.5);
    int hits = 0, edge_rays = 0;
    auto compare = [&](const Ray& ray, bool at_corner = false) {
      WorldHit hb, hm;
      const bool b = box_world.intersect(ray, Interval::positive(), hb);
      const bool m = mesh_world.intersect(ray, Interval::positive(), hm);
      INFO("op " << static_cast<int>(op) << " ray " << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z
                 << " dir " << ray.direction.x << "," << ray.direction.y << "," << ray.direction.z);
      REQUIRE(b == m);
      CHECK(box_world.occluded(ray, Interval::positive()) == mesh_world.occluded(ray, Interval::positive()));
      if (!b) return;
      ++hits;
      CHECK(hm.t == Approx(hb.t).epsilon(1e-9));
      CHECK(box_world.instance(hb.instance).material == mesh_world.instance(hm.instance).material);
      // At a corner either face's normal is right.
      if (!at_corner) CHECK(glm::dot(hm.normal, hb.normal) == Approx(1.0).epsilon(1e-9));
    };
    // Axis-aligned rays on a grid that runs through the cube's edges and corners exactly
    // (x = 0.25 +- 1 after the block's translation; y, z = +-1).
    for (double x : {-0.75, -0.25, 0.25, 0.75, 1.25})
      for (double y : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        compare(Ray{Vec3(x, y, -5), Vec3(0, 0, 1)});
        compare(Ray{Vec3(x, -5, y), Vec3(0, 1, 0)});
        edge_rays += std::abs(x - 0.25) == 1.0 || std::abs(y) == 1.0;
      }
    // Diagonals through the corners, and random rays from outside and inside.
    compare(Ray{Vec3(0.25 - 3, -3, -3), Vec3(1, 1, 1)}, true);
    compare(Ray{Vec3(0.25 + 3, 3, -3), Vec3(-1, -1, 1)}, true);
    for (int r = 0; r < 400; ++r) {
      Vec3 o = r % 2 ? Vec3(c(rng), c(rng), -4) : Vec3(c(rng), c(rng), c(rng)) * 0.5;
      compare(Ray{o, Vec3(c(rng), c(rng), c(rng) + (r % 2 ? 2.0 : 0.0))});
    }
    CHECK(hits > 40);
    CHECK(edge_rays > 10);
  }
}

TEST_CASE("csg mesh: a mesh crossed more often than one sweep lists is swept again", "[csg][mesh]") {
  // Ten unit cubes in one mesh along z (twenty crossings), minus a box over the first six: the
  // ray along them sees the seventh cube's front face, then the hidden ones stay hidden.
  Block b;
  MaterialId red = b.mat(1, 0, 0), green = b.mat(0, 1, 0);
  auto comb = std::make_shared<MeshData>();
  for (int i = 0; i < 10; ++i) cube_mesh(Vec3(-0.5, -0.5, 2.0 * i), Vec3(0.5, 0.5, 2.0 * i + 1), false, comb.get());
  REQUIRE(mesh_closure(*comb).closed);
  b.mesh_child(comb, red);
  b.child(Box{Vec3(-2, -2, -1), Vec3(2, 2, 11.5)}, green);
  b.place_block(CsgOp::Difference);
  BothSweeps both(b.scene);
  for (World* w : {&both.full, &both.pruned}) {
    INFO((w == &both.full ? "every leaf" : "pruned"));
    WorldHit h;
    REQUIRE(w->intersect(Ray{Vec3(0, 0, -5), Vec3(0, 0, 1)}, Interval::positive(), h));
    CHECK(h.t == Approx(5 + 12.0));  // the seventh cube's front face, z = 12
    CHECK(w->instance(h.instance).material == red);
    CHECK(h.normal.z == Approx(-1.0));
    // From inside the fourth cube (hidden by the box): still the seventh's face.
    REQUIRE(w->intersect(Ray{Vec3(0, 0, 6.5), Vec3(0, 0, 1)}, Interval::positive(), h));
    CHECK(h.t == Approx(5.5));
    // Backwards from beyond the comb: the last cube's back face, z = 19.
    REQUIRE(w->intersect(Ray{Vec3(0, 0, 30), Vec3(0, 0, -1)}, Interval::positive(), h));
    CHECK(h.t == Approx(11.0));
    CHECK(h.normal.z == Approx(1.0));
    // A shadow ray between the sixth cube and the box's end is clear; one into the seventh not.
    CHECK_FALSE(w->occluded(Ray{Vec3(0, 0, 10.2), Vec3(0, 0, 1)}, Interval(0.0, 1.0)));
    CHECK(w->occluded(Ray{Vec3(0, 0, 10.2), Vec3(0, 0, 1)}, Interval(0.0, 2.0)));
  }
}

TEST_CASE("csg mesh: pruned and every-leaf sweeps agree on random blocks of meshes and solids", "[csg][mesh]") {
  std::mt19937 rng(5511);
  std::uniform_real_distribution<double> u(0.0, 1.0), c(-1.0, 1.0);
  int hits = 0, rays = 0;
  for (int scene_no = 0; scene_no < 30; ++scene_no) {
    Block b;
    MaterialId red = b.mat(1, 0, 0), green = b.mat(0, 1, 0);
    const CsgOp ops[] = {CsgOp::Union, CsgOp::Merge, CsgOp::Intersection, CsgOp::Difference};
    const CsgOp op = ops[scene_no % 4];
    const int count = 2 + static_cast<int>(3 * u(rng));
    for (int k = 0; k < count; ++k) {
      const double pick = u(rng);
      const MaterialId m = k % 2 ? green : red;
      if (pick < 0.4) {  // a comb of 1-8 cubes along a random axis: up to 16 crossings
        auto comb = std::make_shared<MeshData>();
        const int n = 1 + static_cast<int>(8 * u(rng));
        const double w = 0.1 + 0.15 * u(rng);
        for (int i = 0; i < n; ++i)
          cube_mesh(Vec3(-1 + 2.0 * i / n, -0.5, -0.5), Vec3(-1 + 2.0 * i / n + w, 0.5, 0.5), false, comb.get());
        b.mesh_child(comb, m);
      } else if (pick < 0.6) {
        b.mesh_child(cube_mesh(Vec3(c(rng), c(rng), c(rng)) * 0.3 - 0.5, Vec3(0.5), u(rng) < 0.5), m);
      } else if (pick < 0.8) {
        b.child(Sphere{Vec3(c(rng), c(rng), c(rng)) * 0.5, 0.3 + 0.5 * u(rng)}, m);
      } else {
        b.child(Box{Vec3(-0.5), Vec3(0.5)}, m);  // flush with the cube meshes: ties
      }
      b.kids.back().transform = u(rng) < 0.4 ? Mat4(1.0)
                                              : rotate_deg(180.0 * c(rng), glm::normalize(Vec3(c(rng), c(rng), 1.0)));
    }
    b.place_block(op);
    BothSweeps both(b.scene);
    World &pruned = both.pruned, &full = both.full;
    for (int r = 0; r < 300; ++r) {
      Vec3 o = u(rng) < 0.5 ? Vec3(3 * c(rng), 3 * c(rng), -4) : Vec3(c(rng), c(rng), c(rng));
      Ray ray{o, Vec3(c(rng), c(rng), c(rng)) - o};
      Interval range(u(rng) < 0.5 ? 0.0 : 0.5 * u(rng), u(rng) < 0.5 ? Interval::kInfinity : 0.3 + 1.5 * u(rng));
      WorldHit hp, hf;
      const bool p = pruned.intersect(ray, range, hp), f = full.intersect(ray, range, hf);
      INFO("scene " << scene_no << " ray " << r);
      REQUIRE(p == f);
      if (p) {
        CHECK(hp.t == hf.t);
        CHECK(hp.instance == hf.instance);
        CHECK(hp.normal == hf.normal);
        ++hits;
      }
      CHECK(pruned.occluded(ray, range) == p);
      CHECK(full.occluded(ray, range) == f);
      ++rays;
    }
  }
  CHECK(hits > rays / 10);
}

TEST_CASE("csg: a prism crossed more than a sweep lists is swept again, as a mesh is", "[csg][prism]") {
  // A comb outline: a spine along x with ten teeth towards +z; a ray along the teeth crosses
  // 20 walls. Minus a box over the first six teeth, the ray sees the seventh tooth's wall.
  std::vector<Vec3> pts = {Vec3(0, 0, 0)};
  for (int i = 0; i < 10; ++i) {
    pts.push_back(Vec3(2.0 * i + 1, 1, 0));  // up the tooth's left wall ...
    pts.push_back(Vec3(2.0 * i + 1, 2, 0));
    pts.push_back(Vec3(2.0 * i + 2, 2, 0));
    pts.push_back(Vec3(2.0 * i + 2, 1, 0));  // ... and down its right one
  }
  // Back along the spine: its far corner, then the start, which closes the outline.
  pts.back() = Vec3(20, 1, 0);
  pts.push_back(Vec3(21, 1, 0));
  pts.push_back(Vec3(21, 0, 0));
  pts.push_back(Vec3(0, 0, 0));
  PrismData comb;
  comb.points = pts;
  comb.height1 = -0.5;
  comb.height2 = 0.5;
  prism_setup(comb);
  Block b;
  MaterialId red = b.mat(1, 0, 0), green = b.mat(0, 1, 0);
  b.child(comb, red);
  b.child(Box{Vec3(-1, -1, 0.5), Vec3(12.5, 1, 3)}, green);
  b.place_block(CsgOp::Difference);
  BothSweeps both(b.scene);
  for (World* w : {&both.full, &both.pruned}) {
    INFO((w == &both.full ? "every leaf" : "pruned"));
    WorldHit h;
    // Along x through the teeth (z = 1.5, y = 0): the teeth's walls at x = 2i + 1, 2i + 2.
    REQUIRE(w->intersect(Ray{Vec3(-5, 0, 1.5), Vec3(1, 0, 0)}, Interval::positive(), h));
    CHECK(h.t == Approx(5 + 13.0));  // the seventh tooth's left wall, x = 13
    CHECK(w->instance(h.instance).material == red);
    CHECK(h.normal.x == Approx(-1.0));
    // From inside the box, between the teeth: the same wall.
    REQUIRE(w->intersect(Ray{Vec3(6.5, 0, 1.5), Vec3(1, 0, 0)}, Interval::positive(), h));
    CHECK(h.t == Approx(6.5));
    // Backwards from beyond the comb: the last tooth's right wall, x = 20.
    REQUIRE(w->intersect(Ray{Vec3(30, 0, 1.5), Vec3(-1, 0, 0)}, Interval::positive(), h));
    CHECK(h.t == Approx(10.0));
    CHECK_FALSE(w->occluded(Ray{Vec3(11.2, 0, 1.5), Vec3(1, 0, 0)}, Interval(0.0, 1.5)));
    CHECK(w->occluded(Ray{Vec3(11.2, 0, 1.5), Vec3(1, 0, 0)}, Interval(0.0, 2.0)));
  }
}

TEST_CASE("csg mesh: an inverted closed mesh is everything outside it", "[csg][mesh]") {
  // intersection { box, inverse cube mesh } is difference { box, cube mesh }.
  Block inv, diff;
  for (Block* b : {&inv, &diff}) {
    MaterialId red = b->mat(1, 0, 0), green = b->mat(0, 1, 0);
    b->child(Box{Vec3(-1), Vec3(1)}, red);
    b->mesh_child(cube_mesh(Vec3(-0.5, -0.5, -2), Vec3(0.5, 0.5, 0)), green);
    if (b == &inv) b->scene.shapes.back().inverse = true;
    b->place_block(b == &inv ? CsgOp::Intersection : CsgOp::Difference);
  }
  FlatScene fi = flatten_scene(inv.scene), fd = flatten_scene(diff.scene);
  World wi(inv.scene, fi), wd(diff.scene, fd);
  int hits = 0;
  for (double x = -1.2; x <= 1.2; x += 0.1)
    for (double y = -1.2; y <= 1.2; y += 0.1) {
      const Ray ray{Vec3(x + 0.013, y + 0.007, -5), Vec3(0.01, 0.02, 1)};
      WorldHit hi, hd;
      const bool a = wi.intersect(ray, Interval::positive(), hi), b = wd.intersect(ray, Interval::positive(), hd);
      REQUIRE(a == b);
      if (!a) continue;
      ++hits;
      CHECK(hi.t == hd.t);
      CHECK(glm::dot(hi.normal, hd.normal) == Approx(1.0));
      CHECK(wi.instance(hi.instance).material == wd.instance(hd.instance).material);
    }
  CHECK(hits > 300);
}
