#include "render/bvh.hpp"

#include <algorithm>
#include <numeric>

namespace rts::render {
namespace {

// Relative costs for the surface area heuristic: one box test vs one primitive test.
constexpr double kTraversalCost = 1.0;
constexpr double kIntersectCost = 1.0;

struct Builder {
  const std::vector<AABB>& boxes;
  std::vector<Vec3> centroids;
  BVH& out;

  uint32_t build(uint32_t begin, uint32_t end, int depth) {
    uint32_t index = static_cast<uint32_t>(out.nodes.size());
    out.nodes.emplace_back();
    AABB bounds, centroid_bounds;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.extend(boxes[out.order[i]]);
      centroid_bounds.extend(centroids[out.order[i]]);
    }
    out.nodes[index].bounds = bounds;
    uint32_t count = end - begin;
    auto make_leaf = [&] {
      out.nodes[index].offset = begin;
      out.nodes[index].count = count;
      return index;
    };
    if (count <= 1 || depth >= kBvhMaxDepth) return make_leaf();

    Vec3 extent = centroid_bounds.extent();
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    uint32_t mid;
    if (!(extent[axis] > 0.0)) {
      // All centroids coincide: SAH cannot separate them; split in the middle if too many.
      if (count <= kBvhMaxLeafSize) return make_leaf();
      mid = begin + count / 2;
    } else {
      // Binned SAH along the widest centroid axis.
      struct Bin { AABB box; uint32_t n = 0; } bins[kBvhBins];
      double lo = centroid_bounds.lo[axis];
      double scale = kBvhBins / extent[axis];
      auto bin_of = [&](uint32_t prim) {
        int b = static_cast<int>((centroids[prim][axis] - lo) * scale);
        return std::clamp(b, 0, kBvhBins - 1);
      };
      for (uint32_t i = begin; i < end; ++i) {
        Bin& b = bins[bin_of(out.order[i])];
        b.box.extend(boxes[out.order[i]]);
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
        mid = begin + count / 2;
        std::nth_element(out.order.begin() + begin, out.order.begin() + mid, out.order.begin() + end,
                         [&](uint32_t a, uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
      } else {
        auto it = std::partition(out.order.begin() + begin, out.order.begin() + end,
                                 [&](uint32_t p) { return bin_of(p) <= best_split; });
        mid = static_cast<uint32_t>(it - out.order.begin());
      }
    }
    if (mid == begin || mid == end) mid = begin + count / 2;
    out.nodes[index].axis = static_cast<uint8_t>(axis);
    build(begin, mid, depth + 1);
    uint32_t right = build(mid, end, depth + 1);
    out.nodes[index].offset = right;
    out.nodes[index].count = 0;
    return index;
  }
};

}  // namespace

BVH build_bvh(const std::vector<AABB>& primitive_bounds) {
  BVH bvh;
  if (primitive_bounds.empty()) return bvh;
  bvh.order.resize(primitive_bounds.size());
  std::iota(bvh.order.begin(), bvh.order.end(), 0u);
  bvh.nodes.reserve(primitive_bounds.size() * 2);
  Builder builder{primitive_bounds, {}, bvh};
  builder.centroids.reserve(primitive_bounds.size());
  for (const AABB& b : primitive_bounds) builder.centroids.push_back(b.centroid());
  builder.build(0, static_cast<uint32_t>(primitive_bounds.size()), 0);
  return bvh;
}

}  // namespace rts::render
