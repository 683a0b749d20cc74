// CSG: the interval sweep on hand-made crossings (which surface shows, its orientation, ties),
// the bounds of each operation, and whole scenes traced through World (which child's material
// is seen where, against closed-form positions).
#include <cmath>

#include <catch2/catch.hpp>

#include "render/accel/world.hpp"
#include "render/geometry/csg/csg_tree.hpp"
#include "render/accel/flatten.hpp"
#include "scene_fixture.hpp"
#include "tracer.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

// A tree of `op` over `n` leaves (leaf i = node i), optionally inverting leaves.
CsgTree flat_tree(CsgOp op, uint32_t n, std::vector<bool> inverse = {}) {
  CsgTree t;
  for (uint32_t i = 0; i < n; ++i) {
    CsgNode leaf;
    leaf.leaf = true;
    leaf.first = i;
    leaf.inverse = i < inverse.size() && inverse[i];
    t.nodes.push_back(leaf);
    t.children.push_back(i);
  }
  CsgNode root;
  root.op = op;
  root.first = 0;
  root.count = n;
  t.nodes.push_back(root);
  t.leaf_count = n;
  return t;
}

CsgLeafCrossings span(double a, double b) {
  CsgLeafCrossings c;
  c.count = 2;
  c.t[0] = a;
  c.t[1] = b;
  return c;
}

const Interval kAll = Interval::positive();

bool first(const CsgTree& t, std::vector<CsgLeafCrossings> leaves, CsgSurface& s, Interval range = kAll) {
  return csg_first_surface(t, leaves.data(), range, 1e-12, 1e-12, s);
}

}  // namespace

TEST_CASE("csg sweep: union shows every child's surface, inner ones too", "[csg]") {
  CsgTree t = flat_tree(CsgOp::Union, 2);
  CsgSurface s;
  // A over [1, 3], B over [2, 4]: B's entry at 2 is inside A, and a union still shows it.
  REQUIRE(first(t, {span(1, 3), span(2, 4)}, s));
  CHECK(s.t == 1.0);
  CHECK(s.leaf == 0);
  CHECK(s.entering);
  REQUIRE(first(t, {span(1, 3), span(2, 4)}, s, Interval(1.5, 10)));
  CHECK(s.t == 2.0);
  CHECK(s.leaf == 1);
  CHECK(s.entering);  // B's own entry: its normal faces the ray
}

TEST_CASE("csg sweep: merge hides the inner surfaces", "[csg]") {
  CsgTree t = flat_tree(CsgOp::Merge, 2);
  CsgSurface s;
  REQUIRE(first(t, {span(1, 3), span(2, 4)}, s, Interval(1.5, 10)));
  CHECK(s.t == 4.0);  // 2 (B in, inside A) and 3 (A out, inside B) are hidden
  CHECK(s.leaf == 1);
  CHECK_FALSE(s.entering);
}

TEST_CASE("csg sweep: intersection is where every child is", "[csg]") {
  CsgTree t = flat_tree(CsgOp::Intersection, 2);
  CsgSurface s;
  REQUIRE(first(t, {span(1, 3), span(2, 4)}, s));
  CHECK(s.t == 2.0);
  CHECK(s.leaf == 1);
  CHECK(s.entering);
  REQUIRE(first(t, {span(1, 3), span(2, 4)}, s, Interval(2.5, 10)));
  CHECK(s.t == 3.0);
  CHECK(s.leaf == 0);
  CHECK_FALSE(s.entering);
  CHECK_FALSE(first(t, {span(1, 2), span(3, 4)}, s));  // disjoint: empty
}

TEST_CASE("csg sweep: difference shows the cut face with the subtracted child", "[csg]") {
  CsgTree t = flat_tree(CsgOp::Difference, 2);
  CsgSurface s;
  // A over [1, 5] minus B over [0, 2]: the result starts at B's exit, 2, entering.
  REQUIRE(first(t, {span(1, 5), span(0, 2)}, s));
  CHECK(s.t == 2.0);
  CHECK(s.leaf == 1);
  CHECK(s.entering);
  // B inside A: A's entry, then B's entry is a leaving (the hole), B's exit an entering.
  REQUIRE(first(t, {span(1, 5), span(2, 3)}, s, Interval(1.5, 10)));
  CHECK(s.t == 2.0);
  CHECK(s.leaf == 1);
  CHECK_FALSE(s.entering);
  // B covers A entirely: nothing.
  CHECK_FALSE(first(t, {span(1, 5), span(0, 6)}, s));
}

