#include "render/world.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "render/shapes/box.hpp"
#include "render/shapes/cone.hpp"
#include "render/shapes/cylinder.hpp"
#include "render/shapes/disc.hpp"
#include "render/shapes/plane.hpp"
#include "render/shapes/quad.hpp"
#include "render/shapes/sphere.hpp"
#include "render/shapes/triangle.hpp"
#include "render/tolerances.hpp"

namespace rts::render {
namespace {

bool is_identity(const Mat4& m) { return m == Mat4(1.0); }

}  // namespace

World::World(const SceneDesc& scene, const FlatScene& flat) {
  meshes_.resize(scene.meshes.size());
  std::vector<Instance> bounded, unbounded;
  std::vector<AABB> boxes;
  for (const FlatShape& fs : flat.shapes) {
    const ShapeDesc& shape = scene.shapes[fs.shape];
    Instance inst;
    inst.material = shape.material;
    if (shape.material < scene.materials.size()) {
      const Color& t = scene.materials[shape.material].transmit;
      inst.transmissive = t.r > 0.0 || t.g > 0.0 || t.b > 0.0;
      has_transmissive_ = has_transmissive_ || inst.transmissive;
    }
    bool identity = is_identity(fs.to_world);
    if (!identity) {
      double det = glm::determinant(glm::dmat3(fs.to_world));
      if (!(std::abs(det) > tol::kSingularDeterminant) || !std::isfinite(det)) continue;
      InstanceTransform xf;
      xf.to_object = glm::inverse(fs.to_world);
      xf.normal_to_world = glm::transpose(glm::dmat3(xf.to_object));
      xf.vector_to_world = glm::dmat3(fs.to_world);
      inst.transform = static_cast<uint32_t>(transforms_.size());
      transforms_.push_back(xf);
    }
    AABB object_bounds;
    bool unbounded_shape = false;
    std::visit(
        [&](const auto& g) {
          using T = std::decay_t<decltype(g)>;
          if constexpr (std::is_same_v<T, Sphere>) {
            inst.kind = PrimKind::Sphere; inst.index = spheres_.size(); spheres_.push_back(g);
            object_bounds = bounds(g);
          } else if constexpr (std::is_same_v<T, Plane>) {
            inst.kind = PrimKind::Plane; inst.index = plane_shapes_.size(); plane_shapes_.push_back(g);
            unbounded_shape = true;
          } else if constexpr (std::is_same_v<T, Triangle>) {
            inst.kind = PrimKind::Triangle; inst.index = triangles_.size(); triangles_.push_back(g);
            object_bounds = bounds(g);
          } else if constexpr (std::is_same_v<T, Box>) {
            inst.kind = PrimKind::Box; inst.index = boxes_.size(); boxes_.push_back(g);
            object_bounds = bounds(g);
          } else if constexpr (std::is_same_v<T, Cylinder>) {
            inst.kind = PrimKind::Cylinder; inst.index = cylinders_.size(); cylinders_.push_back(g);
            object_bounds = bounds(g);
          } else if constexpr (std::is_same_v<T, Cone>) {
            inst.kind = PrimKind::Cone; inst.index = cones_.size(); cones_.push_back(g);
            object_bounds = bounds(g);
          } else if constexpr (std::is_same_v<T, Disc>) {
            inst.kind = PrimKind::Disc; inst.index = discs_.size(); discs_.push_back(g);
            object_bounds = bounds(g);
          } else if constexpr (std::is_same_v<T, Quad>) {
            inst.kind = PrimKind::Quad; inst.index = quads_.size(); quads_.push_back(g);
            object_bounds = bounds(g);
          } else if constexpr (std::is_same_v<T, MeshRef>) {
            if (g.mesh >= scene.meshes.size() || !scene.meshes[g.mesh])
              throw RenderError(shape.loc, "internal: shape refers to unknown mesh " + std::to_string(g.mesh));
            meshes_[g.mesh] = mesh_accel(scene, g.mesh);
            inst.kind = PrimKind::Mesh; inst.index = g.mesh; inst.smooth = g.smooth;
            inst.vertex_material = scene.meshes[g.mesh]->has_vertex_material();
            object_bounds = meshes_[g.mesh]->bounds();
          }
        },
        shape.geometry);
    if (unbounded_shape) {
      unbounded.push_back(inst);
      continue;
    }
    if (!object_bounds.valid()) continue;  // empty mesh, nothing to hit
    AABB world_bounds = identity ? object_bounds : transform_bounds(fs.to_world, object_bounds);
    if (!world_bounds.finite()) continue;  // NaN/inf coordinates: never hit
    bounded.push_back(inst);
    boxes.push_back(world_bounds);
  }
  bvh_ = build_bvh(boxes);
  instances_ = std::move(bounded);
  for (Instance& p : unbounded) {
    planes_.push_back(static_cast<uint32_t>(instances_.size()));
    instances_.push_back(p);
  }
}

namespace {
bool same_mesh_data(const MeshData& a, const MeshData& b) {
  return a.source == b.source && a.indices == b.indices && a.positions == b.positions &&
         a.normals == b.normals && a.uvs == b.uvs && a.colors == b.colors &&
         a.diffuse == b.diffuse && a.specular == b.specular && a.shininess == b.shininess;
}
}  // namespace

std::shared_ptr<const MeshAccel> World::mesh_accel(const SceneDesc& scene, MeshId id) {
  if (meshes_[id]) return meshes_[id];
  const MeshData& data = *scene.meshes[id];
  for (MeshId other = 0; other < meshes_.size(); ++other) {
    // Comparing the arrays is far cheaper than building a second BVH over them.
    if (meshes_[other] && (scene.meshes[other] == scene.meshes[id] ||
                           same_mesh_data(*scene.meshes[other], data)))
      return meshes_[other];
  }
  return std::make_shared<const MeshAccel>(scene.meshes[id]);
}

std::size_t World::mesh_bvh_count() const {
  std::vector<const MeshAccel*> distinct;
  for (const auto& m : meshes_)
    if (m && std::find(distinct.begin(), distinct.end(), m.get()) == distinct.end()) distinct.push_back(m.get());
  return distinct.size();
}

Ray World::object_ray(const Instance& inst, const Ray& r) const {
  if (inst.transform == kNoId) return r;
  const Mat4& m = transforms_[inst.transform].to_object;
  return Ray{Vec3(m * glm::dvec4(r.origin, 1.0)), Vec3(m * glm::dvec4(r.direction, 0.0))};
}

bool World::intersect_instance(const Instance& inst, const Ray& world_ray, const Interval& ray_t,
                               SurfaceHit& hit) const {
  Ray ray = object_ray(inst, world_ray);
  switch (inst.kind) {
    case PrimKind::Sphere: return render::intersect(spheres_[inst.index], ray, ray_t, hit);
    case PrimKind::Plane: return render::intersect(plane_shapes_[inst.index], ray, ray_t, hit);
    case PrimKind::Triangle: return render::intersect(triangles_[inst.index], ray, ray_t, hit);
    case PrimKind::Box: return render::intersect(boxes_[inst.index], ray, ray_t, hit);
    case PrimKind::Cylinder: return render::intersect(cylinders_[inst.index], ray, ray_t, hit);
    case PrimKind::Cone: return render::intersect(cones_[inst.index], ray, ray_t, hit);
    case PrimKind::Disc: return render::intersect(discs_[inst.index], ray, ray_t, hit);
    case PrimKind::Mesh: return meshes_[inst.index]->intersect(ray, ray_t, hit, inst.smooth);
    case PrimKind::Quad: return render::intersect(quads_[inst.index], ray, ray_t, hit);
  }
  return false;
}

bool World::occluded_instance(const Instance& inst, const Ray& world_ray, const Interval& ray_t) const {
  if (inst.kind == PrimKind::Mesh) {
    return meshes_[inst.index]->occluded(object_ray(inst, world_ray), ray_t);
  }
  SurfaceHit scratch;
  return intersect_instance(inst, world_ray, ray_t, scratch);
}

bool World::intersect(const Ray& ray, Interval ray_t, WorldHit& hit, bool transmissive_only) const {
  SurfaceHit best;
  uint32_t best_instance = 0;
  // Instance i hit within t_range: keep it as the closest so far and end the range there.
  auto closer = [&](uint32_t i, Interval& t_range) {
    if (transmissive_only && !instances_[i].transmissive) return false;
    SurfaceHit h;
    if (!intersect_instance(instances_[i], ray, t_range, h)) return false;
    t_range.max = h.t;
    best = h;
    best_instance = i;
    return true;
  };
  bool found = traverse_bvh<false>(bvh_, ray, ray_t,
                                   [&](uint32_t slot, Interval& t_range) { return closer(bvh_.order[slot], t_range); });
  for (uint32_t i : planes_) found = closer(i, ray_t) || found;
  if (!found) return false;
  const Instance& inst = instances_[best_instance];
  hit.t = best.t;
  hit.instance = best_instance;
  hit.point = ray.at(best.t);
  hit.object_point = best.point;
  hit.uv = best.uv;
  // Spherical UVs cost two inverse trigonometric calls: computed by surface_uv() only when a
  // texture asks for them.
  hit.has_uv = best.has_uv || inst.kind == PrimKind::Sphere;
  const bool mesh = inst.kind == PrimKind::Mesh;
  hit.triangle = mesh ? best.triangle : 0;
  hit.bary = mesh ? best.bary : glm::dvec2(0.0);
  if (!mesh && inst.kind != PrimKind::Quad) best.dpdu = best.dpdv = Vec3(0.0);   // not set by the others
  if (inst.transform == kNoId) {
    hit.normal = glm::normalize(best.normal);
    hit.shading_normal = glm::normalize(best.shading_normal);
    hit.dpdu = best.dpdu;
    hit.dpdv = best.dpdv;
  } else {
    const InstanceTransform& xf = transforms_[inst.transform];
    const glm::dmat3& nm = xf.normal_to_world;
    hit.normal = glm::normalize(nm * best.normal);
    hit.shading_normal = glm::normalize(nm * best.shading_normal);
    // Tangents transform as vectors, unlike normals.
    hit.dpdu = xf.vector_to_world * best.dpdu;
    hit.dpdv = xf.vector_to_world * best.dpdv;
  }
  return true;
}

bool World::vertex_material(const WorldHit& hit, VertexMaterial& out) const {
  const Instance& inst = instances_[hit.instance];
  if (!inst.vertex_material) return false;
  return meshes_[inst.index]->vertex_material(hit.triangle, hit.bary, out);
}

glm::dvec2 World::surface_uv(const WorldHit& hit) const {
  const Instance& inst = instances_[hit.instance];
  if (inst.kind != PrimKind::Sphere) return hit.uv;
  const Sphere& sp = spheres_[inst.index];
  return sphere_uv((hit.object_point - sp.center) / sp.radius);
}

bool World::occluded(const Ray& ray, Interval ray_t, bool opaque_only) const {
  auto blocks = [&](uint32_t i, const Interval& t_range) {
    return !(opaque_only && instances_[i].transmissive) && occluded_instance(instances_[i], ray, t_range);
  };
  for (uint32_t i : planes_)
    if (blocks(i, ray_t)) return true;
  return traverse_bvh<true>(bvh_, ray, ray_t,
                            [&](uint32_t slot, Interval& t_range) { return blocks(bvh_.order[slot], t_range); });
}

}  // namespace rts::render
