// The World: scene-graph flattening, transformed instances (object-space intersection with the
// inverse matrix, normals by the inverse transpose), shared meshes.
#include <cstring>
#include <memory>

#include <catch2/catch.hpp>

#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {
World make_world(const SceneDesc& s) { return World(s, flatten_scene(s)); }
void check_vec(const Vec3& a, const Vec3& b, double eps = 1e-9) {
  CHECK(a.x == Approx(b.x).margin(eps));
  CHECK(a.y == Approx(b.y).margin(eps));
  CHECK(a.z == Approx(b.z).margin(eps));
}
}  // namespace

TEST_CASE("translated and scaled sphere is hit where the transform puts it", "[transforms]") {
  SceneDesc s;
  place(s, add_shape(s, Sphere{Vec3(0), 1.0}), translate(Vec3(0, 0, 10)) * scale(Vec3(2)));
  World w = make_world(s);
  WorldHit h;
  REQUIRE(w.intersect(Ray{Vec3(0), Vec3(0, 0, 1)}, Interval::positive(), h));
  CHECK(h.t == Approx(8.0));
  check_vec(h.point, Vec3(0, 0, 8));
  check_vec(h.normal, Vec3(0, 0, -1));
  check_vec(h.object_point, Vec3(0, 0, -1));
  CHECK(h.has_uv);  // spherical UVs of the object-space point
  CHECK(w.surface_uv(h).y == Approx(0.5));
}

TEST_CASE("instances placed by translation share one linear part and keep their own translations", "[transforms]") {
  // Shapes placed by `translate` (the POV-Ray way) and a few by the same rotation: the world
  // keeps one linear pair per distinct rotation, and each instance's own translation.
  SceneDesc s;
  const Mat4 turn = rotate_deg(30.0, Vec3(0, 0, 1));
  for (int i = 0; i < 20; ++i) place(s, add_shape(s, Sphere{Vec3(0), 0.4}), translate(Vec3(i, 0, 10)));
  for (int i = 0; i < 5; ++i) place(s, add_shape(s, Box{Vec3(-0.3), Vec3(0.3)}), translate(Vec3(i, 3, 10)) * turn);
  World w = make_world(s);
  CHECK(w.instance_linear_count() == 2);
  STATIC_REQUIRE(sizeof(InstanceTransform) <= 56);
  for (int i = 0; i < 20; ++i) {
    WorldHit h;
    REQUIRE(w.intersect(Ray{Vec3(i, 0, 0), Vec3(0, 0, 1)}, Interval::positive(), h));
    CHECK(h.t == Approx(9.6));
    check_vec(h.object_point, Vec3(0, 0, -0.4));
    const std::optional<InstanceMaps> maps = w.transform(h.instance);
    REQUIRE(maps);
    check_vec(Vec3(maps->to_world[3]), Vec3(i, 0, 10), 0.0);
    check_vec(Vec3(maps->to_object * glm::dvec4(Vec3(i, 0, 10), 1.0)), Vec3(0.0), 0.0);
  }
  for (int i = 0; i < 5; ++i) {
    WorldHit h;
    REQUIRE(w.intersect(Ray{Vec3(i, 3, 0), Vec3(0, 0, 1)}, Interval::positive(), h));
    CHECK(h.t == Approx(9.7));                      // the rotated box's face, turned about z only
    check_vec(h.normal, Vec3(0, 0, -1));
  }
}

