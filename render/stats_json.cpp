#include "render/stats_json.hpp"

#include <cmath>
#include <string_view>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

namespace rts::render {
namespace {

std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) out += fmt::format("\\u{:04x}", c);
        else out += c;
    }
  }
  return out + "\"";
}

template <class T>
std::string json_value(const T& v) {
  if constexpr (std::is_same_v<T, bool>) {
    return v ? "true" : "false";
  } else if constexpr (std::is_floating_point_v<T>) {
    // Negative: a time or an error that was not measured.
    if (!std::isfinite(v) || v < 0) return "null";
    return fmt::format("{}", v);
  } else if constexpr (std::is_arithmetic_v<T>) {
    return fmt::format("{}", v);
  } else if constexpr (std::is_convertible_v<T, std::string_view>) {
    return quoted(v);
  } else if constexpr (std::is_same_v<T, NamedCounts>) {
    std::string out = "{";
    for (std::size_t i = 0; i < v.size(); ++i)
      out += fmt::format("{}{}: {}", i ? ", " : "", quoted(v[i].first), v[i].second);
    return out + "}";
  } else {  // a list of strings
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + quoted(v[i]);
    return out + "]";
  }
}

std::vector<std::string_view> split(std::string_view name) {
  std::vector<std::string_view> parts;
  std::size_t start = 0, dot;
  while ((dot = name.find('.', start)) != std::string_view::npos) {
    parts.push_back(name.substr(start, dot - start));
    start = dot + 1;
  }
  parts.push_back(name.substr(start));
  return parts;
}

}  // namespace

std::string stats_json(const RenderStats& stats) {
  std::string out = fmt::format("{{\n  \"version\": {}", kStatsJsonVersion);
  std::vector<std::string_view> open;  // the objects now open, outermost first
  bool first = false;                  // nothing written yet in the innermost open object
  auto indent = [&](std::size_t depth) { return std::string(2 * (depth + 1), ' '); };
  stats.visit([&](std::string_view name, const auto& value) {
    std::vector<std::string_view> path = split(name);
    std::size_t common = 0;
    while (common < open.size() && common + 1 < path.size() && open[common] == path[common]) ++common;
    while (open.size() > common) {
      open.pop_back();
      out += "\n" + indent(open.size()) + "}";
      first = false;
    }
    for (std::size_t i = common; i + 1 < path.size(); ++i) {
      out += (first ? "\n" : ",\n") + indent(open.size()) + quoted(path[i]) + ": {";
      open.push_back(path[i]);
      first = true;
    }
    out += (first ? "\n" : ",\n") + indent(open.size()) + quoted(path.back()) + ": " + json_value(value);
    first = false;
  });
  while (!open.empty()) {
    open.pop_back();
    out += "\n" + indent(open.size()) + "}";
  }
  return out + "\n}\n";
}

std::string stats_text(const RenderStats& stats) {
  std::string out;
  std::string_view section;
  stats.visit([&](std::string_view name, const auto& value) {
    std::size_t dot = name.find('.');
    std::string_view head = dot == std::string_view::npos ? name : name.substr(0, dot);
    std::string_view key = dot == std::string_view::npos ? std::string_view{} : name.substr(dot + 1);
    if (head != section) {
      if (!out.empty()) out += "\n";
      out += fmt::format("  {:<15}", fmt::format("{}:", head));
      section = head;
    } else {
      out += ", ";
    }
    std::string v = json_value(value);
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_convertible_v<T, std::string_view>) v = std::string(value);
    if constexpr (std::is_same_v<T, std::vector<std::string>>) {
      v.clear();
      for (const std::string& s : value) v += (v.empty() ? "" : " ") + s;
      if (v.empty()) v = "-";
    }
    if constexpr (std::is_same_v<T, NamedCounts>) {
      v.clear();
      for (const auto& [k, n] : value) v += fmt::format("{}{} {}", v.empty() ? "" : ", ", k, n);
      if (v.empty()) v = "-";
    }
    if constexpr (std::is_floating_point_v<T>) {
      if (v != "null") v = value >= 1000 ? fmt::format("{:.0f}", value) : fmt::format("{:.4g}", value);
    }
    if constexpr (std::is_same_v<T, NamedCounts>) {
      if (head == "memory_bytes") {  // bytes are easier to read in KiB
        v.clear();
        for (const auto& [k, n] : value) v += fmt::format("{}{} {:.1f} KiB", v.empty() ? "" : ", ", k, n / 1024.0);
      }
    }
    if (v == "null") v = "n/a";
    out += key.empty() ? v : fmt::format("{} {}", key, v);
  });
  return out + "\n";
}

}  // namespace rts::render
