#include "cli/stats_report.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "render/scene/source_ref.hpp"
#include "render/stats_json.hpp"

namespace rts::cli {

void report_stats(const StatsOptions& options, const render::RenderStats& stats) {
  if (options.print) std::cerr << "rts: stats\n" << render::stats_text(stats);
  if (options.json_path.empty()) return;
  if (options.json_path == "-") {
    std::cout << render::stats_json(stats);
    return;
  }
  // Written beside the target and renamed over it, so a failure never leaves half a file.
  std::string tmp = options.json_path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << render::stats_json(stats);
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      throw render::RenderError({}, fmt::format("cannot write statistics to '{}'", options.json_path));
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, options.json_path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw render::RenderError({}, fmt::format("cannot write statistics to '{}': {}", options.json_path, ec.message()));
  }
}

}  // namespace rts::cli
