// The BVHs against brute force: the same closest hit (and the same occlusion answer) for many
// random rays, over random spheres (top level) and random triangles (a mesh's bottom level).
#include <algorithm>
#include <cstring>
#include <limits>
#include <memory>
#include <random>

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include "render/accel/bvh.hpp"
#include "render/accel/flatten.hpp"
#include "render/accel/mesh_accel.hpp"
#include "render/geometry/shapes/sphere.hpp"
#include "render/geometry/shapes/triangle.hpp"
#include "render/accel/world.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

constexpr int kRays = 2000;

Vec3 random_point(std::mt19937_64& rng, double extent) {
  std::uniform_real_distribution<double> u(-extent, extent);
  return Vec3(u(rng), u(rng), u(rng));
}

Ray random_ray(std::mt19937_64& rng) {
  Vec3 o = random_point(rng, 15.0);
  Vec3 target = random_point(rng, 8.0);
  return Ray{o, target - o};  // deliberately not unit length
}

}  // namespace

TEST_CASE("BVH over random spheres finds the brute-force closest hit", "[bvh]") {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> radius(0.05, 1.0);
  SceneDesc s;
  std::vector<Sphere> spheres;
  for (int i = 0; i < 300; ++i) {
    Sphere sp{random_point(rng, 10.0), radius(rng)};
    spheres.push_back(sp);
    place(s, add_shape(s, sp));
  }
  World w(s, flatten_scene(s));
  REQUIRE(w.top_level().nodes.size() > 1);
  int hits = 0;
  for (int r = 0; r < kRays; ++r) {
    Ray ray = random_ray(rng);
    double best = Interval::kInfinity;
    for (const Sphere& sp : spheres) {
      SurfaceHit h;
      if (intersect(sp, ray, Interval(0.0, best), h)) best = h.t;
    }
    WorldHit wh;
    bool found = w.intersect(ray, Interval::positive(), wh);
    REQUIRE(found == (best < Interval::kInfinity));
    if (found) {
      ++hits;
      CHECK(wh.t == best);
    }
    CHECK(w.occluded(ray, Interval(0.0, 1.0)) == (best <= 1.0));
  }
  CHECK(hits > kRays / 10);  // the test exercises hits, not only misses
}

TEST_CASE("mesh BVH over random triangles finds the brute-force closest hit", "[bvh]") {
  std::mt19937_64 rng(777);
  auto mesh = std::make_shared<MeshData>();
  const int kTriangles = 500;
  for (int i = 0; i < kTriangles; ++i) {
    Vec3 c = random_point(rng, 8.0);
    for (int k = 0; k < 3; ++k) {
      mesh->positions.push_back(glm::vec3(c + random_point(rng, 1.5)));
      mesh->indices.push_back(static_cast<uint32_t>(mesh->positions.size() - 1));
    }
  }
  MeshAccel accel(mesh);
  REQUIRE(accel.triangle_count() == kTriangles);
  int hits = 0;
  for (int r = 0; r < kRays; ++r) {
    Ray ray = random_ray(rng);
    double best = Interval::kInfinity;
    for (int i = 0; i < kTriangles; ++i) {
      double t, b1, b2;
      Vec3 v0(mesh->positions[i * 3]), v1(mesh->positions[i * 3 + 1]), v2(mesh->positions[i * 3 + 2]);
      if (intersect_triangle(v0, v1, v2, ray, Interval(0.0, best), t, b1, b2)) best = t;
    }
    SurfaceHit h;
    bool found = accel.intersect(ray, Interval::positive(), h, true);
    REQUIRE(found == (best < Interval::kInfinity));
    if (found) {
      ++hits;
      CHECK(h.t == best);
    }
    CHECK(accel.occluded(ray, Interval(0.0, 0.5)) == (best <= 0.5));
  }
  CHECK(hits > kRays / 10);
}

TEST_CASE("mesh BVH: triangles left out (bad index, infinite vertex) keep the others' indices", "[bvh]") {
  // Five unit triangles side by side along x; the second and fourth cannot be hit.
  auto mesh = std::make_shared<MeshData>();
  for (int i = 0; i < 5; ++i) {
    const float x = static_cast<float>(2 * i);
    mesh->positions.push_back({x, 0, 0});
    mesh->positions.push_back({x + 1, 0, 0});
    mesh->positions.push_back({x, 1, 0});
    const uint32_t base = static_cast<uint32_t>(3 * i);
    mesh->indices.insert(mesh->indices.end(), {base, base + 1, base + 2});
  }
  mesh->indices[3 * 1 + 2] = 999;                              // triangle 1: index out of range
  mesh->positions[3 * 3 + 1].y = std::numeric_limits<float>::infinity();  // triangle 3: not finite
  MeshAccel accel(mesh);
  CHECK(accel.triangle_count() == 3);
  for (int i = 0; i < 5; ++i) {
    Ray ray{Vec3(2 * i + 0.25, 0.25, -1), Vec3(0, 0, 1)};
    SurfaceHit h;
    const bool found = accel.intersect(ray, Interval::positive(), h, false);
    CHECK(found == (i % 2 == 0));
    if (found) CHECK(h.triangle == static_cast<uint32_t>(i));  // the mesh's own index
  }
}

