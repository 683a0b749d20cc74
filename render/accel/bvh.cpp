#include "render/accel/bvh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <type_traits>

#if defined(__SSE2__)
#include <xmmintrin.h>
#include <emmintrin.h>
#endif

#include <tbb/parallel_invoke.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

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

// CompactRef's bounds as SSE2 float lanes (lo[0..2] then hi[0], hi[0..2] then the index).
template <class PrimRef>
inline constexpr bool kFloatLanes =
#if defined(__SSE2__)
    std::is_same_v<PrimRef, CompactRef>;
#else
    false;
#endif

#if defined(__SSE2__)
// The double box of float lanes (x, y, z, unused).
AABB to_aabb(__m128 lo, __m128 hi) {
  alignas(16) float l[4], h[4];
  _mm_store_ps(l, lo);
  _mm_store_ps(h, hi);
  return AABB{Vec3(l[0], l[1], l[2]), Vec3(h[0], h[1], h[2])};
}
#endif

template <class PrimRef>
struct Builder {
  std::vector<PrimRef>& refs;
  // Written at each leaf, from the references it takes (sized before the build).
  std::vector<uint32_t>& order;
  // Ranges of at most this many references are leaves (build_bvh's leaves_of_up_to; 0: the
  // SAH decides).
  uint32_t leaves_of_up_to = 0;
  // Whether more than one thread may build: with one, building a subtree aside and splicing
  // it only copies (the same tree either way).
  bool parallel = tbb::this_task_arena::max_concurrency() > 1 &&
                  tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1;

  // The references of a finished subtree are not read again: their pages go back to the
  // system (those wholly inside its range; the parent's range covers the ones at its ends).
  // Profile finding (RSS trace, 4M spheres): the references (117 MB) were held to the end of
  // the build beside the nodes (134 MB) being written, the whole render's peak; released as
  // the subtrees finish, the two together stay near the larger of them.
  static constexpr uint32_t kReleaseMinCount = 4096;
  void finished(uint32_t begin, uint32_t end) {
    if (end - begin >= kReleaseMinCount) release_pages(refs.data() + begin, refs.data() + end);
  }

  // The union of refs[begin, end)'s boxes and the bounds of their centroids (CompactRef's in
  // SSE2 lanes: the same double centroids, the same min and max as AABB::extend's).
  void measure(uint32_t begin, uint32_t end, AABB& bounds, AABB& centroid_bounds) const {
    if constexpr (kFloatLanes<PrimRef>) {
#if defined(__SSE2__)
      const MeasureLanes m = halves<MeasureLanes>(begin, end, [&](uint32_t b, uint32_t e) { return measure_lanes(b, e); });
      bounds = to_aabb(m.lo, m.hi);
      alignas(16) double c[8];
      _mm_store_pd(c, m.c_lo_xy);
      _mm_store_pd(c + 2, m.c_lo_z);
      _mm_store_pd(c + 4, m.c_hi_xy);
      _mm_store_pd(c + 6, m.c_hi_z);
      centroid_bounds = AABB{Vec3(c[0], c[1], c[2]), Vec3(c[4], c[5], c[6])};
      return;
#endif
    }
    for (uint32_t i = begin; i < end; ++i) {
      bounds.extend(refs[i].box());
      centroid_bounds.extend(refs[i].centroid());
    }
  }

  // `part(begin, end)` over the whole range, or for a range long enough to build in parallel
  // over its two halves at once, merged (T::merge keeps the earlier half's value on ties, as
  // one pass would: the same result either way). At 2 threads the passes over the root's
  // references were the build's serial part.
  template <class T, class Part>
  T halves(uint32_t begin, uint32_t end, const Part& part) const {
    if (end - begin < kParallelBuildThreshold || !parallel) return part(begin, end);
    const uint32_t mid = begin + (end - begin) / 2;
    T first, second;
    tbb::parallel_invoke([&] { first = part(begin, mid); }, [&] { second = part(mid, end); });
    first.merge(second);
    return first;
  }

#if defined(__SSE2__)
  // The bounds of references and of their centroids, in lanes (measure).
  struct MeasureLanes {
    __m128 lo = _mm_set1_ps(std::numeric_limits<float>::infinity());
    __m128 hi = _mm_set1_ps(-std::numeric_limits<float>::infinity());
    __m128d c_lo_xy = _mm_set1_pd(std::numeric_limits<double>::infinity()), c_lo_z = c_lo_xy;
    __m128d c_hi_xy = _mm_set1_pd(-std::numeric_limits<double>::infinity()), c_hi_z = c_hi_xy;
    // AABB::extend's choices: a later value replaces an earlier one only when smaller (min)
    // or larger (max), never when equal (signed zeros).
    void merge(const MeasureLanes& later) {
      lo = _mm_min_ps(later.lo, lo);
      hi = _mm_max_ps(later.hi, hi);
      c_lo_xy = _mm_min_pd(later.c_lo_xy, c_lo_xy);
      c_hi_xy = _mm_max_pd(later.c_hi_xy, c_hi_xy);
      c_lo_z = _mm_min_pd(later.c_lo_z, c_lo_z);
      c_hi_z = _mm_max_pd(later.c_hi_z, c_hi_z);
    }
  };