TEST_CASE("csg sweep: clip shows the first child's surface inside the others, never theirs", "[csg]") {
  CsgTree t = flat_tree(CsgOp::Clip, 2);
  CsgSurface s;
  // A over [1, 3] clipped by B over [2, 4]: A's entry at 1 lies outside B (cut away), B's entry
  // at 2 never shows, A's exit at 3 lies inside B: the ray sees A's inside there.
  REQUIRE(first(t, {span(1, 3), span(2, 4)}, s));
  CHECK(s.t == 3.0);
  CHECK(s.leaf == 0);
  CHECK_FALSE(s.entering);
  // B over [0, 2]: A's entry shows (inside B), entering; its exit at 3 is cut away.
  REQUIRE(first(t, {span(1, 3), span(0, 2)}, s));
  CHECK(s.t == 1.0);
  CHECK(s.leaf == 0);
  CHECK(s.entering);
  REQUIRE_FALSE(first(t, {span(1, 3), span(0, 2)}, s, Interval(1.5, 10)));
  // The same crossings under an intersection show B's face at 2: a clip does not.
  CHECK_FALSE(first(t, {span(1, 5), span(2, 4)}, s, Interval(0, 4.5)));
  CsgTree i = flat_tree(CsgOp::Intersection, 2);
  REQUIRE(first(i, {span(1, 5), span(2, 4)}, s, Interval(0, 4.5)));
  CHECK(s.t == 2.0);
  // Two clippers: A's surface where both are inside; an inverse clipper keeps what is outside it.
  CsgTree two = flat_tree(CsgOp::Clip, 3);
  REQUIRE(first(two, {span(1, 3), span(0, 4), span(2, 5)}, s));
  CHECK(s.t == 3.0);
  CsgTree inv = flat_tree(CsgOp::Clip, 2, {false, true});
  REQUIRE(first(inv, {span(1, 3), span(2, 4)}, s));
  CHECK(s.t == 1.0);
  CHECK(s.entering);
}

TEST_CASE("csg sweep: a clip's union shows its inner surfaces where they are kept", "[csg]") {
  // clip { union { A  B }  C }: A over [1, 3], B over [2, 4] (its entry inside A), C over [1.5, 5].
  CsgTree t;
  for (uint32_t l = 0; l < 3; ++l) {
    CsgNode leaf;
    leaf.leaf = true;
    leaf.first = l;
    t.nodes.push_back(leaf);
  }
  CsgNode u;
  u.op = CsgOp::Union;
  u.first = 0;
  u.count = 2;
  t.children = {0, 1, 3, 2};
  t.nodes.push_back(u);  // node 3
  CsgNode c;
  c.op = CsgOp::Clip;
  c.first = 2;
  c.count = 2;
  t.nodes.push_back(c);
  t.leaf_count = 3;
  CsgSurface s;
  REQUIRE(first(t, {span(1, 3), span(2, 4), span(1.5, 5)}, s));
  CHECK(s.t == 2.0);  // A's entry at 1 is cut away; B's entry, inside A, shows as in a union
  CHECK(s.leaf == 1);
}

TEST_CASE("csg sweep: coincident faces are one batch, the same for every ray", "[csg]") {
  CsgTree t = flat_tree(CsgOp::Difference, 2);
  CsgSurface s;
  // The cut is flush with the block's front face, up to rounding either way: no face at 1,
  // the result starts where B ends.
  for (double eps : {0.0, 1e-15, -1e-15}) {
    REQUIRE(first(t, {span(1, 5), span(1 + eps, 3)}, s));
    CHECK(s.t == 3.0);
    CHECK(s.leaf == 1);
    CHECK(s.entering);
  }
  // Union of two boxes sharing a face: the merge has no surface at the shared face.
  CsgTree m = flat_tree(CsgOp::Merge, 2);
  for (double eps : {0.0, 1e-15, -1e-15}) {
    REQUIRE(first(m, {span(1, 2), span(2 + eps, 3)}, s, Interval(1.5, 10)));
    CHECK(s.t == 3.0);
  }
}

