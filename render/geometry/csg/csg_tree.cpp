#include "render/geometry/csg/csg_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rts::render {

void CsgTree::evaluate(const uint8_t* leaf_inside, uint8_t* state) const {
  // The arrays' bounds in locals: a store through `state` (a byte type) may alias anything,
  // the vectors' own pointers included, which were otherwise loaded again for every node
  // (profile finding: callgrind on the csg race scene, a sixth of evaluate's instructions).
  const CsgNode* const all = nodes.data();
  const std::size_t count = nodes.size();
  const uint32_t* const kids = children.data();
  for (std::size_t i = 0; i < count; ++i) {
    const CsgNode& n = all[i];
    bool v;
    if (n.leaf) {
      v = leaf_inside[n.first] != 0;
    } else {
      const uint32_t* c = kids + n.first;
      switch (n.op) {
        case CsgOp::Union:
        case CsgOp::Merge:
          v = false;
          for (uint32_t k = 0; k < n.count && !v; ++k) v = state[c[k]] != 0;
          break;
        case CsgOp::Intersection:
        case CsgOp::Clip:
          v = true;
          for (uint32_t k = 0; k < n.count && v; ++k) v = state[c[k]] != 0;
          break;
        case CsgOp::Difference:
          v = n.count > 0 && state[c[0]] != 0;
          for (uint32_t k = 1; k < n.count && v; ++k) v = state[c[k]] == 0;
          break;
        default:
          v = false;
      }
    }
    state[i] = static_cast<uint8_t>(v != n.inverse);
  }
}

AABB CsgTree::bounds(const std::vector<AABB>& leaf_bounds) const {
  const double inf = std::numeric_limits<double>::infinity();
  const AABB everything{Vec3(-inf), Vec3(inf)};
  std::vector<AABB> b(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const CsgNode& n = nodes[i];
    AABB box;
    if (n.leaf) {
      box = leaf_bounds[n.first];
    } else {
      const uint32_t* c = children.data() + n.first;
      switch (n.op) {
        case CsgOp::Union:
        case CsgOp::Merge:
          for (uint32_t k = 0; k < n.count; ++k)
            if (b[c[k]].valid()) box.extend(b[c[k]]);
          break;
        case CsgOp::Intersection:
        case CsgOp::Clip:
          box = everything;
          for (uint32_t k = 0; k < n.count; ++k) {
            box.lo = glm::max(box.lo, b[c[k]].lo);
            box.hi = glm::min(box.hi, b[c[k]].hi);
          }
          if (!box.valid()) box = AABB{};
          break;
        case CsgOp::Difference:
          if (n.count > 0) box = b[c[0]];
          break;
      }
    }
    if (n.inverse) box = everything;
    b[i] = box;
  }
  return b.empty() ? AABB{} : b.back();
}

namespace {

struct Event {
  double t;
  uint32_t leaf;
};

}  // namespace

