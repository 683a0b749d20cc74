// `rts render --stats` and `--stats-json FILE`: the render's figures (render/stats_json.hpp)
// printed to stderr and/or written as JSON (atomically, like the images).
#pragma once

#include <string>

#include "render/image/stats.hpp"

namespace rts::cli {

struct StatsOptions {
  bool print = false;       // --stats
  std::string json_path;    // --stats-json FILE ("" : none)
};

// Throws render::RenderError when the JSON file cannot be written.
void report_stats(const StatsOptions& options, const render::RenderStats& stats);

}  // namespace rts::cli
