// A triangle mesh ready for tracing: its own BVH (the bottom level of the two-level BVH),
// built once per MeshData and shared by every instance of that mesh. It works in the mesh's
// own coordinates (relative to MeshData::origin) and reports hits in object space.
#pragma once

#include <memory>
#include <vector>

#include "render/accel/bvh.hpp"
#include "render/geometry/csg/csg_tree.hpp"
#include "render/scene/scene.hpp"
#include "render/geometry/surface_hit.hpp"

namespace rts::render {

class MeshAccel {
 public:
  explicit MeshAccel(std::shared_ptr<const MeshData> mesh);

  AABB bounds() const { return bounds_; }  // object space (origin included)
  std::size_t triangle_count() const { return triangle_count_; }
  // Closest hit in object space; `smooth` interpolates the mesh's vertex normals if it has them.
  bool intersect(const Ray& ray, Interval ray_t, SurfaceHit& hit, bool smooth) const;
  bool occluded(const Ray& ray, Interval ray_t) const;
  // For CSG (the mesh bounds a solid: render/geometry/shapes/mesh_closure.hpp): where the whole
  // line of `object_ray` enters and leaves the solid, as CSG's crossing lists say it
  // (render/geometry/csg/csg_tree.hpp). Triangle hits closer than a tie (tie_abs + tie_rel |t|)
  // are one place: a line through a shared edge or vertex hits each triangle there, and is one
  // crossing when they all face one way, none (it grazes the silhouette) when they do not.
  // Only crossings at or after `from` are listed (inside_at_start is the state at `from`),
  // at most kMaxLeafCrossings of them; returns true when more follow (the list stops short).
  bool csg_crossings(const Ray& object_ray, double from, double tie_abs, double tie_rel, CsgLeafCrossings& out) const;
  std::size_t bvh_nodes() const { return bvh_.nodes.size(); }
  // Bytes held: the mesh's arrays, its BVH and the leaf-ordered vertices.
  std::size_t memory_bytes() const;
  // Per-vertex material values of triangle `tri` at barycentrics (b1, b2); false when the
  // mesh has none.
  bool vertex_material(uint32_t tri, glm::dvec2 bary, VertexMaterial& out) const;

 private:
  // The object-space ray in the mesh's own coordinates (relative to MeshData::origin).
  Ray local_ray(const Ray& object_ray) const;
  void triangle(uint32_t tri, Vec3& v0, Vec3& v1, Vec3& v2) const;  // by triangle index

  std::shared_ptr<const MeshData> mesh_;
  std::size_t triangle_count_ = 0;
  BVH bvh_;                          // its `order` holds triangle indices into mesh_->indices
  // The vertices of each BVH primitive, 3 per triangle in BVH leaf order: a leaf's triangles
  // are contiguous in memory instead of three index lookups each.
  std::vector<glm::vec3> leaf_vertices_;
  AABB bounds_;
};

}  // namespace rts::render
