// `--tile-log FILE`: where a distributed (or journaled) still's time went, tile by tile, as
// JSON Lines — one line per tile rank 0 stored ({"unit", "round", "tile", "rank", "seconds",
// "bytes"}), then one summary line with rank 0's serial costs and the process's start-up. It
// shows which ranks were slow and which tiles were dear, and it is what
// bench/simulate_ranks.py replays to estimate efficiency at rank counts this machine lacks.
#pragma once

#include <string>

#include "dist/tile_exchange.hpp"
#include "render/image/stats.hpp"

namespace rts::dist {

// Written atomically; throws render::RenderError when the file cannot be written.
void write_tile_log(const std::string& path, const ExchangeStats& x, int ranks, int tiles_per_round,
                    const render::RenderStats& stats);

}  // namespace rts::dist
