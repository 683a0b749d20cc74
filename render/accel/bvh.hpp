// Bounding volume hierarchy over primitives given by their boxes: binned SAH build, nodes
// flattened depth-first (left child follows its parent), traversal ordered by the ray's
// direction along the split axis. Used twice: over instances (top level) and over each
// mesh's triangles (bottom level).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "render/geometry/aabb.hpp"
#include "render/geometry/ray.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rts::render {

// 32 bytes: two nodes per cache line. Bounds are stored as float, rounded outwards so they
// still enclose their primitives; the slab test itself runs in double.
struct BVHNode {
  float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  uint32_t offset = 0;  // leaf: first slot in `order`; interior: index of the right child
  uint16_t count = 0;   // leaf: number of primitives; 0 marks an interior node
  uint8_t axis = 0;     // interior: the split axis

  void set_bounds(const AABB& b);
  AABB bounds() const {
    return AABB{Vec3(lo[0], lo[1], lo[2]), Vec3(hi[0], hi[1], hi[2])};
  }
};

// The float box that encloses b: each bound rounded outwards (infinite past float's range).
void round_outwards(const AABB& b, float lo[3], float hi[3]);

struct BVH {
  std::vector<BVHNode> nodes;
  std::vector<uint32_t> order;  // primitive indices, leaf ranges are contiguous
  bool empty() const { return nodes.empty(); }
};

inline constexpr int kBvhBins = 16;
inline constexpr int kBvhMaxLeafSize = 4;
inline constexpr int kBvhMaxLeafCount = 65535;  // BVHNode::count's range
inline constexpr int kBvhMaxDepth = 64;         // deeper: forced median splits (< 32 more)
inline constexpr int kBvhTraversalStack = 128;  // > the deepest possible tree

// Takes the boxes by value and frees them before the nodes are built (callers done with them
// move them in): the build's peak holds the builder's references, not both.
BVH build_bvh(std::vector<AABB> primitive_bounds);

// Bounds given in float (mesh triangles: their vertices are floats): the same tree as the
// double overload builds for the same boxes, without a 48-byte double box per primitive.
struct FloatBox {
  float lo[3], hi[3];
};
BVH build_bvh(const std::vector<FloatBox>& primitive_bounds);
// The same, with the boxes made on demand (`box_of(i)` for i < count, called once each, from
// several threads at once), so no box array sits beside the builder's own references: 24
// bytes per triangle of the peak.
BVH build_bvh(std::size_t count, const std::function<FloatBox(std::size_t)>& box_of);
// Double boxes made on demand (`box_of(i)` called twice each: once to see whether every box is
// float-exact, once into the references): the same tree as the array overload builds. With
// `leaves_of_up_to` > 0, every range of that many primitives or fewer is a leaf, the SAH not
// asked: a tree made to be quantized (quantize_bvh splits its leaves), a third of the nodes
// where the SAH would split separate boxes down to leaves of one.
BVH build_bvh(std::size_t count, const std::function<AABB(std::size_t)>& box_of, uint32_t leaves_of_up_to = 0);

// slab_hit on two sibling nodes at once: bit-for-bit the scalar test's answers (the same
// double operations, one child per SSE2 lane; MINPD/MAXPD return their second operand on a
// NaN exactly as the scalar comparisons keep the old value). Profile finding (perf, spheres
// and terrain): the two child box tests of each interior node are most of the traversal.
#if defined(__SSE2__)
// The slab test of two boxes given as (left, right) lanes per axis.
inline void slab_hit_lanes(const __m128d lo[3], const __m128d hi[3], const RayInverse& inv, const Interval& ray_t,
                           bool& hit_l, double& t_l, bool& hit_r, double& t_r) {
  __m128d t0 = _mm_set1_pd(ray_t.min), t1 = _mm_set1_pd(ray_t.max);
  for (int a = 0; a < 3; ++a) {
    const __m128d o = _mm_set1_pd(inv.origin[a]), d = _mm_set1_pd(inv.inv_dir[a]);
    const __m128d ta = _mm_mul_pd(_mm_sub_pd(lo[a], o), d);
    const __m128d tb = _mm_mul_pd(_mm_sub_pd(hi[a], o), d);
    // if (ta > tb) swap: near = ta > tb ? tb : ta, far = ta > tb ? ta : tb.
    const __m128d near = _mm_min_pd(tb, ta), far = _mm_max_pd(ta, tb);
    t0 = _mm_max_pd(near, t0);  // near > t0 ? near : t0
    t1 = _mm_min_pd(far, t1);   // far < t1 ? far : t1
  }
  const int hits = _mm_movemask_pd(_mm_cmple_pd(t0, t1));
  alignas(16) double entry[2];
  _mm_store_pd(entry, t0);
  hit_l = (hits & 1) != 0;
  hit_r = (hits & 2) != 0;
  t_l = entry[0];
  t_r = entry[1];
}
#endif

