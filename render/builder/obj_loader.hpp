// Wavefront OBJ loading (tinyobjloader) into the renderer's MeshData: triangulated, with
// per-corner positions/normals/uvs flattened into unified vertices, smooth normals computed
// when the file has none and smoothing is asked for.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "render/scene/scene.hpp"

namespace rts::render {

// What one OBJ file may add, checked while it is read (before its arrays are built).
struct ObjLimits {
  std::size_t max_triangles = SIZE_MAX;  // what is left of --max-mesh-triangles
  std::size_t max_memory = 0;            // --max-memory in bytes (0: no limit)
};

// Loads `path` (already resolved). Throws SceneError at `where` when the file is missing,
// malformed or over the limits; the message names the OBJ as the scene wrote it (`shown`)
// and, where known, the OBJ's own line ("bunny.obj:12: face vertex index 40 out of range").
// `mtllib` lines are ignored and material files never opened: rts does not use OBJ
// materials, and a material path could name any file (or a device that never ends).
std::shared_ptr<MeshData> load_obj(const std::string& path, const std::string& shown, bool smooth, SourceRef where,
                                   const ObjLimits& limits = {});

// Computes per-vertex normals from the triangles (for smooth shading): each face weighted by
// its area, or with `equal_weights` each face's unit normal counted once (MIT 6.837 a2's).
void compute_smooth_normals(MeshData& mesh, bool equal_weights = false);

}  // namespace rts::render
