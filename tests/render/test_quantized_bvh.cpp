// The quantized top level (render/accel/quantized_bvh.hpp) against the binary tree it is made
// from: every decoded box encloses its subtree, every primitive is one leaf, and a World that
// traces with it returns exactly the binary tree's hits, occlusion answers and crossings.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "render/accel/bvh.hpp"
#include "render/accel/flatten.hpp"
#include "render/accel/quantized_bvh.hpp"
#include "render/accel/world.hpp"
#include "render/geometry/shapes/sphere.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

bool encloses(const QuantizedBox& outer, const AABB& inner) {
  for (int a = 0; a < 3; ++a)
    if (!(outer.lo[a] <= inner.lo[a] && outer.hi[a] >= inner.hi[a])) return false;
  return true;
}

// Walks the tree from the root's box, decoding as the traversal does; checks each leaf's box
// against its decoded box and counts the leaves per primitive.
void check_tree(const QuantizedBVH& tree, const std::vector<AABB>& boxes, std::vector<int>& seen) {
  struct Item {
    uint32_t ref;
    QuantizedBox box;
  };
  std::vector<Item> stack{{tree.root, tree.root_box}};
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (item.ref & QuantizedNode::kLeafBit) {
      const uint32_t p = item.ref & ~QuantizedNode::kLeafBit;
      REQUIRE(p < boxes.size());
      CHECK(encloses(item.box, boxes[p]));
      ++seen[p];
      continue;
    }
    REQUIRE(item.ref < tree.nodes.size());
    for (int c = 0; c < 2; ++c) {
      QuantizedBox child;
      decode_child(item.box, tree.nodes[item.ref], c, child);
      for (int a = 0; a < 3; ++a) {  // inside the parent's box
        CHECK(child.lo[a] >= item.box.lo[a]);
        CHECK(child.hi[a] <= item.box.hi[a]);
      }
      stack.push_back({tree.nodes[item.ref].child[c], child});
    }
  }
}

std::vector<AABB> random_boxes(std::mt19937_64& rng, int n, double centre_extent, double size) {
  std::uniform_real_distribution<double> u(-centre_extent, centre_extent), s(0.0, size);
  std::vector<AABB> boxes;
  for (int i = 0; i < n; ++i) {
    const Vec3 c(u(rng), u(rng), u(rng)), h(s(rng), s(rng), s(rng));
    boxes.push_back(AABB{c - h, c + h});
  }
  return boxes;
}

void check_quantized(const std::vector<AABB>& boxes) {
  const BVH bvh = build_bvh(boxes);
  const QuantizedBVH tree = quantize_bvh(bvh, [&](uint32_t i) { return boxes[i]; });
  REQUIRE_FALSE(tree.empty());
  CHECK(tree.nodes.size() == boxes.size() - 1);  // leaves of one: a node per pair
  std::vector<int> seen(boxes.size(), 0);
  check_tree(tree, boxes, seen);
  for (int count : seen) CHECK(count == 1);
}

}  // namespace

TEST_CASE("quantized BVH: decoded boxes enclose their subtrees, each primitive once", "[bvh][quantized]") {
  std::mt19937_64 rng(7);
  SECTION("small boxes spread out") { check_quantized(random_boxes(rng, 5000, 100.0, 0.5)); }
  SECTION("boxes far from the origin, tiny against their offset") {
    std::vector<AABB> boxes = random_boxes(rng, 3000, 1.0, 1e-3);
    for (AABB& b : boxes) {
      b.lo += Vec3(1e7, -3e6, 5e5);
      b.hi += Vec3(1e7, -3e6, 5e5);
    }
    check_quantized(boxes);
  }
  SECTION("boxes of every scale, nested and degenerate (flat, points)") {
    std::vector<AABB> boxes = random_boxes(rng, 2000, 10.0, 3.0);
    for (int i = 0; i < 500; ++i) {
      const double k = std::ldexp(1.0, -i % 40);
      boxes.push_back(AABB{Vec3(k, 0.0, -k), Vec3(k, 0.0, -k)});
      boxes.push_back(AABB{Vec3(-k, -k, 2.0), Vec3(k, k, 2.0)});
    }
    check_quantized(boxes);
  }
  SECTION("identical boxes: the binary tree's big leaves are split into leaves of one") {
    std::vector<AABB> boxes(700, AABB{Vec3(1, 2, 3), Vec3(1.5, 2.5, 3.5)});
    const BVH bvh = build_bvh(boxes);
    bool big_leaf = false;
    for (const BVHNode& n : bvh.nodes) big_leaf = big_leaf || n.count > 1;
    REQUIRE(big_leaf);
    check_quantized(boxes);
  }
  SECTION("one box: the root is a leaf") {
    const std::vector<AABB> boxes{AABB{Vec3(0), Vec3(1)}};
    const QuantizedBVH tree = quantize_bvh(build_bvh(boxes), [&](uint32_t i) { return boxes[i]; });
    REQUIRE_FALSE(tree.empty());
    CHECK(tree.root == (QuantizedNode::kLeafBit | 0u));
    CHECK(tree.nodes.empty());
  }
}

