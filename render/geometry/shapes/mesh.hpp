// Mesh: triangles from an OBJ file or written inline. Its data live in SceneDesc::meshes (a
// MeshRef names one); render/accel/mesh_accel.* builds its BVH and intersects it.
#pragma once

#include "render/geometry/shapes/shape_info.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// The `mesh` block: see docs/shapes.md#mesh.
template <>
struct ShapeTraits<MeshRef> {
  static constexpr PropertyInfo kProperties[] = {
      {"file", "string", "—",
       "A Wavefront OBJ file (relative to the scene file); faces are triangulated, `vn` normals and `vt` uvs kept. Give `file` or `vertices` + `faces`, not both."},
      {"smooth", "bool", "`true`",
       "Smooth shading: the file's or given normals, or normals averaged from the faces when there are none. `false`: flat faces."},
      {"smooth_weights", "string", "`\"area\"`",
       "How faces are averaged into vertex normals when the mesh has none: `\"area\"` weighs each face by its area; `\"equal\"` averages the faces' unit normals (MIT 6.837 a2's)."},
      {"vertices", "list of vectors", "—",
       "Inline positions, kept in single precision about their centre: spanning 1e-36 to 1e38 units (a `scale` transform has no such limit)."},
      {"faces", "list of vectors", "—",
       "Inline triangles, each `<i, j, k>`: indices into `vertices`, from 0."},
      {"normals", "list of vectors", "none", "Inline: one normal per vertex."},
      {"vertex_colors", "list of colors", "none",
       "Inline: a color per vertex, interpolated; replaces the material's `color`."},
      {"vertex_diffuse", "list of numbers", "none", "Inline: a `diffuse` weight per vertex, interpolated."},
      {"vertex_specular", "list of numbers or colors", "none",
       "Inline: a highlight color per vertex (a number x is `rgb(x)`), interpolated."},
      {"vertex_shininess", "list of numbers", "none", "Inline: a `shininess` per vertex, interpolated."},
  };
  static constexpr ShapeInfo kInfo{
      .name = "mesh", .properties = kProperties, .closure = Closure::WhenWatertight, .has_uv = true, .has_tangents = true};
};

}  // namespace rts::render