  MeasureLanes measure_lanes(uint32_t begin, uint32_t end) const {
    MeasureLanes m;
    const __m128d half = _mm_set1_pd(0.5);
    for (uint32_t i = begin; i < end; ++i) {
      const __m128 l = _mm_loadu_ps(refs[i].lo), h = _mm_loadu_ps(refs[i].hi);
      MeasureLanes one;
      one.lo = l;
      one.hi = h;  // lane 3 (the index) unused
      // 0.5 * (lo + hi) in double, as CompactRef::centroid: (x, y) and (z, unused).
      one.c_lo_xy = one.c_hi_xy = _mm_mul_pd(half, _mm_add_pd(_mm_cvtps_pd(l), _mm_cvtps_pd(h)));
      one.c_lo_z = one.c_hi_z = _mm_mul_pd(half, _mm_add_pd(_mm_cvtps_pd(_mm_movehl_ps(l, l)), _mm_cvtps_pd(_mm_movehl_ps(h, h))));
      m.merge(one);
    }
    return m;
  }

  // The bins' boxes in float lanes and their counts (the SAH binning).
  struct BinLanes {
    __m128 lo[kBvhBins], hi[kBvhBins];
    uint32_t n[kBvhBins];
    BinLanes() {
      for (int k = 0; k < kBvhBins; ++k) {
        lo[k] = _mm_set1_ps(std::numeric_limits<float>::infinity());
        hi[k] = _mm_set1_ps(-std::numeric_limits<float>::infinity());
        n[k] = 0;
      }
    }
    void merge(const BinLanes& later) {
      for (int k = 0; k < kBvhBins; ++k) {
        lo[k] = _mm_min_ps(later.lo[k], lo[k]);
        hi[k] = _mm_max_ps(later.hi[k], hi[k]);
        n[k] += later.n[k];
      }
    }
  };
#endif

