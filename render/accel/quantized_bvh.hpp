// The top-level BVH of a scene of a million placements or more (World::build_bvh), in 20 bytes
// per instance where the binary tree of float boxes takes 68 (two 32-byte nodes and a 4-byte
// index; issue 24 asks for <= 64 bytes a placement). Each interior node holds its two
// children's boxes in 8 bits per bound, counted in 1/255ths of its own box's extent (in from
// its lower bound for a child's lower bound, in from its upper bound for the upper one, so 0
// is its own bound exactly), and the two children themselves: a node's index, or an instance
// with kLeafBit.
// Leaves hold one instance each, so no index array is needed. The traversal decodes a child's
// box from its parent's decoded box with the same double operations the build checked: every
// decoded box encloses its subtree's boxes (the build steps a bound outwards until it does),
// so the tree finds the same hits as the binary tree it is made from; it only tests looser
// boxes. The root's box is the binary tree's, kept whole.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "render/accel/bvh.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rts::render {

// A decoded box (or the root's own bounds, the binary tree's float box), in double: the
// traversal's slab test runs in double, and decoding straight to double saves a conversion.
struct QuantizedBox {
  double lo[3], hi[3];
};

// Codes by axis and child, so that one axis's two children are adjacent (one SSE2 pair):
// code[2a + c] is child c's lower bound along axis a, in steps above this box's lower bound;
// code[6 + 2a + c] its upper bound, in steps below this box's upper bound.
struct QuantizedNode {
  uint8_t code[12];
  uint32_t child[2];  // an interior node's index, or kLeafBit | the instance
  static constexpr uint32_t kLeafBit = 0x80000000u;
};
static_assert(sizeof(QuantizedNode) == 20, "20 bytes a node, one node per instance");

// One step of a box's extent along one axis: 1/255th of it (255 steps span the box).
inline double quantized_step(double lo, double hi) { return (hi - lo) * (1.0 / 255.0); }

// Child c's box of `node` whose own box is `parent`. The build checks its codes with this very
// function, and decode_children_sse2 computes the same operations lane by lane, so the
// traversal's boxes are the ones that were checked to enclose.
inline void decode_child(const QuantizedBox& parent, const QuantizedNode& node, int c, QuantizedBox& out) {
  for (int a = 0; a < 3; ++a) {
    const double step = quantized_step(parent.lo[a], parent.hi[a]);
    out.lo[a] = parent.lo[a] + static_cast<double>(node.code[2 * a + c]) * step;
    out.hi[a] = parent.hi[a] - static_cast<double>(node.code[6 + 2 * a + c]) * step;
  }
}

#if defined(__SSE2__)
// A box as one (lower, upper) pair per axis: kept in registers and stored whole, so that no
// 16-byte load reads two 8-byte stores (perf: the store-forwarding stalls of copying decoded
// boxes were most of the first quantized walk's extra time).
struct alignas(16) QuantizedPairs {
  __m128d axis[3];
};

inline QuantizedPairs quantized_pairs(const QuantizedBox& b) {
  return QuantizedPairs{{_mm_set_pd(b.hi[0], b.lo[0]), _mm_set_pd(b.hi[1], b.lo[1]), _mm_set_pd(b.hi[2], b.lo[2])}};
}

// Both children's bounds along each axis as (child 0, child 1) lanes: decode_child's
// operations, two lanes at a time, from the parent's pairs.
inline void decode_children_sse2(const QuantizedPairs& parent, const QuantizedNode& node, __m128d lo[3], __m128d hi[3]) {
  const __m128i zero = _mm_setzero_si128();
  // The 12 codes and the first child's 4 bytes (not used), read as one: a memcpy of 12 bytes
  // went through the stack as an 8- and a 4-byte store read back by one 16-byte load, a
  // store-forwarding stall at every node (perf annotate: 28% of the walk on that load).
  static_assert(offsetof(QuantizedNode, code) == 0 && offsetof(QuantizedNode, child) == 12);
  const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&node));
  const __m128i words = _mm_unpacklo_epi8(bytes, zero);
  const __m128i ints_lo = _mm_unpacklo_epi16(words, zero);   // codes 0-3
  const __m128i ints_mid = _mm_unpackhi_epi16(words, zero);  // codes 4-7
  const __m128i ints_hi = _mm_unpacklo_epi16(_mm_unpackhi_epi8(bytes, zero), zero);  // codes 8-11
  const __m128d code[6] = {_mm_cvtepi32_pd(ints_lo), _mm_cvtepi32_pd(_mm_srli_si128(ints_lo, 8)),
                           _mm_cvtepi32_pd(ints_mid), _mm_cvtepi32_pd(_mm_srli_si128(ints_mid, 8)),
                           _mm_cvtepi32_pd(ints_hi), _mm_cvtepi32_pd(_mm_srli_si128(ints_hi, 8))};
  const __m128d inv255 = _mm_set1_pd(1.0 / 255.0);
  for (int a = 0; a < 3; ++a) {
    const __m128d plo = _mm_unpacklo_pd(parent.axis[a], parent.axis[a]);
    const __m128d phi = _mm_unpackhi_pd(parent.axis[a], parent.axis[a]);
    const __m128d step = _mm_mul_pd(_mm_sub_pd(phi, plo), inv255);  // quantized_step
    lo[a] = _mm_add_pd(plo, _mm_mul_pd(code[a], step));
    hi[a] = _mm_sub_pd(phi, _mm_mul_pd(code[3 + a], step));
  }
}

