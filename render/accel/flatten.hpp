// Flattens the scene graph (groups of groups, shared nodes placed many times) into a list of
// shape instances and lights, each with its composed child → world transform. A group placed
// several times (instanced_groups) is not copied: each placement becomes one FlatGroup, and
// World builds the group's contents once, in the group's own space (two-level instancing).
#pragma once

#include <functional>
#include <vector>

#include "render/accel/bit_interner.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// 8 bytes: most placements carry no transform of their own (spheres placed by their centre),
// and the composed transforms that exist are kept in FlatScene::transforms. Finding (issue 24,
// 4M spheres): with a 128-byte matrix and a location each, the flat copy was 152 bytes per
// sphere at the peak of the build.
struct FlatShape {
  uint32_t shape = 0;          // index into SceneDesc::shapes
  uint32_t transform = kNoId;  // into FlatScene::transforms; kNoId: the identity
};

// A CSG block placed in the world: traced as one object (its children are not flattened).
struct FlatCsg {
  uint32_t csg = 0;            // index into SceneDesc::csgs
  Mat4 to_world{1.0};
  SourceRef loc;               // the block
  MaterialId inherited = kNoId;  // the enclosing group's material (for parts with none)
  bool casts_shadow = true;      // false: the block or a group around it has casts_shadow = false
};

// One placement of an instanced group: World traces it as one object whose contents (the
// group's own BVH, built once) are shared by every placement. 12 bytes: its transform is kept
// as a shape's is (FlatScene::transforms). Finding (issue 24, 1M placements of a group by two
// loops): with its 128-byte matrix and a location nothing read, the flat copy was 160 bytes a
// placement, grown by doubling, at the build's peak.
struct FlatGroup {
  uint32_t group = 0;          // index into SceneDesc::groups
  uint32_t transform = kNoId;  // into FlatScene::transforms; kNoId: the identity
  bool casts_shadow = true;    // false: the group or one around it has casts_shadow = false
};

// A shape's child → world transform: its matrix with the translation's x, y, z taken out,
// kept once per distinct bit pattern (FlatScene::linears: shapes placed by `translate` share
// the identity's), and the translation. 32 bytes where the matrix was 128, alive through the
// world's build; FlatScene::to_world puts the translation back, the matrix exactly as it was.
struct FlatTransform {
  uint32_t linear = 0;
  Vec3 translation{0.0};
};

struct FlatScene {
  std::vector<FlatShape> shapes;
  std::vector<FlatTransform> transforms;  // the shapes' and groups' transforms other than the identity
  std::vector<Mat4> linears;              // their matrices without translation, each once
  std::vector<FlatCsg> csgs;
  std::vector<LightDesc> lights;  // already in world space
  std::vector<FlatGroup> groups;  // placements of instanced groups (their shapes are not in `shapes`)
  // By group index: traced as a shared instance (instanced_groups), empty when none is.
  std::vector<bool> instanced;

  // By shape, once any shape has one: the material of the nearest enclosing group with a
  // material (`group { ... material = m }`), which a shape without its own shows; empty in
  // scenes without group materials, which pay nothing for them.
  std::vector<MaterialId> inherited;
  // By shape, once any shape casts no shadow (its own casts_shadow, or an enclosing group's):
  // 1 for those; empty in scenes where every shape casts one.
  std::vector<uint8_t> shadowless;

