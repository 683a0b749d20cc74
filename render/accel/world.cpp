#include "render/geometry/transform_inverse.hpp"
#include "render/accel/world.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "render/accel/hit_transform.hpp"
#include "render/accel/shape_release.hpp"
#include "render/geometry/csg/leaf_crossings.hpp"
#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {
namespace {
// The traversals' two filters (closest, occluded_impl, shadow_crossings_impl). Types of this
// file alone: the instantiations, their lambdas and the traversals made for them then have
// internal linkage, so GCC inlines as it did before shadowless objects (instantiated on a
// bool, intersect()'s traversal stayed a call: +2.6% instructions on a diffuse scene).
struct AllInstances { static constexpr bool kSkipShadowless = false; };
struct CastingShadows { static constexpr bool kSkipShadowless = true; };

bool is_identity(const Mat4& m) { return m == Mat4(1.0); }

}  // namespace

uint32_t World::add_transform(const Mat4& to_world) {
  const Mat4 to_object = inverse_transform(to_world);
  InstanceLinear linear{glm::dmat3(to_world), glm::dmat3(to_object), glm::transpose(glm::dmat3(to_object))};
  // Shared by bits: two instances share a pair only when every double is the same.
  InstanceTransform xf;
  xf.linear = instance_linear_index_.intern(linear, instance_linears_);
  xf.to_world_t = Vec3(to_world[3]);
  transforms_.push_back(xf);
  return static_cast<uint32_t>(transforms_.size() - 1);
}

void World::add_geometry(const SceneDesc& scene, const ShapeDesc& shape, Instance& inst, AABB& object_bounds,
                         bool& unbounded_shape) {
  visit_shape(
      [&](const auto& g) {
        using T = std::decay_t<decltype(g)>;
        inst.kind = kPrimKind<T>;
        if constexpr (std::is_same_v<T, MeshRef>) {
          if (g.mesh >= scene.meshes.size() || !scene.meshes[g.mesh])
            throw RenderError(shape.loc, "internal: shape refers to unknown mesh " + std::to_string(g.mesh));
          meshes_[g.mesh] = mesh_accel(scene, g.mesh);
          inst.index = g.mesh; inst.smooth = g.smooth;
          inst.vertex_material = scene.meshes[g.mesh]->has_vertex_material();
          object_bounds = meshes_[g.mesh]->bounds();
        } else {
          auto& array = std::get<std::vector<T>>(shapes_);
          inst.index = static_cast<uint32_t>(array.size());
          array.push_back(g);
          if constexpr (std::is_same_v<T, Quad>) quad_frames_.emplace_back(g);
          if constexpr (std::is_same_v<T, Plane>) plane_frames_.emplace_back(g);
          if constexpr (ShapeTraits<T>::kInfo.bounded)
            object_bounds = bounds(g);
          else
            unbounded_shape = true;
        }
      },
      shape.geometry);
}

bool World::add_shape_instance(const SceneDesc& scene, uint32_t shape_index, const Mat4& to_world, Instance& inst,
                               AABB& bounds, bool& unbounded, MaterialId material) {
  const ShapeDesc& shape = scene.shapes[shape_index];
  inst.material = material;  // its own, else its group's
  if (material < scene.materials.size()) {
    const Color& t = scene.materials[material].transmit;
    inst.transmissive = t.r > 0.0 || t.g > 0.0 || t.b > 0.0;
    has_transmissive_ = has_transmissive_ || inst.transmissive;
  }
  if (!is_identity(to_world)) {
    if (!invertible_transform(to_world)) return false;
    inst.transform = add_transform(to_world);
  }
  AABB object_bounds;
  add_geometry(scene, shape, inst, object_bounds, unbounded);
  if (unbounded) return true;
  if (!object_bounds.valid()) return false;  // empty mesh, nothing to hit
  bounds = world_bounds(inst);               // as the BVH build will make it again
  return bounds.finite();                    // NaN/inf coordinates: never hit
}

