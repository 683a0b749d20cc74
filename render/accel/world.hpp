// The traceable world: every shape instance with its world transform, a top-level BVH over
// the bounded ones, unbounded planes kept aside, and one MeshAccel per referenced mesh.
// Ray-primitive tests dispatch on the instance kind (ShapeGeometry's index) into per-kind
// arrays, one per alternative of ShapeGeometry (render/geometry/shapes/shape_kinds.hpp).
#pragma once

#include <memory>
#include <optional>
#include <tuple>
#include <vector>

#include "render/accel/bit_interner.hpp"
#include "render/accel/bvh.hpp"
#include "render/accel/quantized_bvh.hpp"
#include "render/accel/flatten.hpp"
#include "render/accel/mesh_accel.hpp"
#include "render/geometry/csg/csg_tree.hpp"
#include "render/scene/scene.hpp"
#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/geometry/surface_hit.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

// A shape kind: the index of its alternative in ShapeGeometry.
using PrimKind = uint8_t;
template <class T>
inline constexpr PrimKind kPrimKind = static_cast<PrimKind>(shape_index<T>());
static_assert(kShapeKindCount < 255, "PrimKind is a byte, and 255 is a CSG block");
// A CSG block, traced as one instance (World::csgs_); the leaf whose surface a hit shows is
// an instance of its own kind after every other (World::csg_part_count), never in the BVH.
inline constexpr PrimKind kCsgKind = 255;
// A placement of an instanced group (World::groups_): its shapes are instances of their own
// kinds after the planes (World::group_part_count), reached through the group's BVH only.
inline constexpr PrimKind kGroupKind = 254;
static_assert(kShapeKindCount < 254, "PrimKind 254 is an instanced group");

// One array per ShapeGeometry alternative (meshes' stays empty: they are kept by MeshId).
template <class V>
struct ShapeArraysOf;
template <class... T>
struct ShapeArraysOf<std::variant<T...>> {
  using type = std::tuple<std::vector<T>...>;
};
using ShapeArrays = ShapeArraysOf<ShapeGeometry>::type;

// 16 bytes, so the instances a BVH leaf points at share cache lines; transforms live apart
// (only transformed instances have one).
struct Instance {
  PrimKind kind = 0;
  bool smooth = true;          // meshes: interpolate vertex normals
  bool transmissive = false;   // its material lets light through (shadow rays pass it)
  bool vertex_material = false;  // meshes: its vertices carry material values
  uint32_t index = 0;          // into the World's array for `kind` (meshes: the MeshId)
  MaterialId material = kNoId;
  uint32_t transform = kNoId;  // into World's transforms, or kNoId: trace the world ray as is
};

// A transformed instance's maps (object → world and back). Their 3×3 linear parts, with the
// normal matrix read off them, are kept once per distinct pair (InstanceLinear,
// World::instance_linears_): objects placed by `translate` all share the identity's, and a
// loop's rotations repeat. An instance holds the pair's index and its object → world
// translation: 32 bytes where the four matrices were 400 (issue 24: a million spheres placed by
// `translate` held 416 MB of transforms). A ray is carried into object space as
// to_object * (p - to_world_t) (World::object_ray), which needs no translation of its own and
// subtracts the offset before the rotation, so a ray near a far object keeps its digits; a
// translation alone gives the same values as adding the inverse's (its exact negation). Hits
// are carried back by apply_affine on the columns kept, and the 4×4 matrices, where one is
// wanted (transform()), are rebuilt from them (World::instance_to_world, instance_to_object).
struct InstanceLinear {
  glm::dmat3 to_world{1.0};         // the object → world linear part (tangents)
  glm::dmat3 to_object{1.0};        // the world → object linear part
  glm::dmat3 normal_to_world{1.0};  // inverse transpose of the object → world linear part
};
struct InstanceTransform {
  uint32_t linear = 0;              // into World::instance_linears_
  Vec3 to_world_t{0.0};             // the object → world map's translation column
};
// glm's 4×4 product with (v, w), its x, y, z, for an affine map held as its linear part `l`
// and translation `t`: the same operations in the same order ((c0 x + c1 y) + (c2 z + c3 w),
// glm's mat4 * vec4), so the same values, without building the 4×4 matrix per ray (profile
// finding, callgrind on bench/leave_out_a.rts: World::object_ray +18% instructions while it
// rebuilt the matrix).
inline Vec3 apply_affine(const glm::dmat3& l, const Vec3& t, const Vec3& v, double w) {
  return (l[0] * v.x + l[1] * v.y) + (l[2] * v.z + t * w);
}

