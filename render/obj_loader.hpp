// Wavefront OBJ loading (tinyobjloader) into the renderer's MeshData: triangulated, with
// per-corner positions/normals/uvs flattened into unified vertices, smooth normals computed
// when the file has none and smoothing is asked for.
#pragma once

#include <memory>
#include <string>

#include "render/scene.hpp"

namespace rts::render {

// Loads `path` (already resolved). Throws SceneError at `where` when the file is missing or
// malformed; the message names the OBJ as the scene wrote it (`shown`) and, where known, the
// OBJ's own line ("bunny.obj:12: face vertex index 40 out of range").
std::shared_ptr<MeshData> load_obj(const std::string& path, const std::string& shown, bool smooth, SourceRef where);

// Computes area-weighted per-vertex normals from the triangles (for smooth shading).
void compute_smooth_normals(MeshData& mesh);

}  // namespace rts::render