// Any box with `lo[3]` and `hi[3]` (BVHNode's float, QuantizedBox's double).
template <class Box>
inline void slab_hit_pair(const Box& l, const Box& r, const RayInverse& inv, const Interval& ray_t,
                          bool& hit_l, double& t_l, bool& hit_r, double& t_r) {
#if defined(__SSE2__)
  __m128d lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = _mm_set_pd(static_cast<double>(r.lo[a]), static_cast<double>(l.lo[a]));
    hi[a] = _mm_set_pd(static_cast<double>(r.hi[a]), static_cast<double>(l.hi[a]));
  }
  slab_hit_lanes(lo, hi, inv, ray_t, hit_l, t_l, hit_r, t_r);
#else
  auto bounds = [](const Box& b) {
    return AABB{Vec3(b.lo[0], b.lo[1], b.lo[2]), Vec3(b.hi[0], b.hi[1], b.hi[2])};
  };
  hit_l = slab_hit(bounds(l), inv, ray_t, t_l);
  hit_r = slab_hit(bounds(r), inv, ray_t, t_r);
#endif
}

// Visits the leaves a ray may hit, nearest child first (both children's boxes are tested at
// their parent; the farther one waits on the stack with its entry distance and is skipped if
// a closer hit has been found meanwhile). `leaf(slot, ray_t)` tests the primitive at position
// `slot` of bvh.order (callers may keep per-slot data in leaf order), shrinking ray_t.max on a
// hit and returning true; with `any_hit` the traversal stops at the first hit (shadow rays).
template <bool any_hit, class LeafFn>
bool traverse_bvh(const BVH& bvh, const Ray& ray, Interval& ray_t, LeafFn&& leaf) {
  if (bvh.nodes.empty()) return false;
  RayInverse inv(ray.origin, ray.direction);
  if (!slab_hit(bvh.nodes[0].bounds(), inv, ray_t)) return false;
  struct Pending {
    uint32_t node;
    double t_entry;
  };
  Pending stack[kBvhTraversalStack];
  int top = 0;
  uint32_t node_index = 0;
  bool hit = false;
  while (true) {
    const BVHNode& node = bvh.nodes[node_index];
    if (node.count > 0) {
      for (uint32_t i = 0; i < node.count; ++i) {
        if (leaf(node.offset + i, ray_t)) {
          hit = true;
          if constexpr (any_hit) return true;
        }
      }
    } else {
      uint32_t left = node_index + 1, right = node.offset;
      double t_left, t_right;
      bool hit_left, hit_right;
      slab_hit_pair(bvh.nodes[left], bvh.nodes[right], inv, ray_t, hit_left, t_left, hit_right, t_right);
      if (hit_left && hit_right) {
        if (t_right < t_left) {
          std::swap(left, right);
          std::swap(t_left, t_right);
        }
        stack[top++] = Pending{right, t_right};
        node_index = left;
        continue;
      }
      if (hit_left || hit_right) {
        node_index = hit_left ? left : right;
        continue;
      }
    }
    // Next pending subtree that can still hold a closer hit.
    while (top > 0 && stack[top - 1].t_entry > ray_t.max) --top;
    if (top == 0) break;
    node_index = stack[--top].node;
  }
  return hit;
}

}  // namespace rts::render