// All of a transformed instance's maps at once, as World::transform rebuilds them (light
// sampling, which reads them once per emitter).
struct InstanceMaps {
  Mat4 to_world{1.0};               // object → world
  Mat4 to_object{1.0};              // world → object
  glm::dmat3 normal_to_world{1.0};  // inverse transpose of the object → world linear part
  glm::dmat3 vector_to_world{1.0};  // the object → world linear part (tangents)
};

// A placement's affine map (group space → parent space) and its inverse. Their 3×3 linear
// parts are kept once per distinct pair (GroupLinear, World::group_linears_): placements made
// by a loop mostly repeat a few rotations and scales and differ in translation, and the two
// 4×3 double matrices per placement were 192 of its ~244 bytes (issue 24). A placement holds
// the pair's index and its own object → world translation (GroupTransform, below).
struct GroupLinear {
  glm::dmat3 to_world{1.0};
  glm::dmat3 to_object{1.0};
};
// The object map's translation is not kept (24 of the 56 bytes): a ray is carried into the
// group's space as to_object * (origin - to_world_t), which needs none, and subtracts the
// placement's offset before the rotation, so a ray near a far placement loses no digits to it.
// Kept as two arrays (World::group_offsets_, group_linear_of_): 28 bytes a placement where the
// struct's padding made 32 (issue 24: with the quantized top level, 64 bytes a placement).
struct GroupTransform {
  uint32_t linear = 0;           // into World::group_linears_
  Vec3 to_world_t{0.0};          // the object → world map's translation column
};

// A hit in world space, plus what shading needs from object space.
struct WorldHit {
  double t = 0.0;
  uint32_t instance = 0;       // whose surface (material, uv): a CSG block's leaf part
  uint32_t medium = 0;         // whose inside the ray enters or leaves: a CSG block as a whole
  Vec3 point{0.0};             // world
  double error = 0.0;          // bound on the rounding error of `point`, per component
  Vec3 normal{0, 1, 0};        // world geometric normal, unit, outward
  Vec3 shading_normal{0, 1, 0};  // world, unit, outward
  Vec3 object_point{0.0};      // for textures
  glm::dvec2 uv{0.0};           // spheres: use World::surface_uv
  bool has_uv = false;
  Vec3 dpdu{0.0}, dpdv{0.0};    // world-space surface derivatives, zero when unknown
  uint32_t triangle = 0;        // meshes: which triangle, and its barycentrics (b1, b2)
  glm::dvec2 bary{0.0};
};

// A few bounded objects are tested one after another: a BVH over them is one leaf holding the
// same objects behind an extra box test per ray.
inline constexpr std::size_t kMaxObjectsWithoutBvh = kBvhMaxLeafSize;
// From this many bounded objects on (2^20), at least half of them placements of instanced
// groups, the top-level BVH is kept quantized (quantized_bvh.hpp): 20 bytes per object where
// the binary tree of float boxes takes 68 (issue 24: <= 64 bytes a placement), for a walk that
// decodes each box (+12% render at a million placements, 16 spp) and a build that holds both
// trees for a moment (+0.12 s per million placements). Plain shapes keep the binary tree: for
// them the walk cost 13% at 1M spheres under an area light and the moment with both trees put
// 4M spheres at 439 MB against 403, past that scene's 100 bytes a sphere; placements peak in
// evaluation, not in the build (docs/performance.md, "The quantized top level").
inline constexpr std::size_t kQuantizedTopLevelFrom = std::size_t{1} << 20;
// The binary tree a quantized top level is made from ends in leaves of up to this many.
inline constexpr uint32_t kQuantizedInputLeaves = 4;