// Each kind's array sized once for the shapes placed: grown by doubling, the last copy held the
// largest one one and a half times beside the description being released (4M spheres: 67 MB
// more at the build's peak, RSS trace, issue 24). Meshes are kept by MeshId, not copied.
void World::reserve_shape_arrays(const SceneDesc& scene, const FlatScene& flat) {
  std::array<std::size_t, kShapeKindCount> count{};
  for (const FlatShape& fs : flat.shapes)
    if (fs.shape < scene.shapes.size()) ++count[scene.shapes[fs.shape].geometry.index()];
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (std::get<I>(shapes_).reserve(std::is_same_v<ShapeKind<I>, MeshRef> ? 0 : count[I]), ...);
  }(std::make_index_sequence<kShapeKindCount>{});
}

World::World(const SceneDesc& scene, const FlatScene& flat, bool specialize, WorldBuild build, SceneDesc* taken) {
  meshes_.resize(scene.meshes.size());
  std::vector<Instance> bounded, unbounded, parts;
  // Whether each bounded and unbounded instance casts no shadow, kept only when one does not.
  bool any_shadowless = !flat.shadowless.empty();
  for (const FlatCsg& fc : flat.csgs) any_shadowless = any_shadowless || !fc.casts_shadow;
  for (const FlatGroup& fg : flat.groups) any_shadowless = any_shadowless || !fg.casts_shadow;
  std::vector<uint8_t> bounded_shadowless, unbounded_shadowless;
  auto keep = [&](std::vector<Instance>& to, std::vector<uint8_t>& flags, const Instance& inst, bool casts) {
    to.push_back(inst);
    if (any_shadowless) flags.push_back(casts ? 0 : 1);
  };
  // Sized once: grown by doubling, the instances left their outgrown blocks resident in the
  // heap through the BVH build.
  const std::size_t objects = flat.shapes.size() + flat.groups.size() + flat.csgs.size();
  bounded.reserve(objects);
  // The placements' transforms are kept by the shapes' instances and the groups' placements.
  transforms_.reserve(static_cast<std::size_t>(std::count_if(
      flat.shapes.begin(), flat.shapes.end(), [](const FlatShape& fs) { return fs.transform != kNoId; })));
  group_offsets_.reserve(flat.groups.size());
  group_linear_of_.reserve(flat.groups.size());
  reserve_shape_arrays(scene, flat);
  ShapeRelease release(taken, flat);
  for (std::size_t i = 0; i < flat.shapes.size(); ++i) {
    const FlatShape& fs = flat.shapes[i];
    Instance inst;
    AABB world_bounds;
    bool unbounded_shape = false;
    const bool made = add_shape_instance(scene, fs.shape, flat.to_world(fs), inst, world_bounds, unbounded_shape,
                                         flat.material(scene, i));
    release.passed(i);
    if (!made) continue;
    if (unbounded_shape) {
      keep(unbounded, unbounded_shadowless, inst, flat.casts_shadow(i));
      continue;
    }
    keep(bounded, bounded_shadowless, inst, flat.casts_shadow(i));
  }
  // Instanced groups: each group's contents built once, each placement one instance.
  std::vector<Instance> group_parts;
  if (!flat.groups.empty()) {
    std::vector<uint32_t> built(scene.groups.size(), kNoId);
    for (const FlatGroup& fg : flat.groups) {
      const uint32_t gi = group_accel(scene, flat.instanced, fg.group, 0, specialize, group_parts, built);
      Instance inst;
      AABB world_bounds;
      if (!add_group_instance(gi, flat.to_world(fg), inst, world_bounds)) continue;
      keep(bounded, bounded_shadowless, inst, fg.casts_shadow);
    }
  }
  // CSG blocks: traced in world space through their leaves' own transforms (the block has
  // none); transmissive when any leaf is, so shadow rays look at each of its surfaces.
  for (const FlatCsg& fc : flat.csgs) {
    Instance inst;
    AABB world_bounds;
    add_csg(scene, fc, parts, inst, world_bounds);
    has_transmissive_ = has_transmissive_ || inst.transmissive;
    if (!world_bounds.valid()) continue;  // an empty intersection: nothing to hit
    if (!world_bounds.finite()) {
      keep(unbounded, unbounded_shadowless, inst, fc.casts_shadow);
    } else {
      keep(bounded, bounded_shadowless, inst, fc.casts_shadow);
    }
  }
  bounded_count_ = bounded.size();
  group_linear_index_.release();  // every placement is made: free the indexes before the BVH build
  instance_linear_index_.release();
  use_bvh_ = !(specialize && bounded_count_ <= kMaxObjectsWithoutBvh);
  // Room for what follows the bounded instances, so the array is not doubled by appending a
  // group's 64 parts to a million placements (16 bytes per placement of slack, found by
  // --stats on bench/instancing/copies.rts).
  bounded.reserve(bounded.size() + unbounded.size() + group_parts.size() + parts.size());
  instances_ = std::move(bounded);
  for (Instance& p : unbounded) {
    planes_.push_back(static_cast<uint32_t>(instances_.size()));
    instances_.push_back(p);
  }
  if (any_shadowless) {
    shadowless_ = std::move(bounded_shadowless);
    shadowless_.insert(shadowless_.end(), unbounded_shadowless.begin(), unbounded_shadowless.end());
  }
  // Group parts next: they are reached through their group's placements only.
  const uint32_t group_base = static_cast<uint32_t>(instances_.size());
  for (Group& g : groups_) g.first += group_base;
  instances_.insert(instances_.end(), group_parts.begin(), group_parts.end());
  group_parts_ = group_parts.size();
  // CSG leaves last: they are reached through their block only.
  const uint32_t base = static_cast<uint32_t>(instances_.size());
  for (Csg& c : csgs_)
    for (uint32_t& i : c.leaf_instance) i += base;
  instances_.insert(instances_.end(), parts.begin(), parts.end());
  csg_parts_ = parts.size();
  // Group and CSG parts are reached through their placement or block only: never skipped.
  if (any_shadowless) shadowless_.resize(instances_.size(), 0);
  if (build == WorldBuild::Whole) build_bvh();
}