TEST_CASE("csg sweep: inverse and half-spaces", "[csg]") {
  // A plane-like leaf inside from -infinity up to 2, intersected with [1, 5]: [1, 2].
  CsgTree t = flat_tree(CsgOp::Intersection, 2);
  CsgLeafCrossings half;
  half.inside_at_start = true;
  half.count = 1;
  half.t[0] = 2;
  CsgSurface s;
  REQUIRE(first(t, {span(1, 5), half}, s, Interval(1.5, 10)));
  CHECK(s.t == 2.0);
  CHECK(s.leaf == 1);
  CHECK_FALSE(s.entering);
  // Inverting B in an intersection is the difference A - B.
  CsgTree inv = flat_tree(CsgOp::Intersection, 2, {false, true});
  REQUIRE(first(inv, {span(1, 5), span(2, 3)}, s, Interval(1.5, 10)));
  CHECK(s.t == 2.0);
  CHECK_FALSE(s.entering);
  // A ray starting inside a solid sees its exit.
  CsgTree one = flat_tree(CsgOp::Union, 1);
  REQUIRE(first(one, {span(-1, 4)}, s));
  CHECK(s.t == 4.0);
  CHECK_FALSE(s.entering);
}

TEST_CASE("csg sweep: a leaf grazed (entry and exit in one batch) shows nothing", "[csg]") {
  CsgTree t = flat_tree(CsgOp::Union, 1);
  CsgSurface s;
  CHECK_FALSE(first(t, {span(2, 2)}, s));
}

TEST_CASE("csg bounds: union, intersection, difference, inverse", "[csg]") {
  std::vector<AABB> leaves = {AABB{Vec3(0), Vec3(2)}, AABB{Vec3(1), Vec3(3)}};
  AABB u = flat_tree(CsgOp::Union, 2).bounds(leaves);
  CHECK(u.lo == Vec3(0));
  CHECK(u.hi == Vec3(3));
  AABB i = flat_tree(CsgOp::Intersection, 2).bounds(leaves);
  CHECK(i.lo == Vec3(1));
  CHECK(i.hi == Vec3(2));
  AABB d = flat_tree(CsgOp::Difference, 2).bounds(leaves);
  AABB c = flat_tree(CsgOp::Clip, 2).bounds(leaves);  // a clip is bounded as an intersection
  CHECK(c.lo == i.lo);
  CHECK(c.hi == i.hi);
  CHECK(d.lo == Vec3(0));
  CHECK(d.hi == Vec3(2));
  CHECK_FALSE(flat_tree(CsgOp::Union, 2, {true, false}).bounds(leaves).finite());
  std::vector<AABB> apart = {AABB{Vec3(0), Vec3(1)}, AABB{Vec3(2), Vec3(3)}};
  CHECK_FALSE(flat_tree(CsgOp::Intersection, 2).bounds(apart).valid());
}

// ---- whole scenes through World -------------------------------------------------------------

namespace {

struct CsgScene {
  SceneDesc scene;
  std::vector<Child> kids;
  MaterialId mat(double r, double g, double b) { return add_material(scene, emissive(Color(r, g, b))); }
  void child(ShapeGeometry g, MaterialId m, bool inverse = false, Mat4 xf = Mat4(1.0)) {
    NodeId n = add_shape(scene, std::move(g), m);
    scene.shapes.back().inverse = inverse;
    kids.push_back(Child{n, xf, {}});
  }
  NodeId block(CsgOp op, MaterialId m = kNoId) {
    CsgDesc d;
    d.op = op;
    d.children = std::move(kids);
    d.material = m;
    kids.clear();
    return add_csg(scene, std::move(d));
  }
};

// The material seen along a ray, or kNoId for none; `normal` the world normal there.
MaterialId seen(const SceneDesc& scene, const Ray& r, Vec3* normal = nullptr, double* t = nullptr) {
  FlatScene flat = flatten_scene(scene);
  World world(scene, flat);
  WorldHit h;
  if (!world.intersect(r, Interval::positive(), h)) return kNoId;
  if (normal) *normal = h.normal;
  if (t) *t = h.t;
  return world.instance(h.instance).material;
}

}  // namespace

