// A log-log line plot as a standalone SVG (no dependencies): axes with decade ticks, one
// polyline with markers per series, a legend, and optional dashed guide lines.
#pragma once

#include <string>
#include <vector>

namespace rts::cli {

struct PlotSeries {
  std::string name;
  std::vector<double> x, y;  // points with x, y > 0 are drawn
  bool dashed = false;       // guides (e.g. a slope -1/2 reference)
};

struct LogLogPlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
};

std::string render_svg(const LogLogPlot& plot);

}  // namespace rts::cli
