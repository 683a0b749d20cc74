// Rendering a SceneDesc to images. The CLI calls render() then write_png().
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "render/image.hpp"
#include "render/scene.hpp"
#include "render/stats.hpp"

namespace rts::render {

struct RenderOptions {
  int threads = 0;                        // 0: all hardware threads
  std::optional<uint64_t> seed;           // overrides settings.seed
  std::optional<int> width, height, samples, max_depth;  // override settings
  std::vector<std::string> aovs;          // any of "normal", "depth", "albedo"
  bool progress = false;                  // progress bar with ETA on stderr
  std::size_t max_pixels = 100'000'000;   // larger images are a RenderError
};

struct RenderResult {
  Image color;                            // linear RGB
  std::map<std::string, Image> aovs;      // name → image (already display-ready values)
  RenderStats stats;
  std::vector<Warning> warnings;          // settings adjusted to render (max_depth capped)
};

// Throws RenderError (located where possible) for unreadable textures, oversize images...
RenderResult render(const SceneDesc& scene, const RenderOptions& options);

}  // namespace rts::render