TEST_CASE("csg world: a difference's cut face shows the subtracted child's material", "[csg]") {
  CsgScene s;
  MaterialId red = s.mat(1, 0, 0), green = s.mat(0, 1, 0);
  s.child(Box{Vec3(-1), Vec3(1)}, red);
  s.child(Sphere{Vec3(0, 0, -1), 0.5}, green);  // a bite out of the front face
  place(s.scene, s.block(CsgOp::Difference));
  Vec3 n;
  double t;
  // Through the bite's centre: the sphere's far wall at z = -0.5, facing the ray.
  CHECK(seen(s.scene, Ray{Vec3(0, 0, -5), Vec3(0, 0, 1)}, &n, &t) == green);
  CHECK(t == Approx(4.5));
  CHECK(n.z == Approx(-1.0));
  // Beside the bite: the box's face at z = -1.
  CHECK(seen(s.scene, Ray{Vec3(0.8, 0, -5), Vec3(0, 0, 1)}, &n, &t) == red);
  CHECK(t == Approx(4.0));
  CHECK(n.z == Approx(-1.0));
  // The sphere's part outside the box is gone: a ray through it only (z < -1) finds the box.
  CHECK(seen(s.scene, Ray{Vec3(-5, 0, -1.2), Vec3(1, 0, 0)}) == kNoId);
}

TEST_CASE("csg world: clip leaves the sphere open where the box cuts it", "[csg]") {
  CsgScene s;
  MaterialId red = s.mat(1, 0, 0), green = s.mat(0, 1, 0);
  s.child(Sphere{Vec3(0), 1.0}, red);
  s.child(Box{Vec3(-2), Vec3(2, 0.3, 2)}, green);  // keeps the sphere below y = 0.3
  place(s.scene, s.block(CsgOp::Clip));
  Vec3 n;
  double t;
  // Down through the cut: the top is gone, the bowl's inside at y = -1 shows, its normal out
  // of the solid (along the ray).
  CHECK(seen(s.scene, Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}, &n, &t) == red);
  CHECK(t == Approx(6.0));
  CHECK(n.y == Approx(-1.0));
  // From the front below the cut: the sphere's own face.
  CHECK(seen(s.scene, Ray{Vec3(0, 0, -5), Vec3(0, 0, 1)}, &n, &t) == red);
  CHECK(t == Approx(4.0));
  CHECK(n.z == Approx(-1.0));
  // Above the cut the sphere is gone, and the box's faces never show.
  CHECK(seen(s.scene, Ray{Vec3(0, 0.6, -5), Vec3(0, 0, 1)}) == kNoId);
  CHECK(seen(s.scene, Ray{Vec3(1.5, 5, 0), Vec3(0, -1, 0)}) == kNoId);
}

TEST_CASE("csg world: a child without material shows the block's", "[csg]") {
  CsgScene s;
  MaterialId red = s.mat(1, 0, 0), blue = s.mat(0, 0, 1);
  s.child(Box{Vec3(-1), Vec3(1)}, red);
  s.child(Sphere{Vec3(0, 0, -1), 0.5}, kNoId);
  place(s.scene, s.block(CsgOp::Difference, blue));
  CHECK(seen(s.scene, Ray{Vec3(0, 0, -5), Vec3(0, 0, 1)}) == blue);
  CHECK(seen(s.scene, Ray{Vec3(0.8, 0, -5), Vec3(0, 0, 1)}) == red);
}

TEST_CASE("group world: a member without material shows the nearest group's, in CSG too", "[csg]") {
  CsgScene s;
  MaterialId red = s.mat(1, 0, 0), blue = s.mat(0, 0, 1), green = s.mat(0, 1, 0);
  // group(red) { plain sphere at x=0, blue sphere at x=3, group(green) { plain sphere at x=6 },
  //              union { plain box at x=9 }, union(blue) { plain box at x=12 } }
  NodeId plain = add_shape(s.scene, Sphere{Vec3(0), 1.0});
  NodeId own = add_shape(s.scene, Sphere{Vec3(3, 0, 0), 1.0}, blue);
  NodeId inner = add_group(s.scene, {Child{add_shape(s.scene, Sphere{Vec3(6, 0, 0), 1.0}), Mat4(1.0), {}}}, green);
  s.child(Box{Vec3(8, -1, -1), Vec3(10, 1, 1)}, kNoId);
  NodeId csg = s.block(CsgOp::Union);
  s.child(Box{Vec3(11, -1, -1), Vec3(13, 1, 1)}, kNoId);
  NodeId csg_own = s.block(CsgOp::Union, blue);
  std::vector<Child> members;
  for (NodeId n : {plain, own, inner, csg, csg_own}) members.push_back(Child{n, Mat4(1.0), {}});
  place(s.scene, add_group(s.scene, members, red));
  auto at = [&](double x) { return seen(s.scene, Ray{Vec3(x, 0, -5), Vec3(0, 0, 1)}); };
  CHECK(at(0) == red);
  CHECK(at(3) == blue);
  CHECK(at(6) == green);
  CHECK(at(9) == red);
  CHECK(at(12) == blue);
  // The same shapes outside any group with a material keep none.
  CsgScene bare;
  place(bare.scene, add_shape(bare.scene, Sphere{Vec3(0), 1.0}));
  CHECK(seen(bare.scene, Ray{Vec3(0, 0, -5), Vec3(0, 0, 1)}) == kNoId);
}