TEST_CASE("the top-level BVH is built from boxes equal to the ones made with the instances", "[transforms]") {
  // World::build_bvh makes each instance's box again from the world's own arrays (the shape,
  // the matrix rebuilt from the columns kept): the tree must be the one the boxes computed from
  // the flattened scene give, node for node.
  SceneDesc s;
  for (int i = 0; i < 60; ++i) {
    const Mat4 place_at = translate(Vec3(0.37 * i, -1e-3 * i * i, 5.0 - i)) *
                          rotate_deg(7.0 * i, glm::normalize(Vec3(1, i % 3, 2))) * scale(Vec3(1.0 + 0.01 * i, 0.5, 2.0));
    if (i % 3 == 0) place(s, add_shape(s, Sphere{Vec3(0.1 * i, 0, 0), 0.3}), place_at);
    else if (i % 3 == 1) place(s, add_shape(s, Box{Vec3(-0.2), Vec3(0.25)}), translate(Vec3(i, 2.0, -0.0)));
    else place(s, add_shape(s, Sphere{Vec3(i, 1e6, -3), 0.5}));
  }
  const FlatScene flat = flatten_scene(s);
  std::vector<AABB> boxes;
  for (const FlatShape& fs : flat.shapes) {
    const AABB object = visit_shape([](const auto& g) -> AABB {
      if constexpr (requires { bounds(g); }) return bounds(g);
      else return AABB{};
    }, s.shapes[fs.shape].geometry);
    const Mat4 m = flat.to_world(fs);
    boxes.push_back(m == Mat4(1.0) ? object : transform_bounds(m, object));
  }
  const BVH expected = build_bvh(boxes);
  const World w(s, flat, false);
  const BVH& got = w.top_level();
  REQUIRE(got.nodes.size() == expected.nodes.size());
  CHECK(got.order == expected.order);
  for (std::size_t i = 0; i < got.nodes.size(); ++i) {
    const BVHNode &a = got.nodes[i], &b = expected.nodes[i];
    CHECK(std::memcmp(a.lo, b.lo, sizeof a.lo) == 0);
    CHECK(std::memcmp(a.hi, b.hi, sizeof a.hi) == 0);
    CHECK(a.offset == b.offset);
    CHECK(a.count == b.count);
  }
}

TEST_CASE("a child's transform gives back its matrix bit for bit", "[transforms]") {
  // ChildTransform keeps a translation as its offset alone and anything else whole; either way
  // the matrix read back is the one given, down to the sign of a zero.
  Mat4 mirrored_zero = translate(Vec3(1, 2, 3));
  mirrored_zero[0][1] = -0.0;  // equal to the translation by value, not by bits: kept whole
  Mat4 projective = translate(Vec3(1, 2, 3)) * rotate_deg(10.0, Vec3(0, 0, 1));
  projective[3][3] = 0.5;  // w != 1: kept whole
  Mat4 skewed_w = rotate_deg(70.0, Vec3(1, 0, 0));
  skewed_w[0][3] = 0.25;   // a projective row with w = 1: linear columns and offset, w included
  skewed_w[3] = glm::dvec4(-1e-310, 7, 0, 1);
  const Mat4 cases[] = {Mat4(1.0), translate(Vec3(0.1, -2e300, 5e-320)), mirrored_zero,
                        translate(Vec3(4, 5, 6)) * rotate_deg(33.0, glm::normalize(Vec3(1, 2, 3))) * scale(Vec3(2, 1, 0.5)),
                        projective, skewed_w};
  for (const Mat4& m : cases) {
    const ChildTransform t(m);
    const Mat4 back = t.matrix();
    CHECK(std::memcmp(&back, &m, sizeof(Mat4)) == 0);
    CHECK(t[3] == m[3]);
    const ChildTransform copy = t;
    const Mat4 copied = copy.matrix();
    CHECK(std::memcmp(&copied, &m, sizeof(Mat4)) == 0);
  }
}

TEST_CASE("a child's transform block lives while any copy holds it", "[transforms]") {
  // The block is counted in itself (one pointer per child): copies, moves and assignments,
  // self-assignment included, leave every live copy reading its matrix; the sanitizer builds
  // catch a block freed early or twice, or one never freed.
  const Mat4 turn = translate(Vec3(1, 2, 3)) * rotate_deg(20.0, Vec3(0, 1, 0));
  const Mat4 shift = translate(Vec3(-7, 0.5, 9));
  std::vector<ChildTransform> copies;
  {
    ChildTransform a(turn), b(shift);
    for (int i = 0; i < 100; ++i) copies.push_back(i % 2 ? a : b);  // the vector's growth moves them
    ChildTransform c = std::move(a);
    CHECK(a.matrix() == Mat4(1.0));  // NOLINT(bugprone-use-after-move): a moved-from child is the identity
    const ChildTransform& self = c;
    c = self;  // self-assignment, copying and moving, keeps the block
    ChildTransform& same = c;
    c = std::move(same);
    CHECK(c.matrix() == turn);
    b = c;  // b's block still held by the copies
    CHECK(b.matrix() == turn);
    ChildTransform d;
    d = std::move(b);
    CHECK(d.matrix() == turn);
  }
  for (std::size_t i = 0; i < copies.size(); ++i) CHECK(copies[i].matrix() == (i % 2 ? turn : shift));
  copies.erase(copies.begin(), copies.begin() + 50);
  CHECK(copies.back().matrix() == turn);
  STATIC_REQUIRE(sizeof(ChildTransform) == sizeof(void*));
}

