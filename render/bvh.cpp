#include "render/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <tbb/parallel_invoke.h>

namespace rts::render {

void BVHNode::set_bounds(const AABB& b) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    float l = static_cast<float>(b.lo[a]), h = static_cast<float>(b.hi[a]);
    if (static_cast<double>(l) > b.lo[a]) l = std::nextafter(l, -kInf);  // round outwards
    if (static_cast<double>(h) < b.hi[a]) h = std::nextafter(h, kInf);
    lo[a] = l;
    hi[a] = h;
  }
}

namespace {

// Relative costs for the surface area heuristic: one box test vs one primitive test.
constexpr double kTraversalCost = 1.0;
constexpr double kIntersectCost = 1.0;

// A primitive as the builder sees it; partitioned in place so that every pass over a node's
// range reads memory sequentially.
struct PrimRef {
  AABB box;
  Vec3 centroid;
  uint32_t index;
};

// Subtrees over at least this many primitives are built in parallel (each into its own node
// array, spliced afterwards in the same order, so the tree does not depend on scheduling).
constexpr uint32_t kParallelBuildThreshold = 32 * 1024;

// Appends `sub` (a subtree whose interior offsets count from its own start) to `nodes`.
void splice(std::vector<BVHNode>& nodes, const std::vector<BVHNode>& sub) {
  uint32_t base = static_cast<uint32_t>(nodes.size());
  for (BVHNode n : sub) {
    if (n.count == 0) n.offset += base;
    nodes.push_back(n);
  }
}

struct Builder {
  std::vector<PrimRef>& refs;

  // Builds the subtree over refs[begin, end) into `nodes` (depth-first, left child right
  // after its parent); returns the index of its root.
  uint32_t build(uint32_t begin, uint32_t end, int depth, std::vector<BVHNode>& nodes) {
    uint32_t index = static_cast<uint32_t>(nodes.size());
    nodes.emplace_back();
    AABB bounds, centroid_bounds;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.extend(refs[i].box);
      centroid_bounds.extend(refs[i].centroid);
    }
    nodes[index].set_bounds(bounds);
    uint32_t count = end - begin;
    auto make_leaf = [&] {
      nodes[index].offset = begin;
      nodes[index].count = static_cast<uint16_t>(count);
      return index;
    };
    if (count <= 1 || (depth >= kBvhMaxDepth && count <= kBvhMaxLeafCount)) return make_leaf();

    Vec3 extent = centroid_bounds.extent();
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    auto first = refs.begin() + begin, last = refs.begin() + end;
    uint32_t mid;
    auto split_in_middle = [&] {
      mid = begin + count / 2;
      std::nth_element(first, refs.begin() + mid, last, [axis](const PrimRef& a, const PrimRef& b) {
        return a.centroid[axis] < b.centroid[axis];
      });
    };
    if (!(extent[axis] > 0.0) || depth >= kBvhMaxDepth) {
      // All centroids coincide (SAH cannot separate them), or the tree is too deep: split in
      // the middle if there are too many for one leaf.
      if (count <= kBvhMaxLeafSize) return make_leaf();
      split_in_middle();
    } else {
      // Binned SAH along the widest centroid axis.
      struct Bin { AABB box; uint32_t n = 0; } bins[kBvhBins];
      double lo = centroid_bounds.lo[axis];
      double scale = kBvhBins / extent[axis];
      auto bin_of = [&](const PrimRef& p) {
        int b = static_cast<int>((p.centroid[axis] - lo) * scale);
        return std::clamp(b, 0, kBvhBins - 1);
      };
      for (uint32_t i = begin; i < end; ++i) {
        Bin& b = bins[bin_of(refs[i])];
        b.box.extend(refs[i].box);
        ++b.n;
      }
      double right_area[kBvhBins];
      uint32_t right_count[kBvhBins];
      AABB acc;
      uint32_t n = 0;
      for (int i = kBvhBins - 1; i > 0; --i) {
        acc.extend(bins[i].box);
        n += bins[i].n;
        right_area[i] = acc.surface_area();
        right_count[i] = n;
      }
      double best_cost = Interval::kInfinity;
      int best_split = -1;
      acc = AABB{};
      n = 0;
      for (int i = 0; i < kBvhBins - 1; ++i) {
        acc.extend(bins[i].box);
        n += bins[i].n;
        if (n == 0 || right_count[i + 1] == 0) continue;
        double cost = acc.surface_area() * n + right_area[i + 1] * right_count[i + 1];
        if (cost < best_cost) {
          best_cost = cost;
          best_split = i;
        }
      }
      double parent_area = bounds.surface_area();
      double split_cost = parent_area > 0.0
                              ? kTraversalCost + kIntersectCost * best_cost / parent_area
                              : Interval::kInfinity;
      double leaf_cost = kIntersectCost * count;
      if (best_split < 0 || (count <= kBvhMaxLeafSize && split_cost >= leaf_cost)) {
        if (count <= kBvhMaxLeafSize) return make_leaf();
        split_in_middle();
      } else {
        auto it = std::partition(first, last, [&](const PrimRef& p) { return bin_of(p) <= best_split; });
        mid = static_cast<uint32_t>(it - refs.begin());
      }
    }
    if (mid == begin || mid == end) mid = begin + count / 2;
    nodes[index].axis = static_cast<uint8_t>(axis);
    nodes[index].count = 0;
    if (count >= kParallelBuildThreshold) {
      std::vector<BVHNode> left_nodes, right_nodes;
      tbb::parallel_invoke([&] { build(begin, mid, depth + 1, left_nodes); },
                           [&] { build(mid, end, depth + 1, right_nodes); });
      splice(nodes, left_nodes);
      nodes[index].offset = static_cast<uint32_t>(nodes.size());
      splice(nodes, right_nodes);
    } else {
      build(begin, mid, depth + 1, nodes);
      uint32_t right = build(mid, end, depth + 1, nodes);
      nodes[index].offset = right;
    }
    return index;
  }
};

}  // namespace

BVH build_bvh(const std::vector<AABB>& primitive_bounds) {
  BVH bvh;
  if (primitive_bounds.empty()) return bvh;
  std::vector<PrimRef> refs(primitive_bounds.size());
  for (std::size_t i = 0; i < refs.size(); ++i)
    refs[i] = PrimRef{primitive_bounds[i], primitive_bounds[i].centroid(), static_cast<uint32_t>(i)};
  bvh.nodes.reserve(primitive_bounds.size() * 2);
  Builder builder{refs};
  builder.build(0, static_cast<uint32_t>(refs.size()), 0, bvh.nodes);
  bvh.nodes.shrink_to_fit();
  bvh.order.resize(refs.size());
  for (std::size_t i = 0; i < refs.size(); ++i) bvh.order[i] = refs[i].index;
  return bvh;
}

}  // namespace rts::render
