// Builds a height_field block's grid: from an image file's pixels or by sampling a compiled
// macro over the unit square (render/geometry/shapes/height_field.hpp traces it).
#pragma once

#include <cstddef>
#include <string>

#include "render/scene/params.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// `path`: the image file, resolved and allowed by the read policy (empty when the block gives
// a function). Bad parameters and an unreadable image are located SceneErrors.
HeightField build_height_field(ParamSet& ps, const std::string& path, std::size_t max_memory);

}  // namespace rts::render