TEST_CASE("children placed with the same rotation share its linear part", "[transforms]") {
  // A loop placing a group rotated and translated repeats a few rotations: each child keeps its
  // own offset and a pointer to one block per distinct linear part (by bits), not a matrix.
  std::vector<ChildTransform> placed;
  std::vector<Mat4> given;
  for (int i = 0; i < 3000; ++i) {
    const Mat4 m = translate(Vec3(i, -i * 0.5, 3)) * rotate_deg(1.0 + 7.0 * (i % 90), Vec3(0, 1, 0));
    placed.emplace_back(m);
    given.push_back(m);
  }
  for (int i = 0; i < 3000; ++i) {
    const Mat4 back = placed[i].matrix();
    REQUIRE(std::memcmp(&back, &given[i], sizeof(Mat4)) == 0);
    // The same rotation 90 placements apart: one block (the per-thread cache holds 90 easily).
    if (i >= 90) CHECK(ChildTransform::shares_linear_part(placed[i], placed[i - 90]));
    if (i >= 1) CHECK_FALSE(ChildTransform::shares_linear_part(placed[i], placed[i - 1]));
  }
  // A -0 where the other has +0 is another linear part; a pure translation keeps none.
  Mat4 negative_zero = given[0];
  negative_zero[1][0] = -negative_zero[1][0];
  REQUIRE(given[0][1][0] == 0.0);
  const ChildTransform a(given[0]), b(negative_zero), c(translate(Vec3(1, 2, 3)));
  CHECK_FALSE(ChildTransform::shares_linear_part(a, b));
  CHECK_FALSE(ChildTransform::shares_linear_part(c, c));
  const Mat4 back = b.matrix();
  CHECK(std::memcmp(&back, &negative_zero, sizeof(Mat4)) == 0);
}

TEST_CASE("shared transforms are told apart by their bits", "[transforms]") {
  // The interner behind every shared linear part: equal bits share an entry, a -0 is not a +0,
  // and releasing the lookup keeps the values.
  BitInterner<Mat4> interner;
  std::vector<Mat4> values;
  Mat4 negative_zero(1.0);
  negative_zero[1][0] = -0.0;
  const Mat4 turned = rotate_deg(33.0, glm::normalize(Vec3(1, 2, 3)));
  CHECK(interner.intern(Mat4(1.0), values) == 0);
  CHECK(interner.intern(turned, values) == 1);
  CHECK(interner.intern(negative_zero, values) == 2);  // == the identity by value, not by bits
  CHECK(interner.intern(Mat4(1.0), values) == 0);
  CHECK(interner.intern(turned, values) == 1);
  REQUIRE(values.size() == 3);
  CHECK(std::memcmp(&values[2], &negative_zero, sizeof(Mat4)) == 0);
  interner.release();
  CHECK(values.size() == 3);
  CHECK(interner.intern(turned, values) == 3);  // a fresh lookup: appended again
}

TEST_CASE("non-uniform scale: normals use the inverse transpose", "[transforms]") {
  // A sphere squashed to an ellipsoid x^2/4 + y^2 = 1; at (sqrt2, sqrt(1/2)) the true normal
  // is along the gradient (x/4, y) = (sqrt2/4, sqrt(1/2)).
  SceneDesc s;
  place(s, add_shape(s, Sphere{Vec3(0), 1.0}), scale(Vec3(2, 1, 1)));
  World w = make_world(s);
  WorldHit h;
  Vec3 target(std::sqrt(2.0), std::sqrt(0.5), 0);
  REQUIRE(w.intersect(Ray{target * 3.0, -target}, Interval::positive(), h));
  check_vec(h.point, target, 1e-9);
  check_vec(h.normal, glm::normalize(Vec3(std::sqrt(2.0) / 4, std::sqrt(0.5), 0)), 1e-9);
}

