#include "render/accel/flatten.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/geometry/transform_inverse.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {
namespace {

Vec3 transform_point(const Mat4& m, const Vec3& p) { return Vec3(m * glm::dvec4(p, 1.0)); }
Vec3 transform_vector(const Mat4& m, const Vec3& v) { return Vec3(m * glm::dvec4(v, 0.0)); }

// A composed child → world transform must be finite and invertible: instances are traced in
// object space through its inverse, and a singular one (a scale of 0, or tiny scales whose
// product underflows) would give NaN rays and normals, or silently lose the object.
void check_transform(const Mat4& m, const SourceRef& loc) {
  if (m == Mat4(1.0)) return;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r]))
        throw RenderError(loc, "transform is not finite (a scale or translation too large?)");
  if (!invertible_transform(m)) throw RenderError(loc, "transform is singular (scale 0?)");
}

// `instanced`: by group index, the groups placed as FlatGroups instead of copied (may be
// shorter than the group list: then nothing is instanced). `inherited`: the nearest enclosing
// group's material (kNoId: none); a group reached with one is copied, never instanced, since
// its shapes show that material here and maybe another elsewhere. `casts`: false inside a
// group with casts_shadow = false.
void flatten_child(const SceneDesc& scene, const Child& child, const Mat4& parent, int depth,
                   const std::vector<bool>& instanced, MaterialId inherited, bool casts, FlatScene& out) {
  if (depth > tol::kMaxGroupDepth)
    throw RenderError(child.loc, "groups nested more than " + std::to_string(tol::kMaxGroupDepth) +
                                     " deep (a group containing itself?)");
  if (child.node >= scene.nodes.size())
    throw RenderError(child.loc, "internal: instance of unknown node " + std::to_string(child.node));
  const Node& node = scene.nodes[child.node];
  Mat4 m = parent * child.transform;
  switch (node.kind) {
    case NodeKind::Shape:
      if (node.index >= scene.shapes.size()) throw RenderError(child.loc, "internal: unknown shape");
      check_transform(m, child.loc);
      out.add_shape(node.index, m, inherited, casts && scene.shapes[node.index].casts_shadow);
      break;
    case NodeKind::Light:
      if (node.index >= scene.lights.size()) throw RenderError(child.loc, "internal: unknown light");
      check_transform(m, child.loc);
      out.lights.push_back(transform_light(scene.lights[node.index], m));
      break;
    case NodeKind::Csg:
      if (node.index >= scene.csgs.size()) throw RenderError(child.loc, "internal: unknown CSG block");
      check_transform(m, child.loc);
      out.csgs.push_back(FlatCsg{node.index, m, scene.csgs[node.index].loc, inherited, casts && scene.csgs[node.index].casts_shadow});
      break;
    case NodeKind::Group: {
      if (node.index >= scene.groups.size()) throw RenderError(child.loc, "internal: unknown group");
      if (inherited == kNoId && node.index < instanced.size() && instanced[node.index]) {
        check_transform(m, child.loc);
        out.add_group(node.index, m, casts && scene.groups[node.index].casts_shadow);
        break;
      }
      const GroupDesc& g = scene.groups[node.index];
      MaterialId mat = g.material != kNoId ? g.material : inherited;
      for (const Child& c : g.children)
        flatten_child(scene, c, m, depth + 1, instanced, mat, casts && g.casts_shadow, out);
      break;
    }
  }
}

}  // namespace

LightDesc transform_light(const LightDesc& light, const Mat4& m) {
  LightDesc l = light;
  l.position = transform_point(m, light.position);
  l.point_at = transform_point(m, light.point_at);
  l.direction = transform_vector(m, light.direction);
  l.u = transform_vector(m, light.u);
  l.v = transform_vector(m, light.v);
  return l;
}

FlatScene flatten_instance(const SceneDesc& scene, const Child& instance) {
  FlatScene out;
  flatten_child(scene, instance, Mat4(1.0), 0, {}, kNoId, true, out);
  out.built();
  return out;
}

FlatScene flatten_scene(const SceneDesc& scene) {
  FlatScene out;
  out.instanced = instanced_groups(scene);
  // Room for a placement per shape described, the usual count (a loop's shapes are each placed
  // once); capacity never written is never resident. Grown by doubling, the last copy held the
  // array one and a half times at the build's peak (4M spheres: 50 MB, RSS trace).
  out.shapes.reserve(scene.shapes.size());
  // The same for the world's own placements of instanced groups and transformed children (1M
  // placements of a group: the placements and their transforms, 44 MB, grew by doubling at the
  // peak of the build, RSS trace of bench/instancing/copies.rts -D m=8 -D c=1000).
  std::size_t transformed = 0, groups = 0;
  for (const Child& root : scene.roots) {
    transformed += root.transform.same_block(ChildTransform{}) ? 0 : 1;
    if (!out.instanced.empty() && root.node < scene.nodes.size()) {
      const Node node = scene.nodes[root.node];
      groups += node.kind == NodeKind::Group && node.index < out.instanced.size() && out.instanced[node.index];
    }
  }
  out.transforms.reserve(transformed);
  out.groups.reserve(groups);
  for (const Child& root : scene.roots) flatten_child(scene, root, Mat4(1.0), 0, out.instanced, kNoId, true, out);
  out.built();
  return out;
}