TEST_CASE("csg world: intersection of two spheres is a lens; transforms on block and child", "[csg]") {
  CsgScene s;
  MaterialId a = s.mat(1, 0, 0), b = s.mat(0, 1, 0);
  s.child(Sphere{Vec3(0), 1.0}, a, false, translate(Vec3(-0.5, 0, 0)));
  s.child(Sphere{Vec3(0), 1.0}, b, false, translate(Vec3(0.5, 0, 0)));
  NodeId lens = s.block(CsgOp::Intersection);
  place(s.scene, lens, translate(Vec3(0, 0, 10)));
  Vec3 n;
  double t;
  // Along x through the lens's middle: enter through the right sphere's surface (x = -0.5),
  // i.e. sphere b (centred at +0.5) seen first.
  CHECK(seen(s.scene, Ray{Vec3(-5, 0, 10), Vec3(1, 0, 0)}, &n, &t) == b);
  CHECK(t == Approx(4.5));
  CHECK(n.x == Approx(-1.0));
  // Outside the lens (x = 0.8 is in sphere b only): a ray along z misses.
  CHECK(seen(s.scene, Ray{Vec3(0.8, 0, 0), Vec3(0, 0, 1)}) == kNoId);
  // Through the middle along z: sphere a's surface at depth sqrt(1 - 0.25).
  CHECK(seen(s.scene, Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}, &n, &t) != kNoId);
  CHECK(t == Approx(10 - std::sqrt(0.75)));
}

TEST_CASE("csg world: a plane is a half-space, inverse flips it", "[csg]") {
  CsgScene s;
  MaterialId ball = s.mat(1, 0, 0), cut = s.mat(0, 1, 0);
  s.child(Sphere{Vec3(0), 1.0}, ball);
  s.child(Plane{Vec3(0, 1, 0), 0.0}, cut);  // keeps the lower half
  place(s.scene, s.block(CsgOp::Intersection));
  Vec3 n;
  double t;
  CHECK(seen(s.scene, Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}, &n, &t) == cut);
  CHECK(t == Approx(5.0));
  CHECK(n.y == Approx(1.0));
  CsgScene inv;
  MaterialId ball2 = inv.mat(1, 0, 0), cut2 = inv.mat(0, 1, 0);
  inv.child(Sphere{Vec3(0), 1.0}, ball2);
  inv.child(Plane{Vec3(0, 1, 0), 0.0}, cut2, /*inverse=*/true);  // keeps the upper half
  place(inv.scene, inv.block(CsgOp::Intersection));
  CHECK(seen(inv.scene, Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}, &n, &t) == ball2);
  CHECK(t == Approx(4.0));
  CHECK(seen(inv.scene, Ray{Vec3(0, -5, 0), Vec3(0, 1, 0)}, &n, &t) == cut2);
  CHECK(n.y == Approx(-1.0));
}

TEST_CASE("csg world: nested blocks (a tube: cylinder minus cylinder, in a union)", "[csg]") {
  CsgScene s;
  MaterialId outer = s.mat(1, 0, 0), inner = s.mat(0, 1, 0), other = s.mat(0, 0, 1);
  s.child(Cylinder{Vec3(0, -1, 0), Vec3(0, 1, 0), 1.0, true}, outer);
  s.child(Cylinder{Vec3(0, -2, 0), Vec3(0, 2, 0), 0.5, true}, inner);
  NodeId tube = s.block(CsgOp::Difference);
  s.kids.push_back(Child{tube, Mat4(1.0), {}});
  s.child(Sphere{Vec3(5, 0, 0), 0.5}, other);
  place(s.scene, s.block(CsgOp::Union));
  double t;
  // Down the axis: through the hole, nothing.
  CHECK(seen(s.scene, Ray{Vec3(0, 5, 0), Vec3(0, -1, 0)}) == kNoId);
  // Down at x = 0.75: the ring's top cap.
  CHECK(seen(s.scene, Ray{Vec3(0.75, 5, 0), Vec3(0, -1, 0)}, nullptr, &t) == outer);
  CHECK(t == Approx(4.0));
  // Along x from the left: the outer wall, then (from inside the hole) the inner wall.
  CHECK(seen(s.scene, Ray{Vec3(-5, 0, 0), Vec3(1, 0, 0)}, nullptr, &t) == outer);
  CHECK(t == Approx(4.0));
  CHECK(seen(s.scene, Ray{Vec3(0, 0, 0), Vec3(1, 0, 0)}, nullptr, &t) == inner);
  CHECK(t == Approx(0.5));
  CHECK(seen(s.scene, Ray{Vec3(5, 5, 0), Vec3(0, -1, 0)}) == other);
}