TEST_CASE("BVH build: every primitive appears once; leaves are small", "[bvh]") {
  std::mt19937_64 rng(5);
  std::vector<AABB> boxes;
  for (int i = 0; i < 1000; ++i) {
    Vec3 c = random_point(rng, 100.0);
    boxes.push_back(AABB{c - Vec3(0.5), c + Vec3(0.5)});
  }
  BVH bvh = build_bvh(boxes);
  std::vector<int> seen(boxes.size(), 0);
  std::size_t max_leaf = 0;
  for (const BVHNode& n : bvh.nodes) {
    if (n.count == 0) continue;
    max_leaf = std::max<std::size_t>(max_leaf, n.count);
    for (uint32_t i = 0; i < n.count; ++i) {
      uint32_t prim = bvh.order[n.offset + i];
      ++seen[prim];
      // The leaf box encloses its primitives.
      CHECK(n.bounds().lo.x <= boxes[prim].lo.x);
      CHECK(n.bounds().hi.y >= boxes[prim].hi.y);
    }
  }
  for (int count : seen) CHECK(count == 1);
  CHECK(max_leaf <= static_cast<std::size_t>(kBvhMaxLeafSize));
}

TEST_CASE("BVH build with identical primitives terminates and keeps them all", "[bvh]") {
  std::vector<AABB> boxes(100, AABB{Vec3(0), Vec3(1)});
  BVH bvh = build_bvh(boxes);
  std::size_t total = 0;
  for (const BVHNode& n : bvh.nodes) total += n.count;
  CHECK(total == boxes.size());
}

TEST_CASE("large BVHs (built in parallel) are valid and the same on every build", "[bvh]") {
  std::mt19937_64 rng(99);
  const int n = 80'000;  // above the parallel build threshold
  std::vector<AABB> boxes;
  std::vector<Sphere> spheres;
  for (int i = 0; i < n; ++i) {
    Sphere sp{random_point(rng, 50.0), 0.2};
    spheres.push_back(sp);
    boxes.push_back(bounds(sp));
  }
  BVH a = build_bvh(boxes), b = build_bvh(boxes);
  REQUIRE(a.nodes.size() == b.nodes.size());
  CHECK(std::equal(a.order.begin(), a.order.end(), b.order.begin()));
  bool same_nodes = true;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    same_nodes = same_nodes && a.nodes[i].offset == b.nodes[i].offset && a.nodes[i].count == b.nodes[i].count;
  CHECK(same_nodes);

  // Every primitive once; every node's children inside it; closest hits match brute force.
  std::vector<int> seen(n, 0);
  for (const BVHNode& node : a.nodes)
    for (uint32_t i = 0; i < node.count; ++i) ++seen[a.order[node.offset + i]];
  CHECK(std::count(seen.begin(), seen.end(), 1) == n);
  for (int r = 0; r < 200; ++r) {
    Ray ray = random_ray(rng);
    double best = Interval::kInfinity;
    for (const Sphere& sp : spheres) {
      SurfaceHit h;
      if (intersect(sp, ray, Interval(0.0, best), h)) best = h.t;
    }
    Interval range = Interval::positive();
    traverse_bvh<false>(a, ray, range, [&](uint32_t slot, Interval& t_range) {
      SurfaceHit h;
      if (!intersect(spheres[a.order[slot]], ray, t_range, h)) return false;
      t_range.max = h.t;
      return true;
    });
    CHECK(range.max == best);
  }
}

