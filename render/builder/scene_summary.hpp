// A summary of a scene for `rts check` (beside SceneDesc::dump, scene_dump.cpp, which `rts
// eval` prints): what it contains, how many instances,
// where it is (world-space bounds of everything bounded), camera and image settings.
#pragma once

#include <cstddef>
#include <map>
#include <ostream>
#include <string>

#include "render/scene/scene.hpp"

namespace rts::render {

// Up to this many placed instances (groups expanded), the summary visits each one.
inline constexpr std::size_t kExactWalkInstances = 1'000'000;

struct SceneSummary {
  std::map<std::string, std::size_t> shapes;  // kind → placed instances (world-space count)
  std::map<std::string, std::size_t> lights;  // kind → placed instances
  std::size_t shape_definitions = 0;          // ShapeDescs (one per block evaluated)
  std::size_t instances = 0;                  // placements of shapes, lights and groups
  std::size_t triangles = 0;                  // mesh triangles over all placed instances
  std::size_t materials = 0, textures = 0, meshes = 0, groups = 0;
  bool has_bounds = false;  // false when nothing bounded is placed
  Vec3 bounds_min{0.0}, bounds_max{0.0};
  bool unbounded = false;  // a plane is placed (not in the bounds)
  // The bounds enclose each placed group's box under its placement rather than each shape's
  // (scenes of more than kExactWalkInstances instances: exact bounds would walk them all).
  bool bounds_of_group_boxes = false;
};


// Scenes of more than `exact_walk_limit` placed instances are summarized from each group's
// totals (SceneSummary::bounds_of_group_boxes).
SceneSummary summarize(const SceneDesc& scene, std::size_t exact_walk_limit = kExactWalkInstances);

// The `rts check` report; `seconds` is the evaluation time.
void print_summary(std::ostream& out, const SceneDesc& scene, const SceneSummary& s, double seconds);

}  // namespace rts::render
