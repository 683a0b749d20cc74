// The images a render fills in, pixel by pixel: color, per-pixel sample statistics and the
// optional AOVs. Allocated up front (an allocation failure is a RenderError, not a crash);
// workers write disjoint pixels, so no locking is needed.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "render/image/render_result.hpp"

namespace rts::render {

struct AovFlags {
  bool normal = false, depth = false, albedo = false;
  bool error = false;  // the per-pixel standard error, from the statistics after rendering
  bool error_map = false;  // the same as a false-colour picture of the relative error
  bool any() const { return normal || depth || albedo; }  // needs a first-hit ray per pixel
};

// "normal", "depth", "albedo", "error", "error_map"; anything else is a RenderError.
AovFlags parse_aovs(const std::vector<std::string>& names);

struct Frame {
  int width = 0, height = 0;
  AovFlags aovs;
  float normal_miss = 0.0f;                // normal AOV value where nothing is hit
  Image* color = nullptr;
  std::vector<float>* variance = nullptr;  // RenderStats::pixels; null when not kept (1 spp)
  std::vector<uint32_t>* taken = nullptr;
  Image* normal = nullptr;                 // null unless requested
  Image* albedo = nullptr;
  std::vector<float> depth;                // raw distances, < 0 where nothing is hit
  std::vector<uint8_t> depth_bounded;      // 1 where the hit is bounded geometry (not a plane)

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
};

// Sizes result's images and statistics for width x height and points `frame` at them.
// `with_variance`: keep the per-pixel variances (an error estimate is possible: two batches or
// more, or the error_map AOV asked); without them frame.variance is null and
// result.stats.pixels.variance empty (a 1-spp render of 800x600 spared 5.8 MB of stores).
// Throws RenderError (at `where`) when memory runs out.
void allocate_frame(RenderResult& result, int width, int height, AovFlags aovs, bool with_variance, SourceRef where,
                    Frame& frame);

// Normalises the raw depths into result.aovs["depth"]: `miss` where nothing is hit; with a
// range, (depth - near) / (far - near) clamped to [0, 1]; otherwise depth / reference clamped to
// 1. The reference is the farthest hit on bounded geometry when any is visible (so an infinite
// plane running to the horizon cannot squash everything else to black), else the 99th
// percentile of the (plane) depths.
void finish_depth(RenderResult& result, const Frame& frame,
                  std::optional<std::pair<double, double>> range = std::nullopt, float miss = 0.0f);

// Fills result.aovs["error"] (when requested) with each pixel's standard error per channel,
// linear; 0 where it is unknown. Fills result.aovs["error_map"] (when requested) with a picture
// of each pixel's relative standard error, sigma / (value + 0.01) over the channels' means, on a
// log scale from 0.1% (black) through blue, green and yellow to 100% and above (red): a view
// of where the noise is, stored as display colours (written without the sRGB curve, as AOVs
// are). Unknown errors (1 spp) are mid grey.
void finish_error(RenderResult& result, const Frame& frame);

// The error map's colour for a relative error (exposed for its test).
Vec3 error_map_colour(double relative_error);
void finish_error(RenderResult& result, const Frame& frame);

}  // namespace rts::render