TEST_CASE("one thread and several build the same tree, bit for bit", "[bvh]") {
  // With several threads the passes over a long range run on its halves at once and merge,
  // and subtrees are built aside and spliced; with one, neither: the trees must not differ,
  // down to the float bounds' signed zeros (boxes on the axes planes have zero bounds).
  std::mt19937_64 rng(123);
  const int n = 90'000;  // above the parallel build threshold, at several levels
  std::vector<AABB> boxes;
  std::uniform_int_distribution<int> cell(-40, 40);
  for (int i = 0; i < n; ++i) {
    // Boxes standing on the plane y = 0, their lower bound +0 or -0 (which of the two a
    // node's bound takes depends on the order the references are met), and many exact zeros
    // elsewhere.
    Vec3 c(cell(rng) * 0.5, 0.0, cell(rng) * 0.5);
    AABB box{c - Vec3(i % 3 == 0 ? 0.0 : 0.25, 0.0, 0.25), c + Vec3(0.25, 0.25 + (i % 7) * 0.25, 0.25)};
    if (rng() % 2 == 1)
      for (int a = 0; a < 3; ++a) {
        if (box.lo[a] == 0.0) box.lo[a] = -0.0;
        if (box.hi[a] == 0.0) box.hi[a] = -0.0;
      }
    boxes.push_back(box);
  }
  auto build_with = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return build_bvh(boxes);
  };
  const BVH one = build_with(1), several = build_with(4);
  REQUIRE(one.nodes.size() == several.nodes.size());
  CHECK(one.order == several.order);
  bool same = true;
  for (std::size_t i = 0; i < one.nodes.size(); ++i) {
    const BVHNode &a = one.nodes[i], &b = several.nodes[i];
    // Bounds by their bits: -0 and +0 compare equal as floats.
    same = same && std::memcmp(a.lo, b.lo, sizeof a.lo) == 0 && std::memcmp(a.hi, b.hi, sizeof a.hi) == 0 &&
           a.offset == b.offset && a.count == b.count && a.axis == b.axis;
  }
  CHECK(same);
}

TEST_CASE("a tree built for the quantizer ends in leaves of up to N, the SAH not asked", "[bvh]") {
  // Separate boxes: the SAH splits them down to leaves of one; with leaves_of_up_to = 4 every
  // range of four or fewer is one leaf (about a third of the nodes), each box still once.
  std::mt19937_64 rng(5);
  const int n = 50'000;
  std::vector<AABB> boxes;
  for (int i = 0; i < n; ++i) {
    const Vec3 c = random_point(rng, 100.0);
    boxes.push_back(AABB{c - Vec3(0.01), c + Vec3(0.01)});
  }
  auto box_of = [&](std::size_t i) { return boxes[i]; };
  const BVH sah = build_bvh(n, box_of), four = build_bvh(n, box_of, 4);
  std::vector<int> seen(n, 0);
  std::size_t largest = 0;
  bool interior_large = true;  // every interior node holds more than four
  std::vector<uint32_t> under(four.nodes.size(), 0);
  for (std::size_t k = four.nodes.size(); k-- > 0;) {
    const BVHNode& node = four.nodes[k];
    if (node.count > 0) {
      under[k] = node.count;
      largest = std::max<std::size_t>(largest, node.count);
      for (uint32_t i = 0; i < node.count; ++i) ++seen[four.order[node.offset + i]];
    } else {
      under[k] = under[k + 1] + under[node.offset];
      interior_large = interior_large && under[k] > 4;
    }
  }
  CHECK(std::count(seen.begin(), seen.end(), 1) == n);
  CHECK(largest <= 4);
  CHECK(interior_large);
  CHECK(four.nodes.size() < sah.nodes.size() / 2);
}

