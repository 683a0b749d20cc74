// What a render produces: the image, its AOVs, the statistics and the warnings. Here, below
// the renderer, so that the frame and tile code in image/ can fill it (render/renderer.hpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "render/image/image.hpp"
#include "render/image/stats.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

struct RenderResult {
  Image color;                            // linear RGB
  std::map<std::string, Image> aovs;      // name → image (already display-ready values)
  RenderStats stats;
  std::vector<Warning> warnings;          // settings adjusted to render (max_depth capped)
};

}  // namespace rts::render
