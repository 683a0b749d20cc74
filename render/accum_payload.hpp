// A progressive render's tile as bytes, for the rounds of a distributed or journaled render
// (TileExchange, dist/): what a process needs to add samples to a tile's pixels — their sample
// sums so far and how many samples each pixel takes this round — and what it sends back — the
// sums afterwards and the tile's ray counts. A pixel's sums after a round depend only on its
// sums before and the samples added (random numbers are keyed on pixel and sample index), so
// an image made in rounds over several processes is the bytes of one made in one process.
#pragma once

#include <cstdint>
#include <vector>

#include "render/image/tile_payload.hpp"
#include "render/pixel_renderer.hpp"
#include "render/image/stats.hpp"

namespace rts::render {

// `accs` and `add` are the whole image's, row-major with `width` pixels a row.
void pack_round_input(const std::vector<PixelAccum>& accs, const std::vector<uint32_t>& add, int width,
                      const TileRect& rect, std::vector<unsigned char>& out);
// Into the tile's own arrays (row-major within the tile). Throws RenderError on a size mismatch.
void unpack_round_input(const std::vector<unsigned char>& in, const TileRect& rect, std::vector<PixelAccum>& accs,
                        std::vector<uint32_t>& add);

// `accs`: the tile's own (row-major within the tile).
void pack_round_result(const RayCounters& counters, const std::vector<PixelAccum>& accs, std::vector<unsigned char>& out);
// Into the whole image's `accs`. Throws RenderError on a size mismatch.
void unpack_round_result(const std::vector<unsigned char>& in, const TileRect& rect, int width,
                         std::vector<PixelAccum>& accs, RayCounters& counters);

}  // namespace rts::render
