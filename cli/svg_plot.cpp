#include "cli/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace rts::cli {
namespace {

constexpr double kWidth = 640, kHeight = 440;
constexpr double kLeft = 80, kRight = 170, kTop = 40, kBottom = 60;  // margins (legend on the right)
const char* const kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

struct Axis {
  double lo, hi;  // decades (log10), whole numbers around the data
  double map(double v, double a, double b) const { return a + (std::log10(v) - lo) / (hi - lo) * (b - a); }
};

Axis axis_for(double min_v, double max_v) {
  if (!(min_v > 0) || !(max_v > 0)) return {0, 1};
  double lo = std::floor(std::log10(min_v)), hi = std::ceil(std::log10(max_v));
  if (hi <= lo) hi = lo + 1;
  return {lo, hi};
}

std::string tick_label(double decade) {
  double v = std::pow(10.0, decade);
  if (decade >= -3 && decade <= 3) return fmt::format("{:g}", v);
  return fmt::format("1e{:g}", decade);
}

}  // namespace

std::string render_svg(const LogLogPlot& plot) {
  double xmin = std::numeric_limits<double>::infinity(), xmax = 0, ymin = xmin, ymax = 0;
  for (const PlotSeries& s : plot.series)
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (s.x[i] > 0 && s.y[i] > 0 && !s.dashed) {
        xmin = std::min(xmin, s.x[i]); xmax = std::max(xmax, s.x[i]);
        ymin = std::min(ymin, s.y[i]); ymax = std::max(ymax, s.y[i]);
      }
  Axis ax = axis_for(xmin, xmax), ay = axis_for(ymin, ymax);
  const double x0 = kLeft, x1 = kWidth - kRight, y0 = kHeight - kBottom, y1 = kTop;
  auto px = [&](double v) { return ax.map(v, x0, x1); };
  auto py = [&](double v) { return ay.map(v, y0, y1); };

  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
      "font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      kWidth, kHeight);
  svg += fmt::format("<text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">{}</text>\n",
                     (x0 + x1) / 2, escape(plot.title));
  // Grid and ticks: every decade labelled, 2..9 as light lines.
  for (double d = ax.lo; d <= ax.hi; d += 1) {
    for (int m = 1; m < 10 && d + std::log10(m) <= ax.hi; ++m) {
      double x = px(std::pow(10.0, d) * m);
      svg += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"{3}\"/>\n", x, y0, y1,
                         m == 1 ? "#bbb" : "#eee");
    }
    svg += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", px(std::pow(10.0, d)),
                       y0 + 18, tick_label(d));
  }
  for (double d = ay.lo; d <= ay.hi; d += 1) {
    for (int m = 1; m < 10 && d + std::log10(m) <= ay.hi; ++m) {
      double y = py(std::pow(10.0, d) * m);
      svg += fmt::format("<line x1=\"{1}\" y1=\"{0:.1f}\" x2=\"{2}\" y2=\"{0:.1f}\" stroke=\"{3}\"/>\n", y, x0, x1,
                         m == 1 ? "#bbb" : "#eee");
    }
    svg += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>\n", x0 - 6,
                       py(std::pow(10.0, d)) + 4, tick_label(d));
  }
  svg += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n", x0, y1,
                     x1 - x0, y0 - y1);
  svg += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", (x0 + x1) / 2, kHeight - 18,
                     escape(plot.x_label));
  svg += fmt::format("<text transform=\"translate(20,{}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
                     (y0 + y1) / 2, escape(plot.y_label));
  svg += fmt::format("<svg x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" viewBox=\"{} {} {} {}\">\n", x0, y1, x1 - x0,
                     y0 - y1, x0, y1, x1 - x0, y0 - y1);  // clip series to the plot area
  std::size_t color = 0;
  std::string legend;
  double ly = kTop + 10;
  for (const PlotSeries& s : plot.series) {
    std::string c = s.dashed ? "#555" : kColors[color++ % std::size(kColors)];
    std::string points;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
      if (s.x[i] > 0 && s.y[i] > 0) points += fmt::format("{:.1f},{:.1f} ", px(s.x[i]), py(s.y[i]));
    svg += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"{} points=\"{}\"/>\n", c,
                       s.dashed ? 1.2 : 2, s.dashed ? " stroke-dasharray=\"6,4\"" : "", points);
    if (!s.dashed)
      for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
        if (s.x[i] > 0 && s.y[i] > 0)
          svg += fmt::format("<circle cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"3\" fill=\"{}\"/>\n", px(s.x[i]), py(s.y[i]), c);
    legend += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"2\"{}/>\n",
                          x1 + 12, ly, x1 + 36, ly, c, s.dashed ? " stroke-dasharray=\"6,4\"" : "");
    legend += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", x1 + 42, ly + 4, escape(s.name));
    ly += 20;
  }
  svg += "</svg>\n" + legend + "</svg>\n";
  return svg;
}

}  // namespace rts::cli
