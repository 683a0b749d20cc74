// Two-level instancing (render/accel/world_groups.cpp): a group placed several times is built
// once and traced through each placement's transform. Checked against the same scene with
// every placement copied (flatten_instance never instances): the same hits, the same shapes,
// the same occlusion answers; and which groups flattening chooses to instance.
#include <cstring>
#include <random>

#include <catch2/catch.hpp>

#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

Vec3 random_point(std::mt19937_64& rng, double extent) {
  std::uniform_real_distribution<double> u(-extent, extent);
  return Vec3(u(rng), u(rng), u(rng));
}

// Every root flattened without instancing: the world a copy of each placement would give.
FlatScene copied(const SceneDesc& s) {
  FlatScene out;
  for (const Child& root : s.roots) {
    FlatScene one = flatten_instance(s, root);
    for (const FlatShape& fs : one.shapes) out.add_shape(fs.shape, one.to_world(fs));
  }
  return out;
}

// Rays from within `spread` of the origin towards `target` (± 15): the instanced world and the
// copied one agree on every hit's existence, distance, normal, object point and material, and
// the instanced world's occlusion agrees with its closest hit. Returns the number of hits.
int check_same_hits(const World& instanced, const World& copies, std::mt19937_64& rng, double spread, const Vec3& target) {
  int hits = 0;
  for (int r = 0; r < 3000; ++r) {
    const Vec3 o = random_point(rng, spread);
    const Ray ray{o, random_point(rng, 15.0) + target - o};
    WorldHit a, b;
    const bool fa = instanced.intersect(ray, Interval::positive(), a);
    REQUIRE(fa == copies.intersect(ray, Interval::positive(), b));
    if (!fa) continue;
    ++hits;
    CHECK(a.t == Approx(b.t).epsilon(1e-9));
    CHECK(glm::dot(a.normal, b.normal) > 1.0 - 1e-9);
    CHECK(glm::length(a.object_point - b.object_point) <= 1e-9 * (1.0 + glm::length(b.object_point)));
    CHECK(instanced.instance(a.instance).material == copies.instance(b.instance).material);
    CHECK(instanced.occluded(ray, Interval(0.0, a.t * 0.999)) == false);
    CHECK(instanced.occluded(ray, Interval(0.0, a.t * 1.001)) == true);
  }
  return hits;
}

// A group of `n` random spheres, boxes and triangles (some transformed, a nested group among
// them) with two materials.
NodeId random_group(SceneDesc& s, std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> radius(0.05, 0.6), angle(0.0, 360.0);
  MaterialDesc red, green;
  red.color = Color(0.8, 0.1, 0.1);
  green.color = Color(0.1, 0.8, 0.1);
  const MaterialId a = add_material(s, red), b = add_material(s, green);
  std::vector<Child> kids, inner;
  for (int i = 0; i < n; ++i) {
    const Vec3 c = random_point(rng, 4.0);
    NodeId node;
    if (i % 5 == 3) node = add_shape(s, Box{c - radius(rng), c + radius(rng)}, b);
    else if (i % 5 == 4) node = add_shape(s, triangle(c, c + random_point(rng, 0.7), c + random_point(rng, 0.7)), a);
    else node = add_shape(s, Sphere{c, radius(rng)}, i % 2 ? a : b);
    Mat4 m = i % 7 == 0 ? rotate_deg(angle(rng), glm::normalize(random_point(rng, 1.0) + Vec3(0.01))) : Mat4(1.0);
    (i % 3 == 0 ? inner : kids).push_back(Child{node, m, {}});
  }
  kids.push_back(Child{add_group(s, inner), translate(Vec3(0.5, 0.0, -0.25)), {}});
  return add_group(s, kids);
}

}  // namespace

