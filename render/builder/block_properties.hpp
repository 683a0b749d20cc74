// What each non-shape block kind (settings, camera, material, lights, textures, CSG) takes:
// every property with its type, default and a one-line meaning, as the shape kinds describe
// theirs in their ShapeTraits (render/geometry/shapes/shape_info.hpp). The builder's lists of
// valid names (unknown-property errors and their suggestions) are derived from these tables,
// the language server's hover and completion read them, and tests/render/test_block_properties
// checks that docs/rendering.md documents each property.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "render/geometry/shapes/shape_info.hpp"

namespace rts::render {

struct BlockInfo {
  std::string_view kind;                     // the block kind, "camera"
  std::string_view meaning;                  // one line
  std::span<const PropertyInfo> properties;  // every property it takes
};

// Every non-shape block kind with a fixed set of properties, in the builder's order. (Pattern
// textures, marble and its kin, are described by pattern_builder.cpp's own list.)
std::span<const BlockInfo> block_infos();

// The entry for `kind` (a shape kind too: its ShapeTraits properties plus `material`), or
// nullptr for a kind without a table.
const BlockInfo* find_block_info(std::string_view kind);

// The property names of a table, for ParamSet::check_unused.
std::vector<std::string_view> property_names(std::span<const PropertyInfo> properties);

}  // namespace rts::render