// The transmissive surfaces a shadow ray crosses, in no particular order (see shadow_crossings).
struct ShadowCrossings {
  int count = 0;
  double t[tol::kMaxShadowSurfaces];
  uint32_t instance[tol::kMaxShadowSurfaces];
};

// The region every shadow segment from one shading point to an area light lies in: the
// pyramid with the point as apex over the light's rectangle, given as its box and the outward
// planes of its sides (World::occluder_candidates).
struct ShadowRegion {
  AABB box;
  int planes = 0;
  Vec3 normal[4];        // unit, outward
  double offset[4];      // a point x is outside a side when dot(normal, x) > offset
  Vec3 vertex[5];        // the apex (every ray's origin) and the light's corners
  double slack = 0.0;    // how far the segments may stray from the pyramid (rounding)
};

// The pyramid from `apex` over the rectangle centre ± u/2 ± v/2, padded for rounding: every
// segment from the apex to a point of the rectangle lies in it.
ShadowRegion shadow_pyramid(const Vec3& apex, const Vec3& centre, const Vec3& u, const Vec3& v);

// The BVH leaves (or, without a BVH, the bounded instances) that may block a shadow segment
// inside a ShadowRegion: the shading point's shadow rays towards an area light test these few
// objects instead of walking the BVH once per light sample.
struct OccluderCandidates {
  static constexpr int kMax = 8;  // leaves of the binary tree, objects without a BVH, planes
  // Instances from a quantized top level: its leaves hold one object where the binary tree's
  // hold up to 4, so as many objects as 8 leaves hold is more than 8 leaves.
  static constexpr int kMaxInstances = 16;
  int count = 0;
  uint32_t leaf[kMaxInstances];  // BVH node indices (leaves); instances without a BVH or with a quantized one
  int plane_count = 0;
  uint32_t plane[kMax];  // the unbounded planes that cross the region (instance indices)
};

// Bytes held by each part of the world, for --stats.
struct WorldMemory {
  std::size_t instances = 0, transforms = 0, shapes = 0, bvh = 0, meshes = 0;
};

// How a World is built: whole, or its instances first and the top-level BVH when asked
// (World::build_bvh), so that the caller can release the scene description in between and the
// build's peak does not hold it (PreparedScene does, for a scene it owns).
enum class WorldBuild : uint8_t { Whole, BvhLater };

class World {
 public:
  // `specialize`: a scene of at most kMaxObjectsWithoutBvh bounded objects gets no BVH. Once
  // built, the World reads neither `scene` nor `flat` (it holds copies of what it traces).
  // `taken`: the same scene, given up by its owner: its shapes are freed while the instances
  // are made (shape_release.hpp), so that only groups, CSG blocks and what they read stay.
  World(const SceneDesc& scene, const FlatScene& flat, bool specialize = true, WorldBuild build = WorldBuild::Whole,
        SceneDesc* taken = nullptr);
  // Builds the top-level BVH over the instances (WorldBuild::BvhLater); once, before tracing.
  void build_bvh();
  // Before build_bvh (WorldBuild::BvhLater): quantize the top level from `count` bounded
  // objects on, of any kind, instead of kQuantizedTopLevelFrom placements (tests compare the
  // two trees' answers).
  void set_quantized_top_level_from(std::size_t count) {
    quantized_from_ = count;
    quantize_any_kind_ = true;
  }
  bool quantized_top_level() const { return !quantized_.empty(); }