TEST_CASE("an instanced group gives the hits of its copies", "[instancing]") {
  std::mt19937_64 rng(2424);
  SceneDesc s;
  const NodeId g = random_group(s, rng, 120);
  std::uniform_real_distribution<double> angle(0.0, 360.0), size(0.3, 2.5);
  for (int k = 0; k < 6; ++k)
    place(s, g, translate(random_point(rng, 12.0)) * rotate_deg(angle(rng), Vec3(0, 1, 0)) * scale(Vec3(size(rng))));
  place(s, g);  // one placement as is (no transform)

  const FlatScene flat = flatten_scene(s);
  REQUIRE(flat.groups.size() == 7);
  REQUIRE(flat.shapes.empty());
  const World instanced(s, flat), copies(s, copied(s));
  REQUIRE(instanced.group_count() == 1);
  REQUIRE(instanced.group_part_count() == 120);  // the nested group is copied into the instanced one
  REQUIRE(copies.instance_count() == 7 * 120);

  int hits = 0, blocked = 0;
  for (int r = 0; r < 4000; ++r) {
    const Vec3 o = random_point(rng, 25.0);
    const Ray ray{o, random_point(rng, 12.0) - o};
    WorldHit a, b;
    const bool fa = instanced.intersect(ray, Interval::positive(), a);
    const bool fb = copies.intersect(ray, Interval::positive(), b);
    REQUIRE(fa == fb);
    if (fa) {
      ++hits;
      CHECK(a.t == Approx(b.t).epsilon(1e-9));
      CHECK(glm::length(a.point - b.point) <= 1e-9 * (1.0 + glm::length(b.point)));
      CHECK(glm::dot(a.normal, b.normal) > 1.0 - 1e-9);
      CHECK(glm::dot(a.shading_normal, b.shading_normal) > 1.0 - 1e-9);
      CHECK(glm::length(a.object_point - b.object_point) <= 1e-9 * (1.0 + glm::length(b.object_point)));
      CHECK(a.error > 0.0);
      CHECK(a.error < 1e-9 * (1.0 + glm::length(b.point)));
      // The same shape: its kind, its material, its object-space geometry.
      const Instance &ia = instanced.instance(a.instance), &ib = copies.instance(b.instance);
      CHECK(ia.kind == ib.kind);
      CHECK(ia.material == ib.material);
      CHECK(glm::length(instanced.surface_uv(a) - copies.surface_uv(b)) < 1e-6);
    }
    const Interval segment(0.0, std::uniform_real_distribution<double>(0.0, 1.5)(rng));
    const bool oa = instanced.occluded(ray, segment), ob = copies.occluded(ray, segment);
    CHECK(oa == ob);
    blocked += oa;
  }
  CHECK(hits > 400);  // both answers are exercised
  CHECK(blocked > 200);
  CHECK(blocked < 3800);
  // The placements share one BVH: far less than a copy per placement.
  CHECK(instanced.memory().bvh * 3 < copies.memory().bvh);
  CHECK(instanced.memory().instances * 3 < copies.memory().instances);
}

TEST_CASE("placements that repeat a rotation share its linear part and give the copies' hits", "[instancing]") {
  // A loop's placements: two rotations (one with a scale), each with many translations.
  std::mt19937_64 rng(77);
  SceneDesc s;
  const NodeId g = random_group(s, rng, 80);
  const Mat4 turn_a = rotate_deg(33.0, glm::normalize(Vec3(1, 2, 0.5)));
  const Mat4 turn_b = rotate_deg(-70.0, Vec3(0, 1, 0)) * scale(Vec3(1.5));
  for (int k = 0; k < 12; ++k) place(s, g, translate(random_point(rng, 15.0)) * (k % 2 ? turn_a : turn_b));
  const FlatScene flat = flatten_scene(s);
  REQUIRE(flat.groups.size() == 12);
  const World instanced(s, flat), copies(s, copied(s));
  CHECK(instanced.group_linear_count() == 2);
  CHECK(check_same_hits(instanced, copies, rng, 30.0, Vec3(0.0)) > 300);
  // A placement holds an index and two translations, not a 192-byte pair of matrices.
  STATIC_REQUIRE(sizeof(GroupTransform) <= 56);
}

TEST_CASE("a group's placements keep their matrices exactly in the flattened scene", "[instancing]") {
  // FlatGroup holds an index into the shapes' transforms (a shared linear part and its own
  // translation): the matrix given back is the placement's, bit for bit; the identity costs none.
  std::mt19937_64 rng(5);
  SceneDesc s;
  const NodeId g = random_group(s, rng, 70);
  const Mat4 odd = translate(Vec3(1e-300, -0.0, 3.25e7)) * rotate_deg(41.0, glm::normalize(Vec3(0.3, -1, 2)));
  const std::vector<Mat4> placed{Mat4(1.0), odd, translate(Vec3(2, 0, 0)) * odd, translate(Vec3(-5, 1, 9))};
  for (const Mat4& m : placed) place(s, g, m);
  const FlatScene flat = flatten_scene(s);
  REQUIRE(flat.groups.size() == placed.size());
  CHECK(flat.groups[0].transform == kNoId);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Mat4 back = flat.to_world(flat.groups[i]), composed = Mat4(1.0) * placed[i];  // as flattening composes it
    INFO("placement " << i);
    CHECK(std::memcmp(&back, &composed, sizeof(Mat4)) == 0);
  }
  CHECK(flat.linears.size() == 2);  // odd's (shared by two placements) and the translation's
  STATIC_REQUIRE(sizeof(FlatGroup) <= 12);
}