bool csg_first_surface(const CsgTree& tree, const CsgLeafCrossings* leaves, const Interval& ray_t, double tie_abs,
                       double tie_rel, CsgSurface& out) {
  const uint32_t nl = tree.leaf_count;
  const std::size_t nn = tree.nodes.size();
  if (nl == 0 || nl > kMaxCsgLeaves || nn == 0 || nn > kMaxCsgNodes) return false;
  Event ev[kMaxCsgLeaves * kMaxLeafCrossings];
  uint8_t leaf_in[kMaxCsgLeaves];
  int ne = 0;
  for (uint32_t l = 0; l < nl; ++l) {
    leaf_in[l] = leaves[l].inside_at_start ? 1 : 0;
    for (int k = 0; k < leaves[l].count && k < kMaxLeafCrossings; ++k) ev[ne++] = Event{leaves[l].t[k], l};
  }
  if (ne == 0) return false;  // the state never changes along the line: no surface
  std::sort(ev, ev + ne, [](const Event& a, const Event& b) { return a.t < b.t || (a.t == b.t && a.leaf < b.leaf); });

  // Two state buffers whose roles swap after each batch (the next batch's `before` is this
  // one's `after`; evaluate() writes every node, so nothing is copied).
  uint8_t state_a[kMaxCsgNodes], state_b[kMaxCsgNodes], visible[kMaxCsgNodes];
  uint8_t* before = state_a;
  uint8_t* after = state_b;
  // The nodes' states are needed only around batches that can show a surface inside ray_t: a
  // batch whose every crossing is at or before ray_t.min only toggles its leaves (the batches
  // are formed exactly as before, so the later ones are the same).
  bool before_known = false;
  // (A clip's first child may be a union, whose inner surfaces show without a state change.)
  const bool root_shows_own_only =
      tree.nodes[nn - 1].leaf || (tree.nodes[nn - 1].op != CsgOp::Union && tree.nodes[nn - 1].op != CsgOp::Clip);
  int i = 0;
  while (i < ne) {
    const double t0 = ev[i].t;
    if (t0 >= ray_t.max) return false;  // later batches are all beyond the range
    const double tie = tie_abs + tie_rel * std::abs(t0);
    int j = i;
    while (j < ne && ev[j].t - t0 <= tie) ++j;
    if (!(ev[j - 1].t > ray_t.min)) {  // none of the batch's crossings is inside the range
      for (int e = i; e < j; ++e) leaf_in[ev[e].leaf] ^= 1;
      before_known = false;
      i = j;
      continue;
    }
    if (!before_known) tree.evaluate(leaf_in, before);
    before_known = true;
    for (int e = i; e < j; ++e) leaf_in[ev[e].leaf] ^= 1;
    tree.evaluate(leaf_in, after);
    // A root other than a union shows a surface only where its own state changes: most
    // batches (a die's box entered outside its sphere, a pip met outside the die) need no
    // visibility pass.
    if (root_shows_own_only && before[nn - 1] == after[nn - 1]) {
      std::swap(before, after);
      i = j;
      continue;
    }
    // Which nodes show a surface in this batch (post-order, so children first).
    for (std::size_t k = 0; k < nn; ++k) {
      const CsgNode& n = tree.nodes[k];
      bool v = before[k] != after[k];
      if (!n.leaf && n.op == CsgOp::Union)
        for (uint32_t c = 0; c < n.count && !v; ++c) v = visible[tree.children[n.first + c]] != 0;
      if (!n.leaf && n.op == CsgOp::Clip) {
        // Only the first child's surface, and only where every clipping child is inside (on
        // either side of the batch: a clipper's face flush with the surface keeps it).
        const uint32_t* c = tree.children.data() + n.first;
        bool in_before = true, in_after = true;
        for (uint32_t j = 1; j < n.count; ++j) {
          in_before = in_before && before[c[j]] != 0;
          in_after = in_after && after[c[j]] != 0;
        }
        v = n.count > 0 && visible[c[0]] != 0 && (in_before || in_after);
      }
      visible[k] = v;
    }
    if (visible[nn - 1]) {
      // Down to the leaf: the first child that shows; the orientation from the highest node
      // on the way whose state changes (a union's inner surface: the child's own).
      uint32_t k = static_cast<uint32_t>(nn - 1);
      bool oriented = false, entering = false;
      while (true) {
        if (!oriented && before[k] != after[k]) {
          oriented = true;
          entering = after[k] != 0;
        }
        const CsgNode& n = tree.nodes[k];
        if (n.leaf) break;
        uint32_t next = k;
        for (uint32_t c = 0; c < n.count; ++c)
          if (visible[tree.children[n.first + c]]) {
            next = tree.children[n.first + c];
            break;
          }
        if (next == k) break;  // cannot happen: a changed operation has a changed child
        k = next;
      }
      const CsgNode& leaf = tree.nodes[k];
      if (leaf.leaf) {
        double t = t0;
        for (int e = i; e < j; ++e)
          if (ev[e].leaf == leaf.first) {
            t = ev[e].t;
            break;
          }
        if (ray_t.surrounds(t)) {
          out.t = t;
          out.leaf = leaf.first;
          out.entering = entering;
          return true;
        }
      }
    }
    std::swap(before, after);
    i = j;
  }
  return false;
}

}  // namespace rts::render