TEST_CASE("float boxes build the same tree as the same boxes in double", "[bvh]") {
  // Mesh triangles pass float boxes (FloatBox, 28-byte builder references); boxes given as
  // AABB take the compact path too, rounded outwards, when every rounded box is finite, else
  // the double one. Float boxes and the same float-exact boxes in double must give one tree,
  // also above the parallel build threshold.
  std::mt19937_64 rng(7);
  const int n = 40'000;
  std::vector<AABB> exact;
  std::vector<FloatBox> floats;
  for (int i = 0; i < n; ++i) {
    glm::vec3 c(random_point(rng, 30.0));
    glm::vec3 lo = c - 0.3f, hi = c + glm::vec3(0.1f, 0.4f, 0.2f);
    exact.push_back(AABB{Vec3(lo), Vec3(hi)});
    floats.push_back(FloatBox{{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}});
  }
  // The same boxes nudged off float values (rounded outwards: a float step larger), and moved
  // past float's range (1e39: the double references): their trees may differ where the change
  // moves a comparison, so they are checked for validity, not equality.
  std::vector<AABB> wide = exact;
  for (AABB& b : wide) b.hi += Vec3(1e-12);
  std::vector<AABB> far = exact;
  for (AABB& b : far) {
    b.lo.x = b.lo.x * 1e38 + 1e39;
    b.hi.x = b.hi.x * 1e38 + 1e39;
  }
  BVH a = build_bvh(exact), b = build_bvh(floats), c = build_bvh(wide), d = build_bvh(far);
  REQUIRE(a.nodes.size() == b.nodes.size());
  CHECK(a.order == b.order);
  bool same = true;
  for (std::size_t i = 0; i < a.nodes.size(); ++i)
    same = same && a.nodes[i].offset == b.nodes[i].offset && a.nodes[i].count == b.nodes[i].count &&
           a.nodes[i].axis == b.nodes[i].axis && std::equal(a.nodes[i].lo, a.nodes[i].lo + 3, b.nodes[i].lo) &&
           std::equal(a.nodes[i].hi, a.nodes[i].hi + 3, b.nodes[i].hi);
  CHECK(same);
  std::vector<int> seen(n, 0);
  for (const BVHNode& node : c.nodes)
    for (uint32_t i = 0; i < node.count; ++i) ++seen[c.order[node.offset + i]];
  CHECK(std::count(seen.begin(), seen.end(), 1) == n);
  // Every node's float bounds enclose the double boxes of its primitives (rounded outwards),
  // and a node's box encloses its children's.
  auto check_tree = [&](const BVH& t, const std::vector<AABB>& boxes) {
    std::vector<int> count(n, 0);
    bool encloses = true;
    for (std::size_t k = 0; k < t.nodes.size(); ++k) {
      const BVHNode& node = t.nodes[k];
      for (uint32_t i = 0; i < node.count; ++i) {
        const AABB& box = boxes[t.order[node.offset + i]];
        ++count[t.order[node.offset + i]];
        for (int a = 0; a < 3; ++a) encloses = encloses && node.lo[a] <= box.lo[a] && box.hi[a] <= node.hi[a];
      }
      if (node.count == 0)
        for (std::size_t child : {k + 1, std::size_t{node.offset}})
          for (int a = 0; a < 3; ++a)
            encloses = encloses && node.lo[a] <= t.nodes[child].lo[a] && t.nodes[child].hi[a] <= node.hi[a];
    }
    CHECK(encloses);
    CHECK(std::count(count.begin(), count.end(), 1) == n);
  };
  check_tree(c, wide);
  check_tree(d, far);
  // The far boxes still split along y and z (finite there) rather than piling into leaves.
  std::size_t leaves = 0, largest = 0;
  for (const BVHNode& node : d.nodes)
    if (node.count > 0) {
      ++leaves;
      largest = std::max<std::size_t>(largest, node.count);
    }
  CHECK(leaves > n / 8);
  CHECK(largest <= kBvhMaxLeafSize);
}

TEST_CASE("shadow rays tested against the occluder candidates get occluded()'s answer", "[bvh]") {
  // World::occluder_candidates keeps the leaves and planes that meet the pyramid from a point
  // over an area light; every segment in the pyramid must get the same answer from them
  // (occluded_by) as from the whole scene (occluded), including points on the floor plane.
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> radius(0.05, 0.8), unit(0.0, 1.0);
  SceneDesc s;
  for (int i = 0; i < 200; ++i) place(s, add_shape(s, Sphere{random_point(rng, 9.0), radius(rng)}));
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), -10.0}));
  const bool quantized = GENERATE(false, true);  // the top level as float boxes, or quantized
  CAPTURE(quantized);
  World w(s, flatten_scene(s), true, WorldBuild::BvhLater);
  if (quantized) w.set_quantized_top_level_from(1);
  w.build_bvh();
  REQUIRE(w.quantized_top_level() == quantized);
  REQUIRE(w.bvh_nodes() > 1);
  const Vec3 u(3, 0, 0.5), v(0, 0.2, 3);
  int searched = 0, blocked = 0, open = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Vec3 apex = random_point(rng, 10.0);
    if (trial % 4 == 0) apex.y = -10.0;                  // on the floor
    if (trial % 4 == 1) apex.y = std::nextafter(-10.0, 0.0);  // just above it
    const Vec3 centre = random_point(rng, 4.0) + Vec3(0, 12, 0);
    OccluderCandidates c;
    if (!w.occluder_candidates(shadow_pyramid(apex, centre, u, v), c)) continue;
    ++searched;
    for (int k = 0; k < 16; ++k) {
      const Vec3 target = centre + (unit(rng) - 0.5) * u + (unit(rng) - 0.5) * v;
      const Ray ray{apex, target - apex};
      const Interval segment(0.0, 1.0 - 1e-9);
      const bool expected = w.occluded(ray, segment);
      REQUIRE(w.occluded_by(c, ray, segment) == expected);
      (expected ? blocked : open) += 1;
    }
  }
  CHECK(searched > 100);  // the search answers most points (few leaves meet each pyramid)
  CHECK(blocked > 100);   // both answers are exercised
  CHECK(open > 100);
}
