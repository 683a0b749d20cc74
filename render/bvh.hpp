// Bounding volume hierarchy over primitives given by their boxes: binned SAH build, nodes
// flattened depth-first (left child follows its parent), traversal ordered by the ray's
// direction along the split axis. Used twice: over instances (top level) and over each
// mesh's triangles (bottom level).
#pragma once

#include <cstdint>
#include <vector>

#include "render/aabb.hpp"
#include "render/ray.hpp"

namespace rts::render {

struct BVHNode {
  AABB bounds;
  uint32_t offset = 0;  // leaf: first index into `order`; interior: index of the right child
  uint32_t count = 0;   // leaf: number of primitives; 0 marks an interior node
  uint8_t axis = 0;     // interior: the split axis
};

struct BVH {
  std::vector<BVHNode> nodes;
  std::vector<uint32_t> order;  // primitive indices, leaf ranges are contiguous
  bool empty() const { return nodes.empty(); }
};

inline constexpr int kBvhBins = 16;
inline constexpr int kBvhMaxLeafSize = 4;
inline constexpr int kBvhMaxDepth = 60;        // below the traversal stack size
inline constexpr int kBvhTraversalStack = 64;

BVH build_bvh(const std::vector<AABB>& primitive_bounds);

// Visits the leaves a ray may hit, nearest side first. `leaf(prim, ray_t)` tests one
// primitive, shrinking ray_t.max on a hit and returning true; with `any_hit` the traversal
// stops at the first hit (shadow rays).
template <bool any_hit, class LeafFn>
bool traverse_bvh(const BVH& bvh, const Ray& ray, Interval& ray_t, LeafFn&& leaf) {
  if (bvh.nodes.empty()) return false;
  RayInverse inv(ray.origin, ray.direction);
  bool dir_negative[3] = {ray.direction.x < 0, ray.direction.y < 0, ray.direction.z < 0};
  uint32_t stack[kBvhTraversalStack];
  int top = 0;
  uint32_t node_index = 0;
  bool hit = false;
  while (true) {
    const BVHNode& node = bvh.nodes[node_index];
    if (slab_hit(node.bounds, inv, ray_t)) {
      if (node.count > 0) {
        for (uint32_t i = 0; i < node.count; ++i) {
          if (leaf(bvh.order[node.offset + i], ray_t)) {
            hit = true;
            if constexpr (any_hit) return true;
          }
        }
        if (top == 0) break;
        node_index = stack[--top];
      } else if (dir_negative[node.axis]) {
        stack[top++] = node_index + 1;
        node_index = node.offset;
      } else {
        stack[top++] = node.offset;
        node_index = node_index + 1;
      }
    } else {
      if (top == 0) break;
      node_index = stack[--top];
    }
  }
  return hit;
}

}  // namespace rts::render