  // Builds the subtree over refs[begin, end) into `nodes` (depth-first, left child right
  // after its parent); returns the index of its root.
  template <class Nodes>
  uint32_t build(uint32_t begin, uint32_t end, int depth, Nodes& nodes) {
    uint32_t index = static_cast<uint32_t>(nodes.size());
    nodes.emplace_back();
    AABB bounds, centroid_bounds;
    measure(begin, end, bounds, centroid_bounds);
    nodes[index].set_bounds(bounds);
    uint32_t count = end - begin;
    auto make_leaf = [&] {
      nodes[index].offset = begin;
      nodes[index].count = static_cast<uint16_t>(count);
      for (uint32_t i = begin; i < end; ++i) order[i] = refs[i].index;
      return index;
    };
    if (count <= 1 || count <= leaves_of_up_to || (depth >= kBvhMaxDepth && count <= kBvhMaxLeafCount)) return make_leaf();

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
      if constexpr (kFloatLanes<PrimRef>) {
#if defined(__SSE2__)
        // The bins' boxes in float lanes (exact: the references' bounds are floats, and min
        // and max of floats are the min and max of their doubles), one SSE2 min and max per
        // reference. Profile finding (perf, the 320k-triangle terrain's build, 1 thread): the
        // scalar double updates of the bin's six bounds, each loaded back from the previous
        // reference's store to the same bin, were the builder's hottest loop.
        const BinLanes lanes = halves<BinLanes>(begin, end, [&](uint32_t b, uint32_t e) {
          BinLanes out;
          for (uint32_t i = b; i < e; ++i) {
            const int k = bin_of(refs[i]);
            // glm::min(lo, p) keeps lo unless p < lo; _mm_min_ps(p, lo) likewise (signed zeros).
            out.lo[k] = _mm_min_ps(_mm_loadu_ps(refs[i].lo), out.lo[k]);
            out.hi[k] = _mm_max_ps(_mm_loadu_ps(refs[i].hi), out.hi[k]);  // lane 3 (the index) unused
            ++out.n[k];
          }
          return out;
        });
        for (int k = 0; k < kBvhBins; ++k) {
          bins[k].n = lanes.n[k];
          if (bins[k].n > 0) bins[k].box = to_aabb(lanes.lo[k], lanes.hi[k]);
        }
#endif
      } else {
        for (uint32_t i = begin; i < end; ++i) {
          Bin& b = bins[bin_of(refs[i])];
          b.box.extend(refs[i].box());
          ++b.n;
        }
      }
      // The sweeps skip empty bins' boxes and areas (extending by an empty box changes
      // nothing): most bins of the many small nodes near the leaves are empty (perf: the
      // sweeps' area products were a tenth of the build).
      double right_area[kBvhBins];
      uint32_t right_count[kBvhBins];
      AABB acc;
      uint32_t n = 0;
      double area = 0.0;
      for (int i = kBvhBins - 1; i > 0; --i) {
        if (bins[i].n > 0) {
          acc.extend(bins[i].box);
          n += bins[i].n;
          area = acc.surface_area();
        }
        right_area[i] = area;
        right_count[i] = n;
      }
      double best_cost = Interval::kInfinity;
      int best_split = -1;
      acc = AABB{};
      n = 0;
      area = 0.0;
      for (int i = 0; i < kBvhBins - 1; ++i) {
        if (bins[i].n > 0) {
          acc.extend(bins[i].box);
          n += bins[i].n;
          area = acc.surface_area();
        }
        if (n == 0 || right_count[i + 1] == 0) continue;
        double cost = area * n + right_area[i + 1] * right_count[i + 1];
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
    if (count >= kParallelBuildThreshold && parallel) {
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
BVH build_from(std::vector<PrimRef> refs, uint32_t leaves_of_up_to = 0) {
  BVH bvh;
  // Room for the most nodes a tree can have (2n - 1), and no shrink_to_fit afterwards: capacity
  // never written is never resident, while growing by doubling (or trimming at the end) copies
  // the array at the peak, and the freed copies stay resident in the threads' heaps. Profile
  // finding (massif and peak RSS, 2M triangles): node arrays were the largest allocation.
  bvh.nodes.reserve(2 * refs.size());
  bvh.order.resize(refs.size());
  Builder<PrimRef> builder{refs, bvh.order};
  builder.leaves_of_up_to = std::min<uint32_t>(leaves_of_up_to, kBvhMaxLeafCount);  // BVHNode::count's range
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
BVH build_over(std::size_t count, const BoxOf& box_of, const std::function<void()>& refs_made = {},
               uint32_t leaves_of_up_to = 0) {
  if (count == 0) return BVH{};
  bool compact = true;
  for (std::size_t i = 0; i < count && compact; ++i) compact = float_finite(box_of(i));
  auto made = [&]<class PrimRef>(PrimRef) {
    std::vector<PrimRef> refs(count);
    for (std::size_t i = 0; i < count; ++i) refs[i] = PrimRef(box_of(i), static_cast<uint32_t>(i));
    if (refs_made) refs_made();
    return build_from(std::move(refs), leaves_of_up_to);
  };
  return compact ? made(CompactRef{}) : made(WideRef{});
}

}  // namespace

BVH build_bvh(std::vector<AABB> primitive_bounds) {
  return build_over(
      primitive_bounds.size(), [&](std::size_t i) -> const AABB& { return primitive_bounds[i]; },
      [&] { std::vector<AABB>().swap(primitive_bounds); });
}

BVH build_bvh(std::size_t count, const std::function<AABB(std::size_t)>& box_of, uint32_t leaves_of_up_to) {
  return build_over(count, box_of, {}, leaves_of_up_to);
}

BVH build_bvh(const std::vector<FloatBox>& primitive_bounds) {
  return build_bvh(primitive_bounds.size(), [&](std::size_t i) { return primitive_bounds[i]; });
}

BVH build_bvh(std::size_t count, const std::function<FloatBox(std::size_t)>& box_of) {
  if (count == 0) return BVH{};
  std::vector<CompactRef> refs(count);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 16 * 1024), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) refs[i] = CompactRef(box_of(i), static_cast<uint32_t>(i));
  });
  return build_from(std::move(refs));  // which frees the references once the leaves are made
}

}  // namespace rts::render