  // Closest hit; with `transmissive_only`, opaque instances are ignored; with `shadow_ray`,
  // so are the objects that cast no shadow (casts_shadow = false).
  bool intersect(const Ray& ray, Interval ray_t, WorldHit& hit, bool transmissive_only = false,
                 bool shadow_ray = false) const;
  // Any hit (early exit) of a shadow ray: objects that cast no shadow are ignored; with
  // `opaque_only`, transmissive instances are too.
  bool occluded(const Ray& ray, Interval ray_t, bool opaque_only = false) const;
  bool has_transmissive() const { return has_transmissive_; }
  // Whether any object casts no shadow (shadow rays then test each instance's flag).
  bool has_shadowless() const { return !shadowless_.empty(); }
  // One any-hit traversal of [ray_t]: true (blocked) at the first opaque hit, or when the ray
  // crosses tol::kMaxShadowSurfaces transmissive surfaces or more; otherwise every crossing of
  // a transmissive surface is in `out` (each instance is re-tested only along its own
  // crossings, instead of re-walking the whole scene with closest-hit steps).
  bool shadow_crossings(const Ray& ray, Interval ray_t, ShadowCrossings& out) const;
  // The leaves whose boxes meet `region` (its box, and no side plane leaves them outside),
  // into `out`; false (and `out` unusable) when there are more than OccluderCandidates::kMax,
  // the region is not a box (NaN), or some object casts no shadow.
  bool occluder_candidates(const ShadowRegion& region, OccluderCandidates& out) const;
  // occluded(ray, ray_t) for a segment inside the region `candidates` were found for: the same
  // answer, testing only the candidates' planes and leaves (box first, as traversal does).
  bool occluded_by(const OccluderCandidates& candidates, const Ray& ray, Interval ray_t) const;
  bool uses_bvh() const { return use_bvh_; }
  std::size_t bvh_nodes() const;         // top level plus each distinct mesh BVH
  std::size_t triangle_count() const;    // in each distinct mesh
  WorldMemory memory() const;
  // The hit's texture coordinates (spheres' are computed here, on demand).
  glm::dvec2 surface_uv(const WorldHit& hit) const;
  // The hit's per-vertex material values; false when its shape has none.
  bool has_vertex_material(const WorldHit& hit) const { return instances_[hit.instance].vertex_material; }
  bool vertex_material(const WorldHit& hit, VertexMaterial& out) const;

  const Instance& instance(uint32_t i) const { return instances_[i]; }
  // Instance i's maps (nothing: the identity), and the shapes by their Instance::index, for
  // samplers of emissive shapes (render/shade/path/light_set.*).
  std::optional<InstanceMaps> transform(uint32_t i) const {
    if (instances_[i].transform == kNoId) return std::nullopt;
    const InstanceTransform& xf = transforms_[instances_[i].transform];
    const InstanceLinear& l = instance_linears_[xf.linear];
    return InstanceMaps{instance_to_world(xf), instance_to_object(xf), l.normal_to_world, l.to_world};
  }
  static Mat4 affine(const glm::dmat3& l, const Vec3& t) {
    return Mat4(glm::dvec4(l[0], 0.0), glm::dvec4(l[1], 0.0), glm::dvec4(l[2], 0.0), glm::dvec4(t, 1.0));
  }
  Mat4 instance_to_world(const InstanceTransform& xf) const {
    return affine(instance_linears_[xf.linear].to_world, xf.to_world_t);
  }
  Mat4 instance_to_object(const InstanceTransform& xf) const {
    const glm::dmat3& to_object = instance_linears_[xf.linear].to_object;
    return affine(to_object, -(to_object * xf.to_world_t));
  }
  template <class T>
  const T& shape(uint32_t index) const { return std::get<std::vector<T>>(shapes_)[index]; }
  std::size_t instance_count() const { return instances_.size(); }
  std::size_t plane_count() const { return planes_.size(); }
  std::size_t csg_part_count() const { return csg_parts_; }  // the last instances
  // Shapes inside instanced groups: instances after the planes, before the CSG parts.
  std::size_t group_part_count() const { return group_parts_; }
  std::size_t group_count() const { return groups_.size(); }  // distinct instanced groups built
  std::size_t group_linear_count() const { return group_linears_.size(); }  // distinct placement rotations/scales
  std::size_t instance_linear_count() const { return instance_linears_.size(); }  // distinct shape rotations/scales
  std::size_t mesh_bvh_count() const;  // distinct mesh BVHs built
  const BVH& top_level() const { return bvh_; }
  // CSG rays compute only the leaves whose state can matter inside the ray's interval
  // (render/geometry/csg/csg_prune.hpp); off, every leaf the line meets (for tests).
  void set_csg_pruning(bool on) { csg_pruning_ = on; }

