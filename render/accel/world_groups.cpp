// Two-level instancing: a group placed several times (instanced_groups, flatten.hpp) is built
// once, in its own space, with a BVH of its own, and each placement is one top-level instance
// with a GroupTransform. A ray that reaches a placement is carried into the group's space and
// traced against the group's parts; the closest hit comes back carried into the placement's
// parent space, naming the shape instance it shows (SurfaceHit::csg_part) and that shape's
// own object point (SurfaceHit::leaf_point), so shading sees the same records as for a copy.
#include <cmath>

#include "render/geometry/transform_inverse.hpp"
#include "render/accel/hit_transform.hpp"
#include "render/accel/world.hpp"

namespace rts::render {

uint32_t World::group_accel(const SceneDesc& scene, const std::vector<bool>& instanced, uint32_t group, int level,
                            bool specialize, std::vector<Instance>& parts, std::vector<uint32_t>& built) {
  if (built[group] != kNoId) return built[group];
  const FlatScene local = flatten_group(scene, instanced, group, level);
  std::vector<Instance> mine;
  std::vector<AABB> boxes;
  mine.reserve(local.shapes.size() + local.groups.size());
  boxes.reserve(local.shapes.size() + local.groups.size());
  for (const FlatShape& fs : local.shapes) {
    Instance inst;
    AABB box;
    bool unbounded = false;
    // instanced_groups admits bounded shapes only; a shape that cannot be hit is left out.
    // An instanced group holds no group material: each shape shows its own.
    if (!add_shape_instance(scene, fs.shape, local.to_world(fs), inst, box, unbounded, scene.shapes[fs.shape].material) ||
        unbounded)
      continue;
    mine.push_back(inst);
    boxes.push_back(box);
  }
  for (const FlatGroup& fg : local.groups) {
    const uint32_t sub = group_accel(scene, instanced, fg.group, level + 1, specialize, parts, built);
    Instance inst;
    AABB box;
    if (!add_group_instance(sub, local.to_world(fg), inst, box)) continue;
    mine.push_back(inst);
    boxes.push_back(box);
  }
  Group g;
  g.first = static_cast<uint32_t>(parts.size());  // made absolute when the world is assembled
  g.count = static_cast<uint32_t>(mine.size());
  for (const AABB& b : boxes) g.bounds.extend(b);
  g.use_bvh = !(specialize && mine.size() <= kMaxObjectsWithoutBvh);
  if (g.use_bvh) g.bvh = render::build_bvh(std::move(boxes));
  parts.insert(parts.end(), mine.begin(), mine.end());
  groups_.push_back(std::move(g));
  built[group] = static_cast<uint32_t>(groups_.size() - 1);
  return built[group];
}

bool World::add_group_instance(uint32_t gi, const Mat4& to_world, Instance& inst, AABB& bounds) {
  const AABB& group_bounds = groups_[gi].bounds;
  if (!group_bounds.valid()) return false;  // nothing in it can be hit
  inst.kind = kGroupKind;
  inst.index = gi;
  if (to_world == Mat4(1.0)) {
    bounds = group_bounds;
    return true;
  }
  if (!invertible_transform(to_world)) return false;
  const glm::dmat4x3 world_map(to_world), object_map(inverse_transform(to_world));
  GroupLinear linear{glm::dmat3(world_map), glm::dmat3(object_map)};
  // Shared by bits: two placements share a pair only when all 18 doubles are the same.
  GroupTransform xf;
  xf.linear = group_linear_index_.intern(linear, group_linears_);
  xf.to_world_t = world_map[3];
  inst.transform = static_cast<uint32_t>(group_offsets_.size());
  group_offsets_.push_back(xf.to_world_t);
  group_linear_of_.push_back(xf.linear);
  bounds = world_bounds(inst);  // as the BVH build will make it again
  return bounds.finite();
}

Ray World::group_ray(const Instance& inst, const Ray& r) const {
  if (inst.transform == kNoId) return r;
  const GroupTransform xf = group_transform(inst.transform);
  const glm::dmat3& to_object = group_object_linear(xf);
  return Ray{to_object * (r.origin - xf.to_world_t), to_object * r.direction};
}

bool World::intersect_group(const Instance& inst, const Ray& parent_ray, const Interval& ray_t,
                            SurfaceHit& hit) const {
  const Group& g = groups_[inst.index];
  const Ray ray = group_ray(inst, parent_ray);
  SurfaceHit best;
  uint32_t best_part = 0;
  bool have_best = false;
  // The same closest-hit rule as World::intersect (coincident surfaces: the lower part wins).
  const double tie_scale =
      tol::kCoincidentRelative * max_abs_component(ray.origin) / max_abs_component(ray.direction);
  auto closer = [&](uint32_t i, Interval& t_range) {
    SurfaceHit h;
    if (!intersect_instance(instances_[i], ray, t_range, h)) return false;
    if (have_best) {
      double tie = tie_scale + tol::kCoincidentRelative * best.t;
      bool tied = std::abs(h.t - best.t) <= tie;
      if (tied ? i > best_part : h.t > best.t) return false;
    }
    best = h;
    best_part = i;
    have_best = true;
    t_range.max = std::min(ray_t.max, h.t + tie_scale + tol::kCoincidentRelative * h.t);
    return true;
  };
  Interval range = ray_t;
  if (g.use_bvh) {
    traverse_bvh<false>(g.bvh, ray, range,
                        [&](uint32_t slot, Interval& t_range) { return closer(g.first + g.bvh.order[slot], t_range); });
  } else {
    for (uint32_t i = 0; i < g.count; ++i) closer(g.first + i, range);
  }
  if (!have_best) return false;
  // Into the group's space: the part's own transform (a shape's, or a nested placement's).
  const Instance& part = instances_[best_part];
  if (part.kind == kGroupKind) {
    if (part.transform != kNoId) {
      const GroupTransform xf = group_transform(part.transform);
      group_to_parent(group_to_world(xf), group_object_linear(xf), best);
    }
  } else {
    best.csg_part = best_part;
    best.leaf_point = best.point;
    // Only some kinds set tangents; the others' are cleared before they are carried.
    if (!kShapeInfos[part.kind].has_tangents) best.dpdu = best.dpdv = Vec3(0.0);
    if (part.transform != kNoId) {
      const InstanceTransform& xf = transforms_[part.transform];
      shape_to_parent(instance_linears_[xf.linear], xf.to_world_t, best);
    }
  }
  hit = best;
  return true;
}

bool World::occluded_group(const Instance& inst, const Ray& parent_ray, const Interval& ray_t) const {
  const Group& g = groups_[inst.index];
  const Ray ray = group_ray(inst, parent_ray);
  Interval range = ray_t;
  if (!g.use_bvh) {
    for (uint32_t i = 0; i < g.count; ++i)
      if (occluded_instance(instances_[g.first + i], ray, range)) return true;
    return false;
  }
  return traverse_bvh<true>(g.bvh, ray, range, [&](uint32_t slot, Interval& t_range) {
    return occluded_instance(instances_[g.first + g.bvh.order[slot]], ray, t_range);
  });
}

}  // namespace rts::render
