// Constructive solid geometry along one ray, by intervals: each leaf solid reports where the
// whole line origin + t direction crosses its surface (and whether the line starts inside
// it, at t = -infinity); a sweep over those crossings in t order keeps every leaf's and every
// operation's inside/outside state exactly, from the crossings' order alone, never from a
// point-in-solid test at a surface (which is where POV-Ray's coincident surfaces speckle,
// POV-Ray issue #209).
//
// Crossings closer together than a tie distance are one batch, applied at once: a cut face
// flush with the block's face toggles both leaves in the same batch, the result's state does
// not change there, and no surface shows, for every ray alike.
//
// Which surface shows (POV-Ray's semantics): a union shows each child's surface, inner ones
// too (what glass unions show); merge, intersection and difference show where their own
// inside/outside state changes. The surface's leaf is the first child (in the order written)
// whose own surface shows there, recursively, so the cut face of a difference belongs to the
// subtracted child; the normal is then turned to point out of the result.
#pragma once

#include <cstdint>
#include <vector>

#include "render/geometry/aabb.hpp"
#include "render/geometry/interval.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// The most leaf solids in one CSG block and its nested blocks: the sweep keeps its state in
// fixed arrays on the stack (no allocation per ray); 256 leaves are 1024 crossings, 16 KB.
inline constexpr uint32_t kMaxCsgLeaves = 256;
inline constexpr uint32_t kMaxCsgNodes = 2 * kMaxCsgLeaves;
// A leaf solid crosses a line at most this often (a torus: 4).
inline constexpr int kMaxLeafCrossings = 4;

// Where the line crosses one leaf's surface, ascending; entries alternate entering and
// leaving, starting from `inside_at_start`.
struct CsgLeafCrossings {
  bool inside_at_start = false;
  int count = 0;
  double t[kMaxLeafCrossings];
};

struct CsgNode {
  CsgOp op = CsgOp::Union;
  bool inverse = false;
  bool leaf = false;
  uint32_t first = 0;    // leaf: its leaf index; operation: its first entry in CsgTree::children
  uint32_t count = 0;    // operation: how many children
};

struct CsgTree {
  std::vector<CsgNode> nodes;       // post-order: children before their parent, the root last
  std::vector<uint32_t> children;   // node indices, each operation's a contiguous run
  uint32_t leaf_count = 0;

  // Every node's state (inside = 1) given each leaf's (before its node's `inverse`).
  void evaluate(const uint8_t* leaf_inside, uint8_t* state) const;
  // The result's bounds from its leaves' (an infinite box for unbounded leaves): a union's
  // is its children's union, an intersection's their intersection, a difference's its first
  // child's; an inverse is unbounded. Invalid (empty) when nothing can be hit.
  AABB bounds(const std::vector<AABB>& leaf_bounds) const;
};

// The result's first surface inside ray_t.
struct CsgSurface {
  double t = 0.0;
  uint32_t leaf = 0;
  bool entering = false;   // the ray enters the result here (the normal must face the ray)
};

// Crossings within tie_abs + tie_rel * |t| of a batch's first are the same batch.
bool csg_first_surface(const CsgTree& tree, const CsgLeafCrossings* leaves, const Interval& ray_t, double tie_abs,
                       double tie_rel, CsgSurface& out);

}  // namespace rts::render