 private:
  // A bounded instance's world box (the top-level BVH's input).
  AABB world_bounds(const Instance& inst) const;
  bool quantized_candidates(const ShadowRegion& region, OccluderCandidates& out) const;
  // traverse_bvh over the top level, whichever form it has: `visit(instance, t_range)`.
  template <bool any_hit, class Visit>
  bool traverse_top_level(const Ray& ray, Interval& ray_t, Visit&& visit) const;
  template <std::size_t... I>
  AABB object_bounds(const Instance& inst, std::index_sequence<I...>) const {
    AABB b;
    (void)((inst.kind == I && (b = kind_bounds<std::variant_alternative_t<I, ShapeGeometry>>(inst), true)) || ...);
    return b;
  }
  template <class T>
  AABB kind_bounds(const Instance& inst) const {
    if constexpr (std::is_same_v<T, MeshRef>) return meshes_[inst.index]->bounds();
    else if constexpr (ShapeTraits<T>::kInfo.bounded) return bounds(shape<T>(inst.index));
    else return AABB{};  // unbounded kinds are never in the BVH
  }
  Ray object_ray(const Instance& inst, const Ray& world_ray) const;
  // The traversals behind intersect, occluded and shadow_crossings; Filter::kSkipShadowless:
  // the instances flagged in shadowless_ are not tested (only scenes that have some pay).
  template <class Filter>
  bool closest(const Ray& ray, Interval ray_t, bool transmissive_only, SurfaceHit& best,
               uint32_t& best_instance) const;
  // closest() skipping shadowless instances, for shadow rays in scenes that have some.
  bool closest_casting_shadows(const Ray& ray, Interval ray_t, bool transmissive_only, SurfaceHit& best,
                               uint32_t& best_instance) const;
  bool occluded_casting_shadows(const Ray& ray, Interval ray_t, bool opaque_only) const;
  bool shadow_crossings_casting_shadows(const Ray& ray, Interval ray_t, ShadowCrossings& out) const;
  template <class Filter>
  bool occluded_impl(const Ray& ray, Interval ray_t, bool opaque_only) const;
  template <class Filter>
  bool shadow_crossings_impl(const Ray& ray, Interval ray_t, ShadowCrossings& out) const;
  bool intersect_instance(const Instance& inst, const Ray& world_ray, const Interval& ray_t,
                          SurfaceHit& hit) const;
  bool occluded_instance(const Instance& inst, const Ray& world_ray, const Interval& ray_t) const;
  template <std::size_t... I>
  bool intersect_kind(std::index_sequence<I...>, const Instance& inst, const Ray& ray, const Interval& ray_t,
                      SurfaceHit& hit) const;
  std::shared_ptr<const MeshAccel> mesh_accel(const SceneDesc& scene, MeshId id);
  // Puts a shape's geometry in its kind's array; `unbounded` for planes.
  void add_geometry(const SceneDesc& scene, const ShapeDesc& shape, Instance& inst, AABB& object_bounds,
                    bool& unbounded);
  uint32_t add_transform(const Mat4& to_world);
  // Flattens a CSG block into a tree whose leaves are instances in `parts`.
  void reserve_shape_arrays(const SceneDesc& scene, const FlatScene& flat);
  void add_csg(const SceneDesc& scene, const FlatCsg& block, std::vector<Instance>& parts, Instance& inst,
               AABB& world_bounds);
  bool intersect_csg(const Instance& inst, const Ray& world_ray, const Interval& ray_t, SurfaceHit& hit) const;
  // Whether a CSG block has a surface inside ray_t (a shadow ray: no hit point or normal).
  bool occluded_csg(const Instance& inst, const Ray& world_ray, const Interval& ray_t) const;
  // Both: the first surface inside ray_t, and its hit when `hit` is not null (world_csg.cpp).
  bool trace_csg(const Instance& inst, const Ray& world_ray, const Interval& ray_t, SurfaceHit* hit) const;
  // One shape placement (top level or inside a group): its instance and bounds in the
  // placement's parent space; false when it can never be hit (singular, empty, not finite).
  // `material`: what it shows (its own, else its group's: FlatScene::material).
  bool add_shape_instance(const SceneDesc& scene, uint32_t shape_index, const Mat4& to_world, Instance& inst,
                          AABB& bounds, bool& unbounded, MaterialId material);
  // Instanced groups (world_groups.cpp): builds group `group`'s contents once (its parts go
  // to `parts`), returning its index in groups_; `built` maps group index → groups_ index.
  uint32_t group_accel(const SceneDesc& scene, const std::vector<bool>& instanced, uint32_t group, int level,
                       bool specialize, std::vector<Instance>& parts, std::vector<uint32_t>& built);
  // A placement of group `gi` by `to_world`: its instance and world box; false when it can
  // never be hit.
  bool add_group_instance(uint32_t gi, const Mat4& to_world, Instance& inst, AABB& bounds);
  Ray group_ray(const Instance& inst, const Ray& parent_ray) const;
  bool intersect_group(const Instance& inst, const Ray& parent_ray, const Interval& ray_t, SurfaceHit& hit) const;
  bool occluded_group(const Instance& inst, const Ray& parent_ray, const Interval& ray_t) const;