// Child c's pairs from decode_children_sse2's lanes.
inline QuantizedPairs child_pairs(const __m128d lo[3], const __m128d hi[3], int c) {
  QuantizedPairs p;
  for (int a = 0; a < 3; ++a) p.axis[a] = c == 0 ? _mm_unpacklo_pd(lo[a], hi[a]) : _mm_unpackhi_pd(lo[a], hi[a]);
  return p;
}
#endif

struct QuantizedBVH {
  std::vector<QuantizedNode> nodes;
  QuantizedBox root_box{};
  uint32_t root = 0;  // a node's index, or kLeafBit | the instance when there is one instance
  bool present = false;
  bool empty() const { return !present; }
};

// The quantized form of `bvh`, whose leaves' entries in `bvh.order` are primitives with boxes
// `box_of(i)` (read only for leaves of more than one primitive: those are split into leaves of
// one). Returns an empty tree when a box is not finite in float (steps of an infinite extent
// decode to NaN) or there are 2^31 primitives or more: the caller keeps the binary tree.
QuantizedBVH quantize_bvh(const BVH& bvh, const std::function<AABB(uint32_t)>& box_of);

// traverse_bvh's contract on the quantized tree: `leaf(instance, ray_t)` is called with the
// instance itself (there is no `order`), nearest child first, with the same pruning.
template <bool any_hit, class LeafFn>
bool traverse_quantized(const QuantizedBVH& tree, const Ray& ray, Interval& ray_t, LeafFn&& leaf) {
  if (tree.empty()) return false;
  RayInverse inv(ray.origin, ray.direction);
  const QuantizedBox& root = tree.root_box;
  const AABB root_bounds{Vec3(root.lo[0], root.lo[1], root.lo[2]), Vec3(root.hi[0], root.hi[1], root.hi[2])};
  if (!slab_hit(root_bounds, inv, ray_t)) return false;
#if defined(__SSE2__)
  using Box = QuantizedPairs;
  Box box = quantized_pairs(root);
#else
  using Box = QuantizedBox;
  Box box = root;
#endif
  struct Pending {
    Box box;
    double t_entry;
    uint32_t ref;
  };
  Pending stack[kBvhTraversalStack];
  int top = 0;
  uint32_t ref = tree.root;
  bool hit = false;
  while (true) {
    if (ref & QuantizedNode::kLeafBit) {
      if (leaf(ref & ~QuantizedNode::kLeafBit, ray_t)) {
        hit = true;
        if constexpr (any_hit) return true;
      }
    } else {
      const QuantizedNode& node = tree.nodes[ref];
      double t_left, t_right;
      bool hit_left, hit_right;
#if defined(__SSE2__)
      __m128d lo[3], hi[3];
      decode_children_sse2(box, node, lo, hi);
      slab_hit_lanes(lo, hi, inv, ray_t, hit_left, t_left, hit_right, t_right);
      auto child_box = [&](int c) { return child_pairs(lo, hi, c); };
#else
      QuantizedBox kids[2];
      decode_child(box, node, 0, kids[0]);
      decode_child(box, node, 1, kids[1]);
      slab_hit_pair(kids[0], kids[1], inv, ray_t, hit_left, t_left, hit_right, t_right);
      auto child_box = [&](int c) { return kids[c]; };
#endif
      if (hit_left && hit_right) {
        const int near = t_right < t_left ? 1 : 0;
        stack[top++] = Pending{child_box(1 - near), near == 0 ? t_right : t_left, node.child[1 - near]};
        ref = node.child[near];
        box = child_box(near);
        continue;
      }
      if (hit_left || hit_right) {
        const int c = hit_left ? 0 : 1;
        ref = node.child[c];
        box = child_box(c);
        continue;
      }
    }
    while (top > 0 && stack[top - 1].t_entry > ray_t.max) --top;
    if (top == 0) break;
    --top;
    ref = stack[top].ref;
    box = stack[top].box;
  }
  return hit;
}

}  // namespace rts::render