  void add_shape(uint32_t shape, const Mat4& to_world, MaterialId inherited_material = kNoId,
                 bool casts_shadow = true) {
    FlatShape fs{shape, add_transform(to_world)};
    if (inherited_material != kNoId || !inherited.empty()) {
      inherited.resize(shapes.size(), kNoId);
      inherited.push_back(inherited_material);
    }
    if (!casts_shadow || !shadowless.empty()) {
      shadowless.resize(shapes.size(), 0);
      shadowless.push_back(casts_shadow ? 0 : 1);
    }
    shapes.push_back(fs);
  }
  void add_group(uint32_t group, const Mat4& to_world, bool casts_shadow) {
    groups.push_back(FlatGroup{group, add_transform(to_world), casts_shadow});
  }
  // What shapes[i] shows: its own material, else its group's (kNoId: the default).
  MaterialId material(const SceneDesc& scene, std::size_t i) const {
    const MaterialId own = scene.shapes[shapes[i].shape].material;
    return own != kNoId || i >= inherited.size() ? own : inherited[i];
  }
  bool casts_shadow(std::size_t i) const { return i >= shadowless.size() || shadowless[i] == 0; }
  Mat4 to_world(const FlatShape& fs) const { return to_world(fs.transform); }
  Mat4 to_world(const FlatGroup& fg) const { return to_world(fg.transform); }
  // transforms[transform] as the matrix it was made from, exactly (the identity for kNoId).
  Mat4 to_world(uint32_t transform) const {
    if (transform == kNoId) return Mat4(1.0);
    const FlatTransform& t = transforms[transform];
    Mat4 m = linears[t.linear];
    m[3].x = t.translation.x;
    m[3].y = t.translation.y;
    m[3].z = t.translation.z;
    return m;
  }
  // Frees what only building needs (the index of distinct linear parts).
  void built() { linear_lookup.release(); }
  // Frees everything but the lights, once the world holds the placements (PreparedScene of a
  // scene it took: the shapes' placements are 16 bytes and more each).
  void keep_lights_only() {
    std::vector<LightDesc> kept = std::move(lights);
    *this = FlatScene{};
    lights = std::move(kept);
  }

 private:
  // Where to_world is kept (kNoId: the identity, which costs nothing).
  uint32_t add_transform(const Mat4& to_world) {
    if (to_world == Mat4(1.0)) return kNoId;
    transforms.push_back(FlatTransform{linear_index(to_world), Vec3(to_world[3])});
    return static_cast<uint32_t>(transforms.size() - 1);
  }
  uint32_t linear_index(const Mat4& to_world) {
    Mat4 linear = to_world;
    linear[3].x = linear[3].y = linear[3].z = 0.0;
    return linear_lookup.intern(linear, linears);
  }
  BitInterner<Mat4> linear_lookup;
};

// A group is instanced when it is placed at least twice (two Child entries name it), holds at
// least kMinInstancedGroupShapes shapes, and holds nothing that needs world-space identity:
// only bounded shapes (and groups of them) whose materials neither transmit nor emit (media
// are paired by instance, emitters are sampled by instance), no lights, no CSG, nothing inside
// that casts no shadow (shadow rays skip top-level instances only). Below the
// shape count, copying the shapes into the top-level BVH is cheaper to trace than an extra
// ray transform per group, and costs little memory. Instances nest kMaxInstanceLevels deep at
// most (each level is a recursion of the traversal); deeper instanced groups are copied
// into the level above.
inline constexpr std::size_t kMinInstancedGroupShapes = 64;
inline constexpr int kMaxInstanceLevels = 4;
std::vector<bool> instanced_groups(const SceneDesc& scene);
// The contents of group `group` in its own space: its shapes (nested groups flattened), and
// the placements of the instanced groups it holds when `level` + 1 < kMaxInstanceLevels.
FlatScene flatten_group(const SceneDesc& scene, const std::vector<bool>& instanced, uint32_t group, int level);
// Calls f(shape) for each shape placement in the group (nested groups included, instanced or
// not), each distinct nested group once. Used for the features and textures a scene needs.
void for_each_group_shape(const SceneDesc& scene, uint32_t group, const std::function<void(const ShapeDesc&)>& f);

// Throws RenderError when a node index is out of range, groups nest deeper than
// tol::kMaxGroupDepth (a cycle), or an instance's composed transform is not finite or is
// singular ("transform is singular (scale 0?)", located at the instance's placement).
FlatScene flatten_scene(const SceneDesc& scene);
// The same for one instance alone (trace() in the language: render/accel/probe.hpp).
FlatScene flatten_instance(const SceneDesc& scene, const Child& instance);

// The light moved into world space by `m` (positions as points, directions as vectors).
LightDesc transform_light(const LightDesc& light, const Mat4& m);

}  // namespace rts::render
