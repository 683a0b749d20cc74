// Shadow rays that test only the few occluders a light can have (issue 24). Profile finding
// (perf, the soft-shadow race scene, 1 thread): the any-hit BVH walk and the object tests of
// the 16 shadow rays per shading point were ~28% of the render. Every one of those rays lies
// in the pyramid from the shading point over the area light, so one walk per shading point
// finds the leaves whose boxes meet it, and each ray then tests just those leaves (none, for
// a floor in the open). The answer is occluded()'s: a segment's hit lies in its leaf's box
// and in the pyramid, so that leaf is a candidate, and a candidate leaf is tested as the
// traversal would (its box, then its instances).
#include <algorithm>
#include <cmath>

#include "render/accel/world.hpp"

namespace rts::render {
namespace {

template <class Box>
[[gnu::always_inline]] inline bool meets(const ShadowRegion& r, const Box& lo, const Box& hi) {
  if (lo[0] > r.box.hi.x || hi[0] < r.box.lo.x || lo[1] > r.box.hi.y || hi[1] < r.box.lo.y ||
      lo[2] > r.box.hi.z || hi[2] < r.box.lo.z)
    return false;
  for (int k = 0; k < r.planes; ++k) {
    const Vec3& n = r.normal[k];
    // The box's corner farthest inside the plane: outside when even it is outside.
    const Vec3 near(n.x > 0 ? lo[0] : hi[0], n.y > 0 ? lo[1] : hi[1], n.z > 0 ? lo[2] : hi[2]);
    if (glm::dot(n, near) > r.offset[k]) return false;
  }
  return true;
}

}  // namespace

ShadowRegion shadow_pyramid(const Vec3& apex, const Vec3& centre, const Vec3& u, const Vec3& v) {
  ShadowRegion r;
  const Vec3 half_u = 0.5 * u, half_v = 0.5 * v;
  const Vec3 corner[4] = {centre - half_u - half_v, centre + half_u - half_v, centre + half_u + half_v,
                          centre - half_u + half_v};
  r.vertex[0] = apex;
  for (int k = 0; k < 4; ++k) r.vertex[k + 1] = corner[k];
  for (const Vec3& p : r.vertex) r.box.extend(p);
  const double scale = std::max(max_abs_component(r.box.lo), max_abs_component(r.box.hi));
  r.slack = tol::kShadowHullPadRelative * scale;
  r.box.lo -= Vec3(r.slack);
  r.box.hi += Vec3(r.slack);
  // Each side: the plane through the apex and one edge, facing away from the other corners.
  for (int k = 0; k < 4; ++k) {
    const Vec3& a = corner[k];
    const Vec3& b = corner[(k + 1) % 4];
    Vec3 n = glm::cross(a - apex, b - apex);
    const double len = glm::length(n);
    if (!(len > tol::kTinyLength) || !std::isfinite(len)) continue;  // the apex is in the light's plane
    n /= len;
    if (glm::dot(n, corner[(k + 2) % 4] - apex) > 0.0) n = -n;
    r.normal[r.planes] = n;
    r.offset[r.planes] = glm::dot(n, apex) + 4.0 * r.slack;
    ++r.planes;
  }
  return r;
}

bool World::occluder_candidates(const ShadowRegion& region, OccluderCandidates& out) const {
  out.count = 0;
  out.plane_count = 0;
  if (!region.box.valid()) return false;  // also NaN
  if (!shadowless_.empty()) return false;  // the traversal skips what casts no shadow
  // An untransformed plane with the light's corners on one side cannot block a ray from an
  // apex on that side too: a floor under a light, seen from a point on it, is left out (its
  // test was most of the per-ray cost). The apex may lie 1e-14 above the plane (the offset
  // origin of a floor point), so its side is decided as the plane test decides it: the sign
  // of the numerator that test divides (a ray from the plane's side away from it, or from on
  // it, gets t <= 0).
  for (uint32_t i : planes_) {
    const Instance& inst = instances_[i];
    if (inst.kind == kPrimKind<Plane> && inst.transform == kNoId) {
      const Plane& p = std::get<std::vector<Plane>>(shapes_)[inst.index];
      const double len = glm::length(p.normal);
      if (len > tol::kTinyLength) {
        const Vec3 n = p.normal / len;
        const double d = p.offset / len, margin = region.slack + tol::kShadowHullPadRelative * std::abs(d);
        bool above = true, below = true;
        for (int k = 1; k < 5; ++k) {
          const double s = glm::dot(n, region.vertex[k]) - d;
          above = above && s > margin;
          below = below && s < -margin;
        }
        const double numerator = p.offset / len - glm::dot(n, region.vertex[0]);
        if ((above && numerator <= 0.0) || (below && numerator >= 0.0)) continue;
      }
    }
    if (out.plane_count == OccluderCandidates::kMax) return false;
    out.plane[out.plane_count++] = i;
  }
  if (!use_bvh_) {
    if (bounded_count_ > static_cast<std::size_t>(OccluderCandidates::kMax)) return false;
    for (uint32_t i = 0; i < bounded_count_; ++i) out.leaf[out.count++] = i;
    return true;
  }
  if (!quantized_.empty()) return quantized_candidates(region, out);
  if (bvh_.nodes.empty()) return true;
  uint32_t stack[kBvhTraversalStack];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const uint32_t index = stack[--top];
    const BVHNode& node = bvh_.nodes[index];
    if (!meets(region, node.lo, node.hi)) continue;
    if (node.count > 0) {
      if (out.count == OccluderCandidates::kMax) return false;
      out.leaf[out.count++] = index;
    } else {
      stack[top++] = node.offset;  // right
      stack[top++] = index + 1;    // left
    }
  }
  return true;
}