TEST_CASE("rotated box follows POV-Ray's rotate convention", "[transforms]") {
  // A thin box along +x, rotated 90 degrees about y, lies along -z.
  SceneDesc s;
  place(s, add_shape(s, Box{Vec3(0, -0.1, -0.1), Vec3(5, 0.1, 0.1)}), rotate_deg(90, Vec3(0, 1, 0)));
  World w = make_world(s);
  WorldHit h;
  CHECK(w.intersect(Ray{Vec3(0, 5, -3), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.t == Approx(4.9));
  CHECK_FALSE(w.intersect(Ray{Vec3(3, 5, 0), Vec3(0, -1, 0)}, Interval::positive(), h));
}

TEST_CASE("groups of groups compose transforms in order", "[transforms]") {
  SceneDesc s;
  NodeId ball = add_shape(s, Sphere{Vec3(0), 0.5});
  NodeId inner = add_group(s, {Child{ball, translate(Vec3(1, 0, 0)), {}}});
  NodeId outer = add_group(s, {Child{inner, translate(Vec3(0, 2, 0)), {}},
                               Child{inner, translate(Vec3(0, -2, 0)), {}}});
  place(s, outer, translate(Vec3(0, 0, 5)));
  FlatScene flat = flatten_scene(s);
  REQUIRE(flat.shapes.size() == 2);
  World w(s, flat);
  WorldHit h;
  CHECK(w.intersect(Ray{Vec3(1, 2, 0), Vec3(0, 0, 1)}, Interval::positive(), h));
  CHECK(h.t == Approx(4.5));
  CHECK(w.intersect(Ray{Vec3(1, -2, 0), Vec3(0, 0, 1)}, Interval::positive(), h));
  CHECK_FALSE(w.intersect(Ray{Vec3(0, 2, 0), Vec3(0, 0, 1)}, Interval::positive(), h));
}

TEST_CASE("a group containing itself is reported, not a stack overflow", "[transforms]") {
  SceneDesc s;
  NodeId g = add_group(s, {});
  s.groups[0].children.push_back(Child{g, Mat4(1.0), {}});
  place(s, g);
  CHECK_THROWS_AS(flatten_scene(s), RenderError);
}

TEST_CASE("lights are moved by their placement", "[transforms]") {
  SceneDesc s;
  LightDesc l;
  l.position = Vec3(1, 0, 0);
  l.direction = Vec3(1, 0, 0);
  place(s, add_light(s, l), translate(Vec3(0, 5, 0)) * rotate_deg(90, Vec3(0, 1, 0)));
  FlatScene flat = flatten_scene(s);
  REQUIRE(flat.lights.size() == 1);
  check_vec(flat.lights[0].position, Vec3(0, 5, -1));
  check_vec(flat.lights[0].direction, Vec3(0, 0, -1));
}

TEST_CASE("one mesh BVH shared by several instances", "[transforms]") {
  auto mesh = std::make_shared<MeshData>();
  mesh->positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  mesh->indices = {0, 1, 2, 0, 2, 3};
  mesh->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  SceneDesc s;
  s.meshes.push_back(mesh);
  NodeId quad = add_shape(s, MeshRef{0, true});
  place(s, quad, translate(Vec3(0, 0, 3)));
  place(s, quad, translate(Vec3(10, 0, 6)));
  World w = make_world(s);
  WorldHit h;
  REQUIRE(w.intersect(Ray{Vec3(0.5, 0.5, 0), Vec3(0, 0, 1)}, Interval::positive(), h));
  CHECK(h.t == Approx(3.0));
  CHECK(h.has_uv);
  CHECK(w.surface_uv(h).x == Approx(0.75));
  CHECK(h.uv.y == Approx(0.75));
  REQUIRE(w.intersect(Ray{Vec3(10.5, -0.5, 0), Vec3(0, 0, 1)}, Interval::positive(), h));
  CHECK(h.t == Approx(6.0));
  CHECK_FALSE(w.intersect(Ray{Vec3(5, 0, 0), Vec3(0, 0, 1)}, Interval::positive(), h));
}

TEST_CASE("scale 0 is reported by flattening instead of giving NaNs", "[transforms]") {
  SceneDesc s;
  place(s, add_shape(s, Sphere{Vec3(0), 1.0}), scale(Vec3(0)));
  CHECK_THROWS_WITH(flatten_scene(s), "transform is singular (scale 0?)");
  // World, given such an instance anyway, skips it rather than tracing NaNs.
  FlatScene flat;
  flat.add_shape(0, scale(Vec3(0)));
  World w(s, flat);
  WorldHit h;
  CHECK_FALSE(w.intersect(Ray{Vec3(0, 0, -5), Vec3(0, 0, 1)}, Interval::positive(), h));
}

TEST_CASE("planes stay outside the BVH but are hit and occlude", "[transforms]") {
  SceneDesc s;
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}), translate(Vec3(0, -1, 0)));
  place(s, add_shape(s, Sphere{Vec3(0), 0.5}));
  World w = make_world(s);
  CHECK(w.plane_count() == 1);
  CHECK(w.instance_count() == 2);
  WorldHit h;
  REQUIRE(w.intersect(Ray{Vec3(3, 5, 0), Vec3(0, -1, 0)}, Interval::positive(), h));
  CHECK(h.t == Approx(6.0));
  CHECK(w.occluded(Ray{Vec3(3, 5, 0), Vec3(0, -1, 0)}, Interval(0, 10)));
  CHECK_FALSE(w.occluded(Ray{Vec3(3, 5, 0), Vec3(0, -1, 0)}, Interval(0, 5)));
}

