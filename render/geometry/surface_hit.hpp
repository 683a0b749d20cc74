// What a primitive's intersect() reports: all vectors in the primitive's object space.
#pragma once

#include <glm/glm.hpp>

#include "render/scene/scene.hpp"

namespace rts::render {

struct SurfaceHit {
  double t = 0.0;            // ray parameter (the same in object and world space)
  Vec3 point{0.0};           // object-space hit point
  Vec3 normal{0, 1, 0};      // geometric normal, outward, not necessarily unit length
  Vec3 shading_normal{0, 1, 0};  // interpolated normal (== normal unless smooth)
  glm::dvec2 uv{0.0};
  bool has_uv = false;
  double error = 0.0;        // bound on |point - exact point| per component (object space)
  // Object-space derivatives of the point along u and v, for bump and normal maps' tangent
  // frame; set only by the shapes that have them (quads, meshes with uvs: World reads them for
  // those kinds only), so the candidate hits of every other test do not pay to clear them.
  Vec3 dpdu, dpdv;
  // Triangles of meshes: the triangle index and barycentrics (b1, b2) of vertices 1 and 2, for
  // per-vertex materials (set by meshes only, read for meshes only).
  uint32_t triangle;
  glm::dvec2 bary;
  // CSG blocks: the instance of the leaf whose surface this is (set and read for CSG only).
  // Instanced groups: the same, the shape instance inside the group.
  uint32_t csg_part;
  // Instanced groups: the leaf's object-space point (`point` is then in the group's space).
  Vec3 leaf_point;
};

// Per-vertex material values interpolated at a hit (each only when the mesh has it).
struct VertexMaterial {
  bool has_color = false, has_diffuse = false, has_specular = false, has_shininess = false;
  Color color, specular;   // specular: the highlight's color (weight per channel)
  double diffuse = 0, shininess = 0;
};

}  // namespace rts::render
