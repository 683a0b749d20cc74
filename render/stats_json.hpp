// RenderStats as JSON (`rts render --stats-json FILE`) and as the `--stats` text report.
// Both walk RenderStats::visit, so a figure added there appears in both with no change here.
// The schema is documented in docs/stats-json.md.
#pragma once

#include <string>

#include "render/image/stats.hpp"

namespace rts::render {

inline constexpr int kStatsJsonVersion = 1;

// {"version": 1, "image": {...}, "scene": {...}, ...}: dotted names become nested objects;
// numbers that are not finite or negative "not measured" times are written as null.
std::string stats_json(const RenderStats& stats);

// One line per section: "rays: camera 307200, shadow 286112, ...".
std::string stats_text(const RenderStats& stats);

}  // namespace rts::render