void World::build_bvh() {
  if (!use_bvh_ || bvh_built_) return;
  bvh_built_ = true;
  // The BVH's leaves index instances_[0, bounded_count_), which the rest of the assembly leaves
  // in place. Their boxes are made again from the world's own arrays, straight into the
  // builder's references: no box array lives beside the scene description while the instances
  // are made (48 bytes per object of that peak), nor beside the references.
  auto mostly_placements = [&] {
    const auto placements = std::count_if(instances_.begin(), instances_.begin() + bounded_count_,
                                          [](const Instance& inst) { return inst.kind == kGroupKind; });
    return 2 * static_cast<std::size_t>(placements) >= bounded_count_;
  };
  auto box_of = [&](std::size_t i) { return world_bounds(instances_[i]); };
  if (bounded_count_ >= quantized_from_ && (quantize_any_kind_ || mostly_placements())) {
    // The binary tree is only the quantizer's input: leaves of up to four (which it splits)
    // leave a third of its nodes. Profile finding (RSS trace, a million placements): the binary tree's
    // two 32-byte nodes a placement, held beside the world, were the whole render's peak.
    bvh_ = render::build_bvh(bounded_count_, box_of, kQuantizedInputLeaves);
    quantized_ = quantize_bvh(bvh_, [&](uint32_t i) { return box_of(i); });
    if (!quantized_.empty()) {
      bvh_ = BVH{};
      return;
    }
    // Not quantizable (a box past float's range): the binary tree the SAH would build.
  }
  bvh_ = render::build_bvh(bounded_count_, box_of);
}

template <bool any_hit, class Visit>
bool World::traverse_top_level(const Ray& ray, Interval& ray_t, Visit&& visit) const {
  if (!quantized_.empty()) return traverse_quantized<any_hit>(quantized_, ray, ray_t, visit);
  return traverse_bvh<any_hit>(bvh_, ray, ray_t,
                               [&](uint32_t slot, Interval& t_range) { return visit(bvh_.order[slot], t_range); });
}