  // A CSG block: its tree and the instance of each leaf (parts after every other instance).
  struct Csg {
    CsgTree tree;
    std::vector<uint32_t> leaf_instance;
    std::vector<AABB> leaf_bounds;   // world space, to skip the leaves a ray misses
    bool has_windowed = false;       // a leaf whose crossings a sweep lists from its start (World::trace_csg)
  };

  ShapeArrays shapes_;
  // Beside shapes_' quads and planes, index for index: what their tests derive from them.
  std::vector<QuadFrame> quad_frames_;
  std::vector<PlaneFrame> plane_frames_;
  std::vector<Csg> csgs_;
  // An instanced group's contents: parts instances_[first, first + count), in the group's
  // space, under one BVH shared by every placement.
  struct Group {
    BVH bvh;
    uint32_t first = 0, count = 0;
    bool use_bvh = true;
    AABB bounds;
  };
  std::vector<Group> groups_;
  // Placement i's GroupTransform: its translation and its linear pair's index.
  std::vector<Vec3> group_offsets_;
  std::vector<uint32_t> group_linear_of_;
  GroupTransform group_transform(uint32_t i) const { return GroupTransform{group_linear_of_[i], group_offsets_[i]}; }
  std::vector<GroupLinear> group_linears_;
  // While building: each distinct linear pair's index in group_linears_, by its 18 doubles' bits.
  BitInterner<GroupLinear> group_linear_index_;
  glm::dmat4x3 group_to_world(const GroupTransform& xf) const {
    const glm::dmat3& l = group_linears_[xf.linear].to_world;
    return glm::dmat4x3(l[0], l[1], l[2], xf.to_world_t);
  }
  const glm::dmat3& group_object_linear(const GroupTransform& xf) const { return group_linears_[xf.linear].to_object; }
  std::size_t group_parts_ = 0;
  // By MeshId; null when unreferenced. MeshIds whose data are identical (the same OBJ file
  // loaded by several statements) share one MeshAccel, so one BVH.
  std::vector<std::shared_ptr<const MeshAccel>> meshes_;

  std::vector<Instance> instances_;  // bounded instances first (BVH), then planes
  std::vector<InstanceTransform> transforms_;
  std::vector<InstanceLinear> instance_linears_;
  // While building: each distinct linear pair's index in instance_linears_, by its doubles' bits.
  BitInterner<InstanceLinear> instance_linear_index_;
  std::vector<uint32_t> planes_;     // instance indices of unbounded planes
  BVH bvh_;                          // empty once quantized_ is made from it
  QuantizedBVH quantized_;
  std::size_t quantized_from_ = kQuantizedTopLevelFrom;
  bool quantize_any_kind_ = false;
  bool bvh_built_ = false;
  std::size_t bounded_count_ = 0;    // instances_[0, bounded_count_) are bounded
  bool use_bvh_ = true;
  bool has_transmissive_ = false;
  // By instance, once some top-level instance casts no shadow: 1 for those; empty otherwise.
  std::vector<uint8_t> shadowless_;
  std::size_t csg_parts_ = 0;
  bool csg_pruning_ = true;
};

}  // namespace rts::render
