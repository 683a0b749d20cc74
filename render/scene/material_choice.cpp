// Scene-wide questions about materials chosen by pattern, kept out of line: world.cpp's
// traversal code is inlined by size, and a loop over choices written into it cost the
// leave-out scene 0.5% of its instructions (GCC stopped inlining a glm::normalize into
// World::intersect_kind; callgrind on bench/leave_out_a.rts).
#include "render/scene/scene.hpp"

namespace rts::render {

bool may_transmit(const std::vector<MaterialDesc>& materials, MaterialId id) {
  bool any = false;
  for_each_material_choice(materials, id, [&](MaterialId, const MaterialDesc& m) {
    any = any || m.transmit.r > 0.0 || m.transmit.g > 0.0 || m.transmit.b > 0.0;
  });
  return any;
}

}  // namespace rts::render
