#include "render/frame.hpp"

#include <algorithm>
#include <new>

#include <fmt/format.h>

namespace rts::render {

AovFlags parse_aovs(const std::vector<std::string>& names) {
  AovFlags f;
  for (const std::string& n : names) {
    if (n == "normal") f.normal = true;
    else if (n == "depth") f.depth = true;
    else if (n == "albedo") f.albedo = true;
    else throw RenderError({}, fmt::format("unknown AOV '{}' (expected normal, depth or albedo)", n));
  }
  return f;
}

void allocate_frame(RenderResult& result, int width, int height, AovFlags aovs, SourceRef where,
                    Frame& frame) {
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  frame.width = width;
  frame.height = height;
  frame.aovs = aovs;
  try {
    result.color = Image(width, height);
    result.stats.pixels.mean.assign(pixels, 0.0f);
    result.stats.pixels.variance.assign(pixels, 0.0f);
    // std::map lookups happen here, once: operator[] must not run concurrently in workers.
    if (aovs.normal) frame.normal = &(result.aovs["normal"] = Image(width, height));
    if (aovs.albedo) frame.albedo = &(result.aovs["albedo"] = Image(width, height));
    if (aovs.depth) {
      result.aovs["depth"] = Image(width, height);
      frame.depth.assign(pixels, -1.0f);
    }
  } catch (const std::bad_alloc&) {
    throw RenderError(where, fmt::format("out of memory for a {}x{} image", width, height));
  }
  frame.color = &result.color;
  frame.mean = &result.stats.pixels.mean;
  frame.variance = &result.stats.pixels.variance;
}

void finish_depth(RenderResult& result, const Frame& frame) {
  if (!frame.aovs.depth) return;
  float farthest = 0.0f;
  for (float d : frame.depth) farthest = std::max(farthest, d);
  Image& img = result.aovs["depth"];
  for (std::size_t i = 0; i < frame.depth.size(); ++i) {
    float v = frame.depth[i] >= 0.0f && farthest > 0.0f ? frame.depth[i] / farthest : 0.0f;
    img.rgb[i * 3] = img.rgb[i * 3 + 1] = img.rgb[i * 3 + 2] = v;
  }
}

}  // namespace rts::render