FlatScene flatten_group(const SceneDesc& scene, const std::vector<bool>& instanced, uint32_t group, int level) {
  FlatScene out;
  static const std::vector<bool> none;
  const std::vector<bool>& nested = level + 1 < kMaxInstanceLevels ? instanced : none;
  for (const Child& c : scene.groups[group].children) flatten_child(scene, c, Mat4(1.0), level + 1, nested, kNoId, true, out);
  out.built();
  return out;
}

std::vector<bool> instanced_groups(const SceneDesc& scene) {
  const std::size_t n = scene.groups.size();
  if (n == 0) return {};
  // Placements of each group: Child entries naming it (the world's and groups'; a group inside
  // a CSG block is part of that block's tree).
  std::vector<uint32_t> placed(n, 0);
  auto count = [&](const auto& children) {
    for (const Child& c : children)
      if (c.node < scene.nodes.size() && scene.nodes[c.node].kind == NodeKind::Group &&
          scene.nodes[c.node].index < n && placed[scene.nodes[c.node].index] < 2)
        ++placed[scene.nodes[c.node].index];
  };
  count(scene.roots);
  for (const GroupDesc& g : scene.groups) count(g.children);
  bool any = false;
  for (uint32_t p : placed) any = any || p >= 2;
  if (!any) return {};

  auto material_ok = [&](MaterialId id) {
    if (id >= scene.materials.size()) return true;  // the default material: opaque, dark
    auto black = [](const Color& c) { return !(c.r > 0.0 || c.g > 0.0 || c.b > 0.0); };
    bool ok = true;
    for_each_material_choice(scene.materials, id, [&](MaterialId, const MaterialDesc& m) {
      ok = ok && black(m.transmit) && black(m.emission) && m.transmit_texture == kNoId && m.emission_texture == kNoId;
    });
    return ok;
  };
  // Whether each group may be instanced, and how many shapes it holds (saturating): computed
  // once per group over the graph (a DAG; a cycle makes its groups ineligible, and flattening
  // then reports it).
  enum : uint8_t { Unknown, Visiting, Done };
  std::vector<uint8_t> state(n, Unknown);
  std::vector<bool> eligible(n, false);
  std::vector<uint64_t> shapes(n, 0);
  constexpr uint64_t kSaturated = uint64_t(1) << 40;
  auto visit = [&](auto& self, uint32_t g, int depth) -> void {
    state[g] = Visiting;
    // A group with a material gives it to members without one: copied where it is placed.
    bool ok = depth <= tol::kMaxGroupDepth && scene.groups[g].material == kNoId;
    uint64_t count_here = 0;
    for (const Child& c : scene.groups[g].children) {
      if (!ok) break;
      if (c.node >= scene.nodes.size()) { ok = false; break; }
      const Node& node = scene.nodes[c.node];
      if (node.kind == NodeKind::Shape) {
        if (node.index >= scene.shapes.size()) { ok = false; break; }
        const ShapeDesc& s = scene.shapes[node.index];
        // A shape that casts no shadow is told apart by its instance at the top level only.
        ok = kShapeInfos[s.geometry.index()].bounded && material_ok(s.material) && s.casts_shadow;
        ++count_here;
      } else if (node.kind == NodeKind::Group && node.index < n) {
        if (state[node.index] == Unknown) self(self, node.index, depth + 1);
        ok = state[node.index] == Done && eligible[node.index] && scene.groups[node.index].casts_shadow;
        count_here += shapes[node.index];
      } else {
        ok = false;  // lights, CSG blocks
      }
      count_here = std::min(count_here, kSaturated);
    }
    eligible[g] = ok;
    shapes[g] = count_here;
    state[g] = Done;
  };
  std::vector<bool> out(n, false);
  for (uint32_t g = 0; g < n; ++g) {
    if (placed[g] < 2) continue;
    if (state[g] == Unknown) visit(visit, g, 0);
    out[g] = eligible[g] && shapes[g] >= kMinInstancedGroupShapes;
  }
  return out;
}

void for_each_group_shape(const SceneDesc& scene, uint32_t group, const std::function<void(const ShapeDesc&)>& f) {
  std::vector<bool> seen(scene.groups.size(), false);
  auto walk = [&](auto& self, uint32_t g, int depth) -> void {
    if (g >= scene.groups.size() || seen[g] || depth > tol::kMaxGroupDepth) return;
    seen[g] = true;
    for (const Child& c : scene.groups[g].children) {
      if (c.node >= scene.nodes.size()) continue;
      const Node& node = scene.nodes[c.node];
      if (node.kind == NodeKind::Shape && node.index < scene.shapes.size()) f(scene.shapes[node.index]);
      else if (node.kind == NodeKind::Group) self(self, node.index, depth + 1);
    }
  };
  walk(walk, group, 0);
}

}  // namespace rts::render
