// Walks the leaf shapes of a CSG block (through nested blocks and groups), each with the
// material it shows: its own, else the nearest enclosing block's.
#pragma once

#include "render/scene/scene.hpp"

namespace rts::render {

namespace detail {
template <class F>
void csg_leaves_of(const SceneDesc& scene, NodeId id, MaterialId inherited, F& f, int depth) {
  if (id >= scene.nodes.size() || depth > 1024) return;
  const Node& node = scene.nodes[id];
  if (node.kind == NodeKind::Group && node.index < scene.groups.size()) {
    const GroupDesc& g = scene.groups[node.index];
    MaterialId m = g.material != kNoId ? g.material : inherited;
    for (const Child& c : g.children) csg_leaves_of(scene, c.node, m, f, depth + 1);
    return;
  }
  if (node.kind == NodeKind::Csg && node.index < scene.csgs.size()) {
    const CsgDesc& d = scene.csgs[node.index];
    MaterialId m = d.material != kNoId ? d.material : inherited;
    for (const Child& c : d.children) csg_leaves_of(scene, c.node, m, f, depth + 1);
    return;
  }
  if (node.kind != NodeKind::Shape || node.index >= scene.shapes.size()) return;
  const ShapeDesc& shape = scene.shapes[node.index];
  f(shape, shape.material != kNoId ? shape.material : inherited);
}
}  // namespace detail

// f(const ShapeDesc& leaf, MaterialId shown) for each leaf of SceneDesc::csgs[csg];
// `inherited`: the material of the group the block is placed in (kNoId: none).
template <class F>
void for_each_csg_leaf(const SceneDesc& scene, uint32_t csg, F&& f, MaterialId inherited = kNoId) {
  if (csg >= scene.csgs.size()) return;
  const CsgDesc& d = scene.csgs[csg];
  MaterialId m = d.material != kNoId ? d.material : inherited;
  for (const Child& c : d.children) detail::csg_leaves_of(scene, c.node, m, f, 0);
}

}  // namespace rts::render
