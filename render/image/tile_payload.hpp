// One tile of a frame as bytes, for distribution (TileExchange) and checkpoints: its ray counts,
// then per pixel (row-major within the tile) the colour, its variance, the samples taken and
// each AOV the frame has. Unpacking a tile's bytes reproduces the pixels exactly, so an image
// gathered from several processes is the bytes one process would have made.
#pragma once

#include <vector>

#include "render/image/frame.hpp"
#include "render/image/stats.hpp"

namespace rts::render {

struct TileRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) × [y0, y1)
};

void pack_tile(const Frame& frame, const TileRect& rect, const RayCounters& counters, std::vector<unsigned char>& out);
// Throws RenderError when the bytes are not a tile of this size and layout.
void unpack_tile(Frame& frame, const TileRect& rect, const std::vector<unsigned char>& in, RayCounters& counters);

}  // namespace rts::render