TEST_CASE("quantized BVH: float's whole range; boxes past it keep the binary tree", "[bvh][quantized]") {
  std::vector<AABB> boxes{AABB{Vec3(-3e38, 0, 0), Vec3(-2e38, 1, 1)}, AABB{Vec3(2e38, 0, 0), Vec3(3e38, 1, 1)},
                          AABB{Vec3(-1, -1e-30, 0), Vec3(1, 1e-30, 1)}};
  check_quantized(boxes);
  boxes = {AABB{Vec3(0), Vec3(1)}, AABB{Vec3(1e39, 0, 0), Vec3(2e39, 1, 1)}};  // inf in float
  CHECK(quantize_bvh(build_bvh(boxes), [&](uint32_t i) { return boxes[i]; }).empty());
}

#if defined(__SSE2__)
TEST_CASE("quantized BVH: the SSE2 decoding is decode_child's, bit for bit", "[bvh][quantized]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  std::uniform_int_distribution<int> code(0, 255);
  for (int trial = 0; trial < 20000; ++trial) {
    QuantizedBox parent;
    for (int a = 0; a < 3; ++a) {
      const double x = static_cast<float>(u(rng)), y = static_cast<float>(u(rng) * std::ldexp(1.0, -trial % 60));
      parent.lo[a] = std::min(x, x + y);
      parent.hi[a] = std::max(x, x + y);
    }
    QuantizedNode node{};
    for (uint8_t& q : node.code) q = static_cast<uint8_t>(code(rng));
    __m128d lo[3], hi[3];
    decode_children_sse2(quantized_pairs(parent), node, lo, hi);
    for (int c = 0; c < 2; ++c) {
      QuantizedBox scalar;
      decode_child(parent, node, c, scalar);
      for (int a = 0; a < 3; ++a) {
        alignas(16) double l[2], h[2];
        _mm_store_pd(l, lo[a]);
        _mm_store_pd(h, hi[a]);
        REQUIRE(std::memcmp(&l[c], &scalar.lo[a], sizeof(double)) == 0);
        REQUIRE(std::memcmp(&h[c], &scalar.hi[a], sizeof(double)) == 0);
      }
    }
  }
}
#endif

TEST_CASE("a World traced through the quantized top level gives the binary tree's answers", "[bvh][quantized]") {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> u(-10.0, 10.0), radius(0.02, 0.6);
  SceneDesc s;
  for (int i = 0; i < 3000; ++i) place(s, add_shape(s, Sphere{Vec3(u(rng), u(rng), u(rng)), radius(rng)}));
  // Clusters of touching and identical spheres, so the binary tree has leaves of several.
  for (int i = 0; i < 200; ++i) place(s, add_shape(s, Sphere{Vec3(3.0, 3.0, 3.0), 0.25}));
  const FlatScene flat = flatten_scene(s);
  World binary(s, flat);
  World quantized(s, flat, true, WorldBuild::BvhLater);
  quantized.set_quantized_top_level_from(1);
  quantized.build_bvh();
  REQUIRE_FALSE(binary.quantized_top_level());
  REQUIRE(quantized.quantized_top_level());
  CHECK(quantized.memory().bvh < binary.memory().bvh / 3);
  int hits = 0, blocked = 0;
  for (int r = 0; r < 4000; ++r) {
    const Vec3 o(u(rng) * 1.5, u(rng) * 1.5, u(rng) * 1.5);
    const Vec3 target = r % 8 == 0 ? Vec3(3.0, 3.0, 3.0) : Vec3(u(rng), u(rng), u(rng));
    const Ray ray{o, target - o};
    WorldHit a, b;
    const bool found_a = binary.intersect(ray, Interval::positive(), a);
    const bool found_b = quantized.intersect(ray, Interval::positive(), b);
    REQUIRE(found_a == found_b);
    if (found_a) {
      ++hits;
      CHECK(a.t == b.t);
      CHECK(a.instance == b.instance);
    }
    const Interval segment(0.0, 0.5);
    const bool occ = binary.occluded(ray, segment);
    CHECK(occ == quantized.occluded(ray, segment));
    blocked += occ ? 1 : 0;
  }
  CHECK(hits > 1000);
  CHECK(blocked > 100);
}