AABB World::world_bounds(const Instance& inst) const {
  // The same values as the instance's box when it was made: the same object box, and the
  // matrix rebuilt from exactly the columns kept (transform_bounds reads its x, y, z rows only).
  if (inst.kind == kCsgKind) {
    const Csg& c = csgs_[inst.index];
    return c.tree.bounds(c.leaf_bounds);
  }
  if (inst.kind == kGroupKind) {
    const AABB& b = groups_[inst.index].bounds;
    if (inst.transform == kNoId) return b;
    const GroupTransform xf = group_transform(inst.transform);
    return transform_bounds(affine(group_linears_[xf.linear].to_world, xf.to_world_t), b);
  }
  const AABB object = object_bounds(inst, std::make_index_sequence<kShapeKindCount>{});
  return inst.transform == kNoId ? object : transform_bounds(instance_to_world(transforms_[inst.transform]), object);
}

namespace {
bool same_mesh_data(const MeshData& a, const MeshData& b) {
  return a.source == b.source && a.origin == b.origin && a.indices == b.indices && a.positions == b.positions &&
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
  const InstanceTransform& xf = transforms_[inst.transform];
  const glm::dmat3& l = instance_linears_[xf.linear].to_object;
  return Ray{l * (r.origin - xf.to_world_t), l * r.direction};
}

// One test per kind, chosen by comparing the kind with each index in turn (GCC turns the
// chain into a jump table, like the switch it replaces).
template <std::size_t... I>
bool World::intersect_kind(std::index_sequence<I...>, const Instance& inst, const Ray& ray, const Interval& ray_t,
                           SurfaceHit& hit) const {
  bool found = false;
  (void)((inst.kind == I && (found = [&] {
            using T = ShapeKind<I>;
            if constexpr (std::is_same_v<T, MeshRef>)
              return meshes_[inst.index]->intersect(ray, ray_t, hit, inst.smooth);
            else if constexpr (std::is_same_v<T, Quad>)
              return render::intersect(quad_frames_[inst.index], ray, ray_t, hit);
            else if constexpr (std::is_same_v<T, Plane>)
              return render::intersect(plane_frames_[inst.index], ray, ray_t, hit);
            else
              return render::intersect(std::get<I>(shapes_)[inst.index], ray, ray_t, hit);
          }(), true)) || ...);
  return found;
}

bool World::intersect_instance(const Instance& inst, const Ray& world_ray, const Interval& ray_t,
                               SurfaceHit& hit) const {
  if (inst.kind == kCsgKind) return intersect_csg(inst, world_ray, ray_t, hit);
  if (inst.kind == kGroupKind) return intersect_group(inst, world_ray, ray_t, hit);
  return intersect_kind(std::make_index_sequence<kShapeKindCount>(), inst, object_ray(inst, world_ray), ray_t, hit);
}

bool World::occluded_instance(const Instance& inst, const Ray& world_ray, const Interval& ray_t) const {
  if (inst.kind == kPrimKind<MeshRef>) {
    return meshes_[inst.index]->occluded(object_ray(inst, world_ray), ray_t);
  }
  if (inst.kind == kPrimKind<Sphere>) {  // the root alone: no hit point, normal or error bound
    double t;
    return sphere_root(std::get<std::vector<Sphere>>(shapes_)[inst.index], object_ray(inst, world_ray), ray_t, t);
  }
  if (inst.kind == kPrimKind<Isosurface>)   // the crossing alone: no normal (six evaluations)
    return occludes(std::get<std::vector<Isosurface>>(shapes_)[inst.index], object_ray(inst, world_ray), ray_t);
  if (inst.kind == kGroupKind) return occluded_group(inst, world_ray, ray_t);
  if (inst.kind == kCsgKind) return occluded_csg(inst, world_ray, ray_t);  // the sweep's answer alone
  SurfaceHit scratch;
  return intersect_instance(inst, world_ray, ray_t, scratch);
}

// Inlined into intersect: a call per ray would cost scenes that have no shadowless object.
template <class Filter>
[[gnu::always_inline]] inline bool World::closest(const Ray& ray, Interval ray_t, bool transmissive_only, SurfaceHit& best,
                    uint32_t& best_instance) const {
  bool have_best = false;
  // Coincident surfaces (coplanar overlapping triangles, a box face on a plane) compute t's
  // that differ only by rounding, so "closest" would pick one or the other pixel by pixel
  // (speckles). Hits within `tie` of the closest count as the same distance and the lower
  // instance index wins: one surface shows, the same for every ray and thread.
  const double tie_scale =
      tol::kCoincidentRelative * max_abs_component(ray.origin) / max_abs_component(ray.direction);
  // Instance i hit within t_range: keep it as the closest so far and end the range there.
  auto closer = [&](uint32_t i, Interval& t_range) {
    if (transmissive_only && !instances_[i].transmissive) return false;
    if constexpr (Filter::kSkipShadowless)
      if (shadowless_[i]) return false;
    SurfaceHit h;
    if (!intersect_instance(instances_[i], ray, t_range, h)) return false;
    if (have_best) {
      double tie = tie_scale + tol::kCoincidentRelative * best.t;
      bool tied = std::abs(h.t - best.t) <= tie;
      if (tied ? i > best_instance : h.t > best.t) return false;
    }
    best = h;
    best_instance = i;
    have_best = true;
    t_range.max = h.t + tie_scale + tol::kCoincidentRelative * h.t;  // a tie may still follow
    return true;
  };
  bool found = false;
  if (use_bvh_) {
    found = traverse_top_level<false>(ray, ray_t, closer);
  } else {
    for (uint32_t i = 0; i < bounded_count_; ++i) found = closer(i, ray_t) || found;
  }
  for (uint32_t i : planes_) found = closer(i, ray_t) || found;
  return found;
}

// Out of line: scenes without shadowless objects carry none of its code in intersect().
[[gnu::noinline]] bool World::closest_casting_shadows(const Ray& ray, Interval ray_t, bool transmissive_only,
                                                     SurfaceHit& best, uint32_t& best_instance) const {
  return closest<CastingShadows>(ray, ray_t, transmissive_only, best, best_instance);
}

bool World::intersect(const Ray& ray, Interval ray_t, WorldHit& hit, bool transmissive_only, bool shadow_ray) const {
  SurfaceHit best;
  uint32_t best_instance = 0;
  const bool found = shadow_ray && !shadowless_.empty()
                         ? closest_casting_shadows(ray, ray_t, transmissive_only, best, best_instance)
                         : closest<AllInstances>(ray, ray_t, transmissive_only, best, best_instance);
  if (!found) return false;
  // A CSG block's hit shows one of its leaves: that leaf's instance has the material, uv and
  // transform of the surface; the block stays the medium.
  // So does an instanced group's: `best` is in the group's space, carried here to the world's.
  const Instance& placed = instances_[best_instance];
  const bool grouped = placed.kind == kGroupKind;
  const uint32_t shown = placed.kind == kCsgKind || grouped ? best.csg_part : best_instance;
  const Instance& inst = instances_[shown];
  hit.t = best.t;
  hit.instance = shown;
  hit.medium = best_instance;
  hit.object_point = grouped ? best.leaf_point : best.point;
  hit.uv = best.uv;
  // Spherical UVs cost two inverse trigonometric calls: computed by surface_uv() only when a
  // texture asks for them.
  hit.has_uv = best.has_uv || inst.kind == kPrimKind<Sphere>;
  const bool mesh = inst.kind == kPrimKind<MeshRef>;
  hit.triangle = mesh ? best.triangle : 0;
  hit.bary = mesh ? best.bary : glm::dvec2(0.0);
  if (!kShapeInfos[inst.kind].has_tangents) best.dpdu = best.dpdv = Vec3(0.0);   // not set by the others
  // The world point is the shape's own (refined) object point carried to world space, not
  // ray.at(t): its error bound then stays relative to the shape, whatever the ray travelled.
  if (grouped && placed.transform != kNoId) {
    const GroupTransform xf = group_transform(placed.transform);
    group_to_parent(group_to_world(xf), group_object_linear(xf), best);
  }
  if (grouped || inst.transform == kNoId) {
    hit.point = best.point;
    hit.error = best.error;
    hit.normal = glm::normalize(best.normal);
    hit.shading_normal = glm::normalize(best.shading_normal);
    hit.dpdu = best.dpdu;
    hit.dpdv = best.dpdv;
  } else {
    const InstanceTransform& xf = transforms_[inst.transform];
    const InstanceLinear& lin = instance_linears_[xf.linear];
    hit.point = apply_affine(lin.to_world, xf.to_world_t, best.point, 1.0);
    // The linear part scales the object-space error; the product and the translation add
    // rounding of their own (pbrt-v4's transformed-point error bound).
    double linear = linear_norm(lin.to_world);
    hit.error = linear * best.error * (1.0 + error_gamma(3)) +
                error_gamma(3) * (linear * max_abs_component(best.point) + max_abs_component(xf.to_world_t));
    const glm::dmat3& nm = lin.normal_to_world;
    hit.normal = glm::normalize(nm * best.normal);
    hit.shading_normal = glm::normalize(nm * best.shading_normal);
    // Tangents transform as vectors, unlike normals.
    hit.dpdu = lin.to_world * best.dpdu;
    hit.dpdv = lin.to_world * best.dpdv;
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
  if (inst.kind != kPrimKind<Sphere>) return hit.uv;
  const Sphere& sp = std::get<std::vector<Sphere>>(shapes_)[inst.index];
  return sphere_uv((hit.object_point - sp.center) / sp.radius);
}

bool World::occluded(const Ray& ray, Interval ray_t, bool opaque_only) const {
  if (!shadowless_.empty()) [[unlikely]]
    return occluded_casting_shadows(ray, ray_t, opaque_only);
  return occluded_impl<AllInstances>(ray, ray_t, opaque_only);
}

// Out of line, as closest_casting_shadows: inlined beside the other, it kept GCC from inlining
// the plane tests into occluded() (+0.9M instructions on a diffuse scene).
[[gnu::noinline]] bool World::occluded_casting_shadows(const Ray& ray, Interval ray_t, bool opaque_only) const {
  return occluded_impl<CastingShadows>(ray, ray_t, opaque_only);
}

template <class Filter>
bool World::occluded_impl(const Ray& ray, Interval ray_t, bool opaque_only) const {
  auto blocks = [&](uint32_t i, const Interval& t_range) {
    if constexpr (Filter::kSkipShadowless)
      if (shadowless_[i]) return false;
    return !(opaque_only && instances_[i].transmissive) && occluded_instance(instances_[i], ray, t_range);
  };
  for (uint32_t i : planes_)
    if (blocks(i, ray_t)) return true;
  if (!use_bvh_) {
    for (uint32_t i = 0; i < bounded_count_; ++i)
      if (blocks(i, ray_t)) return true;
    return false;
  }
  return traverse_top_level<true>(ray, ray_t, blocks);
}

bool World::shadow_crossings(const Ray& ray, Interval ray_t, ShadowCrossings& out) const {
  if (!shadowless_.empty()) [[unlikely]]
    return shadow_crossings_casting_shadows(ray, ray_t, out);
  return shadow_crossings_impl<AllInstances>(ray, ray_t, out);
}

[[gnu::noinline]] bool World::shadow_crossings_casting_shadows(const Ray& ray, Interval ray_t,
                                                              ShadowCrossings& out) const {
  return shadow_crossings_impl<CastingShadows>(ray, ray_t, out);
}

template <class Filter>
bool World::shadow_crossings_impl(const Ray& ray, Interval ray_t, ShadowCrossings& out) const {
  out.count = 0;
  // Instance i on the segment: an opaque one blocks; a transmissive one adds each of its own
  // crossings (a sphere has two), stepping past each by the same offset as a closest-hit walk.
  auto visit = [&](uint32_t i) {
    if constexpr (Filter::kSkipShadowless)
      if (shadowless_[i]) return false;
    const Instance& inst = instances_[i];
    if (!inst.transmissive) return occluded_instance(inst, ray, ray_t);
    Interval range = ray_t;
    SurfaceHit h;
    const Vec3 object_dir = object_ray(inst, ray).direction;
    while (intersect_instance(inst, ray, range, h)) {
      // A CSG hit is in its leaf's object space.
      const Vec3 dir = inst.kind == kCsgKind ? object_ray(instances_[h.csg_part], ray).direction : object_dir;
      if (out.count == tol::kMaxShadowSurfaces) return true;  // too many: treated as blocked
      uint32_t shown = i;
      if (inst.kind == kCsgKind) {
        shown = h.csg_part;  // an opaque part of a partly transmissive block blocks
        if (!instances_[shown].transmissive) return true;
      }
      out.t[out.count] = h.t;
      out.instance[out.count] = shown;
      ++out.count;
      // Step past the surface by the hit's own error bound, as offset_ray_origin moves a
      // spawned ray's origin: that distance along the normal, converted to ray parameter.
      Vec3 n = glm::normalize(h.normal);
      double n1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
      double offset = std::max(tol::kOffsetErrorScale * h.error * n1, tol::kMinRayOffset);
      double cos_dn = std::max(std::abs(glm::dot(n, dir)), tol::kParallelCosine);
      range.min = h.t + offset / cos_dn;
    }
    return false;
  };
  for (uint32_t i : planes_)
    if (visit(i)) return true;
  if (!use_bvh_) {
    for (uint32_t i = 0; i < bounded_count_; ++i)
      if (visit(i)) return true;
    return false;
  }
  return traverse_top_level<true>(ray, ray_t, [&](uint32_t i, Interval&) { return visit(i); });
}

std::size_t World::bvh_nodes() const {
  std::size_t n = bvh_.nodes.size() + quantized_.nodes.size();
  for (const Group& g : groups_) n += g.bvh.nodes.size();
  std::vector<const MeshAccel*> distinct;
  for (const auto& m : meshes_)
    if (m && std::find(distinct.begin(), distinct.end(), m.get()) == distinct.end()) {
      distinct.push_back(m.get());
      n += m->bvh_nodes();
    }
  return n;
}

std::size_t World::triangle_count() const {
  std::size_t n = 0;
  std::vector<const MeshAccel*> distinct;
  for (const auto& m : meshes_)
    if (m && std::find(distinct.begin(), distinct.end(), m.get()) == distinct.end()) {
      distinct.push_back(m.get());
      n += m->triangle_count();
    }
  return n;
}

WorldMemory World::memory() const {
  WorldMemory w;
  w.instances = instances_.capacity() * sizeof(Instance) + planes_.capacity() * sizeof(uint32_t);
  w.transforms = transforms_.capacity() * sizeof(InstanceTransform) + instance_linears_.capacity() * sizeof(InstanceLinear) +
                 group_offsets_.capacity() * sizeof(Vec3) + group_linear_of_.capacity() * sizeof(uint32_t) + group_linears_.capacity() * sizeof(GroupLinear);
  for (const Group& g : groups_) w.bvh += g.bvh.nodes.capacity() * sizeof(BVHNode) + g.bvh.order.capacity() * sizeof(uint32_t);
  std::apply([&](const auto&... array) { ((w.shapes += array.capacity() * sizeof(array[0])), ...); }, shapes_);
  w.shapes += quad_frames_.capacity() * sizeof(QuadFrame) + plane_frames_.capacity() * sizeof(PlaneFrame);
  for (const Csg& c : csgs_)
    w.shapes += c.tree.nodes.capacity() * sizeof(CsgNode) + c.tree.children.capacity() * sizeof(uint32_t) +
                c.leaf_instance.capacity() * sizeof(uint32_t) + c.leaf_bounds.capacity() * sizeof(AABB);
  w.bvh += bvh_.nodes.capacity() * sizeof(BVHNode) + bvh_.order.capacity() * sizeof(uint32_t) +
           quantized_.nodes.capacity() * sizeof(QuantizedNode);
  std::vector<const MeshAccel*> distinct;
  for (const auto& m : meshes_)
    if (m && std::find(distinct.begin(), distinct.end(), m.get()) == distinct.end()) {
      distinct.push_back(m.get());
      w.meshes += m->memory_bytes();
    }
  return w;
}

}  // namespace rts::render