TEST_CASE("World::intersect writes every field of the hit it returns", "[instancing]") {
  // Integrator::shade keeps one WorldHit per thread instead of initialising a fresh one per
  // ray (render/shade/integrator.cpp): that is only right while a returned hit owes nothing to
  // what the record held before. A record full of sentinels must come back equal, field by
  // field, to a fresh one, for plain shapes, transformed ones, instanced groups and a plane.
  std::mt19937_64 rng(77);
  SceneDesc s;
  const NodeId g = random_group(s, rng, 60);
  place(s, g, translate(Vec3(3, 0, 1)) * rotate_deg(30.0, Vec3(0, 1, 0)));
  place(s, g);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), -6.0}));
  const FlatScene flat = flatten_scene(s);
  const World instanced(s, flat), copies(s, copied(s));
  auto sentinel = [] {
    WorldHit h;
    h.t = h.error = 1234.5;
    h.instance = h.medium = h.triangle = 0xDEADBEEF;
    h.point = h.normal = h.shading_normal = h.object_point = h.dpdu = h.dpdv = Vec3(-777.25);
    h.uv = h.bary = glm::dvec2(99.5);
    h.has_uv = true;
    return h;
  };
  int hits = 0;
  for (const World* world : {&instanced, &copies}) {
    for (int r = 0; r < 2000; ++r) {
      const Vec3 o = random_point(rng, 20.0);
      const Ray ray{o, random_point(rng, 8.0) - o};
      WorldHit fresh, reused = sentinel();
      const bool a = world->intersect(ray, Interval::positive(), fresh);
      REQUIRE(a == world->intersect(ray, Interval::positive(), reused));
      if (!a) continue;
      ++hits;
      CHECK(reused.t == fresh.t);
      CHECK(reused.instance == fresh.instance);
      CHECK(reused.medium == fresh.medium);
      CHECK(reused.point == fresh.point);
      CHECK(reused.error == fresh.error);
      CHECK(reused.normal == fresh.normal);
      CHECK(reused.shading_normal == fresh.shading_normal);
      CHECK(reused.object_point == fresh.object_point);
      CHECK(reused.uv == fresh.uv);
      CHECK(reused.has_uv == fresh.has_uv);
      CHECK(reused.dpdu == fresh.dpdu);
      CHECK(reused.dpdv == fresh.dpdv);
      CHECK(reused.triangle == fresh.triangle);
      CHECK(reused.bary == fresh.bary);
    }
  }
  CHECK(hits > 1000);
}

TEST_CASE("nested instanced groups and groups without a BVH", "[instancing]") {
  std::mt19937_64 rng(77);
  SceneDesc s;
  const NodeId leaf = random_group(s, rng, 70);
  // A row of the group (placed 3 times inside it), the row placed 4 times.
  const NodeId row = add_group(s, {Child{leaf, translate(Vec3(-9, 0, 0)), {}}, Child{leaf, Mat4(1.0), {}},
                                   Child{leaf, translate(Vec3(9, 0, 0)) * scale(Vec3(0.5)), {}}});
  for (int k = 0; k < 4; ++k) place(s, row, translate(Vec3(0, 0, 10.0 * k)) * rotate_deg(20.0 * k, Vec3(0, 1, 0)));
  const FlatScene flat = flatten_scene(s);
  REQUIRE(flat.groups.size() == 4);
  const World instanced(s, flat), copies(s, copied(s));
  REQUIRE(instanced.group_count() == 2);  // the row (3 placements of the leaf) and the leaf
  REQUIRE(instanced.group_part_count() == 70 + 3);
  CHECK(check_same_hits(instanced, copies, rng, 40.0, Vec3(0, 0, 15)) > 300);
}

TEST_CASE("which groups are instanced", "[instancing]") {
  auto group_of = [](SceneDesc& s, int n, MaterialId m) {
    std::vector<Child> kids;
    for (int i = 0; i < n; ++i) kids.push_back(Child{add_shape(s, Sphere{Vec3(i, 0, 0), 0.4}, m), Mat4(1.0), {}});
    return kids;
  };
  auto decide = [](SceneDesc& s, NodeId g, int placements) {
    for (int k = 0; k < placements; ++k) place(s, g, translate(Vec3(0, 0, 2.0 * k)));
    std::vector<bool> d = instanced_groups(s);
    const uint32_t index = s.nodes[g].index;
    return index < d.size() && d[index];
  };
  {
    SceneDesc s;
    CHECK(decide(s, add_group(s, group_of(s, int(kMinInstancedGroupShapes), kNoId)), 2));
  }
  {
    SceneDesc s;  // placed once: copied
    CHECK_FALSE(decide(s, add_group(s, group_of(s, 500, kNoId)), 1));
  }
  {
    SceneDesc s;  // too small to pay for a second level
    CHECK_FALSE(decide(s, add_group(s, group_of(s, int(kMinInstancedGroupShapes) - 1, kNoId)), 5));
  }
  {
    SceneDesc s;  // glass: media are paired by instance
    MaterialDesc glass;
    glass.transmit = Color(0.9);
    CHECK_FALSE(decide(s, add_group(s, group_of(s, 100, add_material(s, glass))), 3));
  }
  {
    SceneDesc s;  // an emitter: sampled by instance
    CHECK_FALSE(decide(s, add_group(s, group_of(s, 100, add_material(s, emissive(Color(1.0))))), 3));
  }
  {
    SceneDesc s;  // a light or a plane inside
    std::vector<Child> kids = group_of(s, 100, kNoId);
    kids.push_back(Child{add_light(s, LightDesc{}), Mat4(1.0), {}});
    CHECK_FALSE(decide(s, add_group(s, kids), 3));
    SceneDesc p;
    kids = group_of(p, 100, kNoId);
    kids.push_back(Child{add_shape(p, Plane{}), Mat4(1.0), {}});
    CHECK_FALSE(decide(p, add_group(p, kids), 3));
  }
}