TEST_CASE("every primitive kind honours its instance transform", "[transforms]") {
  // Each shape is built along +y at the origin, then rotated 90 degrees about z (so +y goes
  // to -x), scaled 2x and moved to z = 10; rays must meet it where that geometry lies.
  Mat4 m = translate(Vec3(0, 0, 10)) * scale(Vec3(2)) * rotate_deg(90, Vec3(0, 0, 1));
  auto first_hit = [&](ShapeGeometry g, Ray ray) {
    SceneDesc s;
    place(s, add_shape(s, std::move(g)), m);
    World w(s, flatten_scene(s));
    WorldHit h;
    bool found = w.intersect(ray, Interval::positive(), h);
    return std::make_pair(found, h);
  };
  SECTION("cylinder along -x, radius 2 after scaling") {
    auto [found, h] = first_hit(Cylinder{Vec3(0), Vec3(0, 1, 0), 1.0, true}, Ray{Vec3(-1, 0, 0), Vec3(0, 0, 1)});
    REQUIRE(found);
    CHECK(h.t == Approx(8.0));  // surface at z = 10 - 2
    check_vec(h.normal, Vec3(0, 0, -1));
  }
  SECTION("cone along -x: radius 2 at the base (x=0) shrinking to 0 at x=-2") {
    auto [found, h] = first_hit(Cone{Vec3(0), Vec3(0, 1, 0), 1.0, 0.0, false}, Ray{Vec3(-1, 0, 0), Vec3(0, 0, 1)});
    REQUIRE(found);
    CHECK(h.t == Approx(9.0));  // radius 1 halfway
    check_vec(h.normal, glm::normalize(Vec3(-1, 0, -1)), 1e-9);  // 45 degree slope
  }
  SECTION("disc facing -x") {
    auto [found, h] = first_hit(Disc{Vec3(0), Vec3(0, 1, 0), 1.0, 0.0}, Ray{Vec3(-5, 0, 10.5), Vec3(1, 0, 0)});
    REQUIRE(found);
    CHECK(h.t == Approx(5.0));
    check_vec(h.normal, Vec3(-1, 0, 0));
  }
  SECTION("triangle") {
    auto [found, h] = first_hit(triangle(Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0)), Ray{Vec3(-0.5, 0.5, 0), Vec3(0, 0, 1)});
    REQUIRE(found);
    CHECK(h.t == Approx(10.0));
    check_vec(h.normal, Vec3(0, 0, 1));
  }
  SECTION("plane y = 0 becomes x = 0") {
    auto [found, h] = first_hit(Plane{Vec3(0, 1, 0), 0.0}, Ray{Vec3(3, 0, 10), Vec3(-1, 0, 0)});
    REQUIRE(found);
    CHECK(h.t == Approx(3.0));
    check_vec(h.normal, Vec3(-1, 0, 0));
  }
}

TEST_CASE("identical mesh data loaded twice share one BVH", "[transforms]") {
  auto make = [] {
    auto m = std::make_shared<MeshData>();
    m->positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    m->indices = {0, 1, 2};
    m->source = "tri.obj";
    return m;
  };
  SceneDesc s;
  s.meshes = {make(), make()};
  auto other = make();
  other->positions[2].y = 2;  // different content: its own BVH
  s.meshes.push_back(other);
  for (MeshId id = 0; id < 3; ++id) place(s, add_shape(s, MeshRef{id, true}), translate(Vec3(3.0 * id, 0, 0)));
  World w(s, flatten_scene(s));
  CHECK(w.mesh_bvh_count() == 2);
  WorldHit h;
  CHECK(w.intersect(Ray{Vec3(3, 0, -1), Vec3(0, 0, 1)}, Interval::positive(), h));
  CHECK(w.intersect(Ray{Vec3(6, 1.5, -1), Vec3(0, 0, 1)}, Interval::positive(), h));
}
