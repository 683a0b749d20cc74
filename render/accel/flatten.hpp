// Flattens the scene graph (groups of groups, shared nodes placed many times) into a list of
// shape instances and lights, each with its composed child → world transform.
#pragma once

#include <vector>

#include "render/scene/scene.hpp"

namespace rts::render {

struct FlatShape {
  uint32_t shape = 0;          // index into SceneDesc::shapes
  Mat4 to_world{1.0};
  SourceRef loc;               // where the instance was placed
};

// A CSG block placed in the world: traced as one object (its children are not flattened).
struct FlatCsg {
  uint32_t csg = 0;            // index into SceneDesc::csgs
  Mat4 to_world{1.0};
  SourceRef loc;               // the block
};

struct FlatScene {
  std::vector<FlatShape> shapes;
  std::vector<FlatCsg> csgs;
  std::vector<LightDesc> lights;  // already in world space
};

// Throws RenderError when a node index is out of range, groups nest deeper than
// tol::kMaxGroupDepth (a cycle), or an instance's composed transform is not finite or is
// singular ("transform is singular (scale 0?)", located at the instance's placement).
FlatScene flatten_scene(const SceneDesc& scene);
// The same for one instance alone (trace() in the language: render/accel/probe.hpp).
FlatScene flatten_instance(const SceneDesc& scene, const Child& instance);

// The light moved into world space by `m` (positions as points, directions as vectors).
LightDesc transform_light(const LightDesc& light, const Mat4& m);

}  // namespace rts::render