// The quantized tree's leaves are instances, with boxes decoded on the way down: the candidates
// are the instances themselves (occluded_by then tests each without a box first, as it does
// without a BVH: the object's own test is exact, the box only saved time).
bool World::quantized_candidates(const ShadowRegion& region, OccluderCandidates& out) const {
  struct Item {
    QuantizedBox box;
    uint32_t ref;
  };
  Item stack[kBvhTraversalStack];
  int top = 0;
  if (meets(region, quantized_.root_box.lo, quantized_.root_box.hi))
    stack[top++] = Item{quantized_.root_box, quantized_.root};
  while (top > 0) {
    --top;
    const uint32_t ref = stack[top].ref;
    if (ref & QuantizedNode::kLeafBit) {
      if (out.count == OccluderCandidates::kMaxInstances) return false;
      out.leaf[out.count++] = ref & ~QuantizedNode::kLeafBit;
      continue;
    }
    const QuantizedNode& node = quantized_.nodes[ref];
    QuantizedBox kids[2];
    decode_child(stack[top].box, node, 1, kids[1]);
    decode_child(stack[top].box, node, 0, kids[0]);
    for (int c = 1; c >= 0; --c) {  // the left child on top, as in the binary walk
      if (meets(region, kids[c].lo, kids[c].hi)) stack[top++] = Item{kids[c], node.child[c]};
    }
  }
  return true;
}

bool World::occluded_by(const OccluderCandidates& candidates, const Ray& ray, Interval ray_t) const {
  for (int k = 0; k < candidates.plane_count; ++k)
    if (occluded_instance(instances_[candidates.plane[k]], ray, ray_t)) return true;
  if (!use_bvh_ || !quantized_.empty()) {
    for (int k = 0; k < candidates.count; ++k)
      if (occluded_instance(instances_[candidates.leaf[k]], ray, ray_t)) return true;
    return false;
  }
  if (candidates.count == 0) return false;
  const RayInverse inv(ray.origin, ray.direction);
  for (int k = 0; k < candidates.count; ++k) {
    const BVHNode& node = bvh_.nodes[candidates.leaf[k]];
    double t_entry;
    if (!slab_hit(node.bounds(), inv, ray_t, t_entry)) continue;
    for (uint32_t s = 0; s < node.count; ++s)
      if (occluded_instance(instances_[bvh_.order[node.offset + s]], ray, ray_t)) return true;
  }
  return false;
}

}  // namespace rts::render
