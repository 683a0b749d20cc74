#include "import/pov/render_options.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <set>

#include <fmt/format.h>

namespace rts::import::pov {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  std::size_t b = s.find_first_not_of(" \t\r");
  std::size_t e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// POV-Ray's booleans: on/off, true/false, yes/no, 1/0.
bool truth(const std::string& v) {
  std::string l = lower(v);
  return l == "on" || l == "true" || l == "yes" || (!l.empty() && std::atof(l.c_str()) != 0);
}

}  // namespace

void read_render_options(const std::string& text, const std::string& path, PovOptions& options,
                         std::vector<Diagnostic>& warnings) {
  // Keys that change the picture and are not carried into the scene.
  static const std::set<std::string> unread = {"clock", "initial_clock", "final_clock", "initial_frame",
                                                "final_frame", "antialias_depth", "sampling_method", "jitter",
                                                "jitter_amount", "display_gamma", "file_gamma", "declare",
                                                "start_column", "end_column", "start_row", "end_row"};
  bool antialias = false;
  double threshold = 0.3;  // POV-Ray's default Antialias_Threshold
  int line_no = 0;
  std::size_t start = 0;
  auto number = [&](const std::string& v, int col, const std::string& key) {
    char* end = nullptr;
    double d = std::strtod(v.c_str(), &end);
    if (v.empty() || end != v.c_str() + v.size())
      throw PovError{Diagnostic{path, line_no, col, fmt::format("'{}' needs a number, got '{}'", key, v)}};
    return d;
  };
  auto size = [&](const std::string& v, int col, const std::string& key) {
    double d = number(v, col, key);
    if (d < 1 || d > 65536 || d != static_cast<int>(d))
      throw PovError{Diagnostic{path, line_no, col, fmt::format("'{}' must be a whole number from 1 to 65536", key)}};
    return static_cast<int>(d);
  };
  while (start <= text.size()) {
    std::size_t nl = text.find('\n', start);
    std::string line = text.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
    start = nl == std::string::npos ? text.size() + 1 : nl + 1;
    ++line_no;
    if (std::size_t c = line.find(';'); c != std::string::npos) line.resize(c);  // ; starts a comment
    std::string t = trim(line);
    if (t.empty() || t[0] == '[') continue;  // [section] headers name animation variants
    const int col = static_cast<int>(line.find_first_not_of(" \t") + 1);
    if (t[0] == '+' || t[0] == '-') {
      // Switches, several to a line: +W320 +H240 +A0.3 -A
      std::size_t p = 0;
      while (p < t.size()) {
        std::size_t e = t.find_first_of(" \t", p);
        std::string sw = t.substr(p, e == std::string::npos ? std::string::npos : e - p);
        p = e == std::string::npos ? t.size() : t.find_first_not_of(" \t", e);
        if (p == std::string::npos) p = t.size();
        if (sw.size() < 2) continue;
        const bool on = sw[0] == '+';
        const char k = static_cast<char>(std::toupper(static_cast<unsigned char>(sw[1])));
        std::string v = sw.substr(2);
        if (k == 'W' && v.size() && std::isdigit(static_cast<unsigned char>(v[0]))) options.width = size(v, col, sw);
        else if (k == 'H' && v.size() && std::isdigit(static_cast<unsigned char>(v[0]))) options.height = size(v, col, sw);
        else if (k == 'A' && (v.empty() || std::isdigit(static_cast<unsigned char>(v[0])) || v[0] == '.')) {
          antialias = on;
          if (!v.empty()) threshold = number(v, col, sw);
        } else if (k == 'K') {
          warnings.push_back(Diagnostic{path, line_no, col, fmt::format("POV-Ray's '{}' (the clock) is not read; "
                                                                      "rts's clock is set with --frames", sw)});
        }
      }
      continue;
    }
    std::size_t eq = t.find('=');
    if (eq == std::string::npos) continue;  // a bare file name: POV-Ray's Input_File_Name
    std::string key = lower(trim(t.substr(0, eq))), value = trim(t.substr(eq + 1));
    if (key == "width") options.width = size(value, col, "Width");
    else if (key == "height") options.height = size(value, col, "Height");
    else if (key == "antialias") antialias = truth(value);
    else if (key == "antialias_threshold") threshold = number(value, col, "Antialias_Threshold");
    else if (unread.count(key))
      warnings.push_back(Diagnostic{path, line_no, col, fmt::format("POV-Ray's '{}' is not read from the .ini file "
                                                                  "(rts reads Width, Height, Antialias and "
                                                                  "Antialias_Threshold)", trim(t.substr(0, eq)))});
  }
  options.antialias_threshold = antialias ? std::max(0.0, threshold) : -1;
}

}  // namespace rts::import::pov
