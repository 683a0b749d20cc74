// Which leaves of a CSG tree a ray needs (render/geometry/csg/csg_tree.hpp): the sweep keeps
// every leaf's state along the whole line, but only the states where they can change the
// result's surface inside the ray's interval matter. Walking the tree from the root with the
// span of t where a node's state can matter, an intersection's later children need only the
// part of the span where the earlier ones can be inside (outside it the intersection is
// outside whatever they are), and a difference's subtracted children only where its first
// child can be inside. A bounded leaf whose box misses its span (widened by a few tie
// distances, so no crossing that could share a batch with a kept one is dropped) is outside
// throughout the span, which is what an empty crossing list says: it is not computed.
//
// That is the profile's finding (docs/performance.md, "csg"): every ray reaching a die
// computed all 8 leaves along the whole line; most pips lie off the ray's path through the
// box and sphere, and a shadow ray's segment misses most leaves of the die it starts on.
#pragma once

#include "render/geometry/csg/csg_tree.hpp"
#include "render/geometry/interval.hpp"

namespace rts::render {

// Where along the line a leaf with these crossings can be inside: from its first entry (or
// -infinity when it starts inside) to its last exit (or +infinity when it ends inside).
inline Interval csg_inside_hull(const CsgLeafCrossings& c) {
  const double inf = Interval::kInfinity;
  if (c.count == 0) return c.inside_at_start ? Interval::universe() : Interval();
  const bool inside_at_end = c.inside_at_start != (c.count % 2 == 1);
  return Interval(c.inside_at_start ? -inf : c.t[0], inside_at_end ? inf : c.t[c.count - 1]);
}

// Fills leaves[l] for every leaf under `node`: compute(l, span) for a leaf whose state can
// matter inside `span` (non-empty; it may leave the list empty when the leaf's bounds miss
// the span), an empty list (outside throughout) otherwise. Returns where the node can be
// inside, valid within `span`: an inverted node is taken as inside anywhere.
template <class Compute>
Interval csg_gather(const CsgTree& tree, uint32_t node, const Interval& span, CsgLeafCrossings* leaves,
                    Compute& compute);

// One leaf, handled in its parent's loop: most nodes are leaves, and a call per leaf was most
// of the walk's cost.
template <class Compute>
inline Interval csg_gather_leaf(const CsgNode& n, const Interval& span, CsgLeafCrossings* leaves,
                                Compute& compute) {
  CsgLeafCrossings& c = leaves[n.first];
  c.count = 0;
  c.inside_at_start = false;
  Interval hull;  // empty
  if (!span.empty()) {
    compute(n.first, span);
    hull = csg_inside_hull(c);
  }
  return n.inverse ? Interval::universe() : hull;
}

template <class Compute>
Interval csg_gather(const CsgTree& tree, uint32_t node, const Interval& span, CsgLeafCrossings* leaves,
                    Compute& compute) {
  const CsgNode& n = tree.nodes[node];
  if (n.leaf) return csg_gather_leaf(n, span, leaves, compute);
  const uint32_t* kids = tree.children.data() + n.first;
  auto child = [&](uint32_t k, const Interval& s) {
    const CsgNode& c = tree.nodes[kids[k]];
    return c.leaf ? csg_gather_leaf(c, s, leaves, compute) : csg_gather(tree, kids[k], s, leaves, compute);
  };
  Interval hull;  // empty
  switch (n.op) {
    case CsgOp::Union:
    case CsgOp::Merge:
      for (uint32_t k = 0; k < n.count; ++k) {
        Interval h = child(k, span);
        hull = Interval(std::min(hull.min, h.min), std::max(hull.max, h.max));
      }
      break;
    case CsgOp::Intersection:
    case CsgOp::Clip: {  // a clip's surface lies where its clippers can be inside, as an intersection's
      Interval s = span;
      for (uint32_t k = 0; k < n.count; ++k) s = s.intersect(child(k, s));
      hull = s;
      break;
    }
    case CsgOp::Difference:
      if (n.count > 0) {
        hull = span.intersect(child(0, span));
        for (uint32_t k = 1; k < n.count; ++k) child(k, hull);
      }
      break;
  }
  if (hull.empty()) hull = Interval();  // one empty form, so the min/max above stay exact
  return n.inverse ? Interval::universe() : hull;
}

// The whole tree for a ray whose surfaces are wanted inside ray_t; returns where the result
// can be inside (valid within ray_t).
template <class Compute>
Interval csg_gather(const CsgTree& tree, const Interval& ray_t, CsgLeafCrossings* leaves, Compute&& compute) {
  if (tree.nodes.empty()) return Interval();
  return csg_gather(tree, static_cast<uint32_t>(tree.nodes.size() - 1), ray_t, leaves, compute);
}

}  // namespace rts::render
