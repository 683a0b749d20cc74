#include "render/accel/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <tbb/parallel_invoke.h>

#include "render/accel/memory.hpp"

namespace rts::render {

void round_outwards(const AABB& b, float lo[3], float hi[3]) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (int a = 0; a < 3; ++a) {
    float l = static_cast<float>(b.lo[a]), h = static_cast<float>(b.hi[a]);
    if (static_cast<double>(l) > b.lo[a]) l = std::nextafter(l, -kInf);  // round outwards
    if (static_cast<double>(h) < b.hi[a]) h = std::nextafter(h, kInf);
    lo[a] = l;
    hi[a] = h;
  }
}

void BVHNode::set_bounds(const AABB& b) { round_outwards(b, lo, hi); }

namespace {

// Relative costs for the surface area heuristic: one box test vs one primitive test.
constexpr double kTraversalCost = 1.0;
constexpr double kIntersectCost = 1.0;

// A primitive as the builder sees it; partitioned in place so that every pass over a node's
// range reads memory sequentially. Two layouts with the same interface:
// - CompactRef (28 bytes): the box rounded outwards to float, centroid recomputed on use; for
//   every set of boxes whose rounded bounds are finite. The nodes' boxes are the same either
//   way (a node's float box is its union rounded outwards, and rounding outwards commutes with
//   the union); only the SAH's choices see the rounding, by at most one float step per bound.
//   Profile findings: the builder's 80-byte references were the largest allocation of a
//   2M-triangle mesh's render (peak RSS); with the 56-byte double layout below they were 235
//   MB of the 668 MB peak of 4M spheres (RSS trace, issue 24: bytes per sphere), the rest the
//   world's records (257 MB) and the nodes written beside them.
// - WideRef (56 bytes): double box, centroid recomputed on use (the same expression as
//   AABB::centroid), for boxes past float's range (a scene at 1e39), where rounded bounds
//   would be infinite and their centroids meaningless.
struct CompactRef {
  float lo[3], hi[3];
  uint32_t index;

  CompactRef() = default;
  CompactRef(const FloatBox& b, uint32_t i) : index(i) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = b.lo[a];
      hi[a] = b.hi[a];
    }
  }
  CompactRef(const AABB& b, uint32_t i) : index(i) { round_outwards(b, lo, hi); }
  AABB box() const { return AABB{Vec3(lo[0], lo[1], lo[2]), Vec3(hi[0], hi[1], hi[2])}; }
  double centroid(int axis) const { return 0.5 * (static_cast<double>(lo[axis]) + static_cast<double>(hi[axis])); }
  Vec3 centroid() const { return 0.5 * (Vec3(lo[0], lo[1], lo[2]) + Vec3(hi[0], hi[1], hi[2])); }
};

struct WideRef {
  AABB bounds;
  uint32_t index;

  WideRef() = default;
  WideRef(const AABB& b, uint32_t i) : bounds(b), index(i) {}
  const AABB& box() const { return bounds; }
  double centroid(int axis) const { return 0.5 * (bounds.lo[axis] + bounds.hi[axis]); }
  Vec3 centroid() const { return bounds.centroid(); }
};
static_assert(sizeof(WideRef) <= 56, "the builder's wide reference grew");

// Whether b's box rounded outwards to float is finite (CompactRef holds it).
bool float_finite(const AABB& b) {
  float lo[3], hi[3];
  round_outwards(b, lo, hi);
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(lo[a]) || !std::isfinite(hi[a])) return false;
  return true;
}

// Subtrees over at least this many primitives are built in parallel (each into its own node
// array, spliced afterwards in the same order, so the tree does not depend on scheduling).
constexpr uint32_t kParallelBuildThreshold = 32 * 1024;

// A subtree's node array built aside (PageAllocator: unmapped when spliced, not left resident
// in a worker thread's heap). Profile finding (RSS sampled every 10 ms, the race's 2M-triangle
// mesh): 95 MB rose and fell within the last 30 ms of the build, the freed subtree arrays of
// the nested parallel splits still resident beside the top split's.
using SubtreeNodes = std::vector<BVHNode, PageAllocator<BVHNode>>;

// Appends `sub` (a subtree whose interior offsets count from its own start) to `nodes`, giving
// each copied stretch of `sub` back to the system as it goes: the copy and the original are not
// both resident (profile finding, RSS trace of 4M spheres: the top split's right subtree, 64 MB,
// was held twice at the end of the build).
template <class Nodes>
void splice(Nodes& nodes, SubtreeNodes& sub) {
  uint32_t base = static_cast<uint32_t>(nodes.size());
  if (nodes.capacity() < nodes.size() + sub.size()) nodes.reserve(std::max(nodes.size() + sub.size(), 2 * nodes.size()));
  constexpr std::size_t kStretch = std::size_t{1} << 14;  // nodes (512 KB)
  for (std::size_t from = 0; from < sub.size(); from += kStretch) {
    const std::size_t to = std::min(sub.size(), from + kStretch);
    for (std::size_t i = from; i < to; ++i) {
      BVHNode n = sub[i];
      if (n.count == 0) n.offset += base;
      nodes.push_back(n);
    }
    release_pages(sub.data() + from, sub.data() + to);
  }
}

template <class PrimRef>
struct Builder {
  std::vector<PrimRef>& refs;
  // Written at each leaf, from the references it takes (sized before the build).
  std::vector<uint32_t>& order;

