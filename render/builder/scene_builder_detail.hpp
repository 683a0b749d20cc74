// What scene_builder.cpp, material_builder.cpp and scene_nodes.cpp (the parts of SceneBuilder)
// share: the property names each block kind accepts, paths resolved against the naming file,
// the typed reading of a reference property and of a two-word choice.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "render/builder/block_properties.hpp"
#include "render/scene/params.hpp"

namespace rts::render::builder_detail {

// The property names a block kind accepts (for unknown-name checks and suggestions), from the
// tables in block_properties.cpp.
inline std::vector<std::string_view> names_of_block(std::string_view kind) {
  return property_names(find_block_info(kind)->properties);
}
// The property names `kind` accepts (a shape, light, group or CSG block), or null
// (scene_nodes.cpp).
const std::vector<std::string_view>* names_of(std::string_view kind);
// Adds a node for scene.shapes/groups/...[index] (scene_nodes.cpp).
NodeId add_node(SceneDesc& scene, NodeKind kind, std::size_t index, SourceRef loc);
// Paths in a scene are relative to the file that names them.
std::string resolve_path(const std::string& path, SourceRef where);
// A string property that is one of two words: whether it is the second. Any other word is
// "unknown NAME 'x' (expected FIRST or SECOND)", located at the property (scene_builder.cpp).
bool second_word(ParamSet& ps, std::string_view name, std::string_view first, std::string_view second);

// The reference in property `name` (a shape's material, a material's texture), or null when
// it is absent: "property 'material' of sphere expects a material, got a number".
template <typename Ref>
const Ref* reference(ParamSet& ps, std::string_view name, std::string_view block, std::string_view what) {
  const ParamValue* v = ps.value(name);
  if (!v) return nullptr;
  auto* ref = std::get_if<Ref>(v);
  if (!ref)
    ps.fail(*ps.find(name),
            fmt::format("property '{}' of {} expects a {}, got a {}", name, block, what, param_type_name(*v)));
  return ref;
}

}  // namespace rts::render::builder_detail
