// Whether a triangle mesh bounds a solid, so that it can take part in CSG: every edge must be
// walked as often in one direction as in the other by the triangles that use it (the mesh's
// boundary is empty). Then every line crosses its surface an even number of times, the
// crossings' facing (towards or away from the line) tells entering from leaving, and inside is
// where more faces have been entered than left (a nonzero winding number). Positions are
// compared exactly, so vertices an OBJ file splits for their normals or uvs are one vertex here.
#pragma once

#include <cstddef>

#include "render/scene/scene.hpp"

namespace rts::render {

struct MeshClosure {
  bool closed = false;
  std::size_t open_edges = 0;      // edges walked more often one way than the other
  bool inconsistent = false;       // one of them is used by two or more faces: a winding problem, not a hole
  Vec3 edge_from{0.0}, edge_to{0.0};  // one such edge, in object space (for the message)
  std::size_t triangles = 0;       // triangles counted (indices in range, finite positions)
};

MeshClosure mesh_closure(const MeshData& mesh);

}  // namespace rts::render