  // The references of a finished subtree are not read again: their pages go back to the
  // system (those wholly inside its range; the parent's range covers the ones at its ends).
  // Profile finding (RSS trace, 4M spheres): the references (117 MB) were held to the end of
  // the build beside the nodes (134 MB) being written, the whole render's peak; released as
  // the subtrees finish, the two together stay near the larger of them.
  static constexpr uint32_t kReleaseMinCount = 4096;
  void finished(uint32_t begin, uint32_t end) {
    if (end - begin >= kReleaseMinCount) release_pages(refs.data() + begin, refs.data() + end);
  }

  // Builds the subtree over refs[begin, end) into `nodes` (depth-first, left child right
  // after its parent); returns the index of its root.
  template <class Nodes>
  uint32_t build(uint32_t begin, uint32_t end, int depth, Nodes& nodes) {
    uint32_t index = static_cast<uint32_t>(nodes.size());
    nodes.emplace_back();
    AABB bounds, centroid_bounds;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.extend(refs[i].box());
      centroid_bounds.extend(refs[i].centroid());
    }
    nodes[index].set_bounds(bounds);
    uint32_t count = end - begin;
    auto make_leaf = [&] {
      nodes[index].offset = begin;
      nodes[index].count = static_cast<uint16_t>(count);
      for (uint32_t i = begin; i < end; ++i) order[i] = refs[i].index;
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
        return a.centroid(axis) < b.centroid(axis);
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
        int b = static_cast<int>((p.centroid(axis) - lo) * scale);
        return std::clamp(b, 0, kBvhBins - 1);
      };
      for (uint32_t i = begin; i < end; ++i) {
        Bin& b = bins[bin_of(refs[i])];
        b.box.extend(refs[i].box());
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
      // The left subtree goes straight into `nodes` (where the serial build would put it);
      // only the right one is built aside and spliced after it. Profile finding (massif,
      // 320k triangles): splicing both halves from their own vectors held the node array
      // twice at the peak, the largest allocation of the build.
      SubtreeNodes right_nodes;
      right_nodes.reserve(2 * static_cast<std::size_t>(end - mid));  // the most a subtree can need
      tbb::parallel_invoke([&] { build(begin, mid, depth + 1, nodes); },
                           [&] { build(mid, end, depth + 1, right_nodes); });
      finished(begin, end);
      nodes[index].offset = static_cast<uint32_t>(nodes.size());
      splice(nodes, right_nodes);
    } else {
      build(begin, mid, depth + 1, nodes);
      uint32_t right = build(mid, end, depth + 1, nodes);
      nodes[index].offset = right;
      finished(begin, end);
    }
    return index;
  }
};

template <class PrimRef>
BVH build_from(std::vector<PrimRef> refs) {
  BVH bvh;
  // Room for the most nodes a tree can have (2n - 1), and no shrink_to_fit afterwards: capacity
  // never written is never resident, while growing by doubling (or trimming at the end) copies
  // the array at the peak, and the freed copies stay resident in the threads' heaps. Profile
  // finding (massif and peak RSS, 2M triangles): node arrays were the largest allocation.
  bvh.nodes.reserve(2 * refs.size());
  bvh.order.resize(refs.size());
  Builder<PrimRef> builder{refs, bvh.order};
  builder.build(0, static_cast<uint32_t>(refs.size()), 0, bvh.nodes);
  const std::size_t count = refs.size();
  std::vector<PrimRef>().swap(refs);
  release_free_memory(count);  // what is left of them lies in the heap (memory.hpp)
  return bvh;
}

// The tree over `count` boxes (box_of(i) called twice each: once to see whether every box
// rounds to a finite float box, which picks the reference layout, once into the references);
// `refs_made` runs once the references hold every box (the array overload frees its boxes
// there).
template <class BoxOf>
BVH build_over(std::size_t count, const BoxOf& box_of, const std::function<void()>& refs_made = {}) {
  if (count == 0) return BVH{};
  bool compact = true;
  for (std::size_t i = 0; i < count && compact; ++i) compact = float_finite(box_of(i));
  auto made = [&]<class PrimRef>(PrimRef) {
    std::vector<PrimRef> refs(count);
    for (std::size_t i = 0; i < count; ++i) refs[i] = PrimRef(box_of(i), static_cast<uint32_t>(i));
    if (refs_made) refs_made();
    return build_from(std::move(refs));
  };
  return compact ? made(CompactRef{}) : made(WideRef{});
}

}  // namespace

BVH build_bvh(std::vector<AABB> primitive_bounds) {
  return build_over(
      primitive_bounds.size(), [&](std::size_t i) -> const AABB& { return primitive_bounds[i]; },
      [&] { std::vector<AABB>().swap(primitive_bounds); });
}

BVH build_bvh(std::size_t count, const std::function<AABB(std::size_t)>& box_of) {
  return build_over(count, box_of);
}

BVH build_bvh(const std::vector<FloatBox>& primitive_bounds) {
  return build_bvh(primitive_bounds.size(), [&](std::size_t i) { return primitive_bounds[i]; });
}

BVH build_bvh(std::size_t count, const std::function<FloatBox(std::size_t)>& box_of) {
  if (count == 0) return BVH{};
  std::vector<CompactRef> refs(count);
  for (std::size_t i = 0; i < count; ++i) refs[i] = CompactRef(box_of(i), static_cast<uint32_t>(i));
  return build_from(std::move(refs));  // which frees the references once the leaves are made
}

}  // namespace rts::render