// ---- shading through CSG: transmissive shadows and the medium stack ------------------------

namespace {

// A lit floor under two overlapping glass spheres (transmit `k`) combined by `op`, the light
// straight above: the floor point below both gets I * k^(surfaces crossed).
Rgb floor_under(CsgOp op, double k) {
  CsgScene s;
  MaterialDesc glass;
  glass.transmit = Color(k);
  glass.diffuse = 0;
  glass.ambient = 0;
  MaterialId g = add_material(s.scene, glass);
  // Off-centre, so that the vertical shadow ray meets four distinct surfaces.
  s.child(Sphere{Vec3(-0.25, 2, 0), 0.5}, kNoId);
  s.child(Sphere{Vec3(0.35, 2, 0), 0.5}, kNoId);
  place(s.scene, s.block(op, g));
  MaterialDesc floor;
  floor.color = Color(1.0);
  floor.diffuse = 1.0;
  floor.ambient = 0;
  place(s.scene, add_shape(s.scene, Plane{Vec3(0, 1, 0), 0.0}, add_material(s.scene, floor)));
  LightDesc l;
  l.position = Vec3(0, 10, 0);
  l.attenuation = Vec3(1, 0, 0);
  place(s.scene, add_light(s.scene, l));
  Tracer tracer(s.scene);
  return tracer.trace(Ray{Vec3(0, 0.5, -1), Vec3(0, -0.5, 1)});  // hits the floor at the origin
}

}  // namespace

TEST_CASE("csg shading: shadows through glass cross a union's inner walls, not a merge's", "[csg]") {
  const double k = 0.5;
  // The floor at the origin, lit from straight above, unshadowed: cos = 1, I = 1.
  Rgb merged = floor_under(CsgOp::Merge, k);
  Rgb united = floor_under(CsgOp::Union, k);
  CHECK(merged.x == Approx(k * k));                  // in and out
  CHECK(united.x == Approx(k * k * k * k));          // and the two inner walls
  Rgb lens = floor_under(CsgOp::Intersection, k);
  CHECK(lens.x == Approx(k * k));
}

TEST_CASE("csg shading: a glass lens refracts as one medium (in through one sphere, out through the other)",
          "[csg]") {
  // A lens of two unit spheres 1.2 apart along x, glass of index 1.5, in front of an emissive
  // wall; a ray along the axis passes straight through (normal incidence), with no
  // reflection or absorption: the wall's colour arrives unchanged only if the exit, through the
  // other sphere's surface, pops the same medium the entry pushed.
  CsgScene s;
  MaterialDesc glass;
  glass.transmit = Color(1.0);
  glass.ior = 1.5;
  glass.diffuse = 0;
  glass.ambient = 0;
  MaterialId g = add_material(s.scene, glass);
  s.child(Sphere{Vec3(-0.6, 0, 0), 1.0}, kNoId);
  s.child(Sphere{Vec3(0.6, 0, 0), 1.0}, kNoId);
  place(s.scene, s.block(CsgOp::Intersection, g));
  place(s.scene, add_shape(s.scene, Box{Vec3(5, -10, -10), Vec3(6, 10, 10)},
                           add_material(s.scene, emissive(Color(0.25, 0.5, 0.75)))));
  Tracer tracer(s.scene);
  Rgb got = tracer.trace(Ray{Vec3(-5, 0, 0), Vec3(1, 0, 0)});
  CHECK(got.x == Approx(0.25));
  CHECK(got.y == Approx(0.5));
  CHECK(got.z == Approx(0.75));
  // Off axis the ray bends twice and still reaches the wall (it is large).
  Rgb off = tracer.trace(Ray{Vec3(-5, 0.2, 0), Vec3(1, 0, 0)});
  CHECK(off.y == Approx(0.5));
}
