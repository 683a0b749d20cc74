// Builds the TextureDesc of a pattern texture block (marble { ... }, wood { ... }, pattern
// { function = f }, ...) from its parameters: the scene builder's texture() hands these kinds
// here. Names and defaults follow POV-Ray; docs/textures.md lists every property.
#pragma once

#include <string_view>
#include <vector>

#include "render/scene/params.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// The block kinds that are pattern textures ("bozo", "marble", ..., "pattern").
const std::vector<std::string_view>& pattern_kinds();
bool is_pattern_kind(std::string_view kind);
// The properties a pattern texture kind takes (empty for other kinds).
std::vector<std::string_view> pattern_property_names(std::string_view kind);
// Fills t.kind = Pattern and t.pattern; throws SceneError located at the offending property.
void build_pattern_texture(std::string_view kind, ParamSet& ps, TextureDesc& t);

}  // namespace rts::render
