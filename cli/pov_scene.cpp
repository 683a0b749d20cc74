#include "cli/pov_scene.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "import/pov/render_options.hpp"

namespace rts::cli {

namespace fs = std::filesystem;

bool is_pov_path(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == ".pov";
}

void print_pov_diagnostic(const import::pov::Diagnostic& d, const char* severity) {
  if (d.line <= 0) {
    std::cerr << fmt::format("{}: {}: {}\n", d.file, severity, d.message);
    return;
  }
  std::cerr << fmt::format("{}:{}:{}: {}: {}\n", d.file, d.line, d.col, severity, d.message);
  std::ifstream in(d.file, std::ios::binary);
  std::string line;
  for (int i = 1; std::getline(in, line); ++i) {
    if (i != d.line) continue;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::cerr << "    " << line << "\n    " << std::string(static_cast<std::size_t>(std::max(0, d.col - 1)), ' ')
              << "^\n";
    break;
  }
}

bool import_pov_file(const std::string& path, const import::pov::PovOptions& options,
                     import::pov::PovResult& result, std::string& why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = fmt::format("cannot open '{}'", path);
    return false;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  try {
    result = import::pov::import_pov(buffer.str(), options);
  } catch (const import::pov::PovError& e) {
    print_pov_diagnostic(e.where, "error");
    why.clear();
    return false;
  }
  for (const import::pov::Diagnostic& w : result.warnings) print_pov_diagnostic(w, "warning");
  return true;
}

bool read_pov_ini(const std::string& path, import::pov::PovOptions& options, std::string& why) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    why = fmt::format("cannot open the .ini file '{}'", path);
    return false;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::vector<import::pov::Diagnostic> warnings;
  try {
    import::pov::read_render_options(buffer.str(), path, options, warnings);
  } catch (const import::pov::PovError& e) {
    print_pov_diagnostic(e.where, "error");
    why.clear();
    return false;
  }
  for (const import::pov::Diagnostic& w : warnings) print_pov_diagnostic(w, "warning");
  return true;
}

}  // namespace rts::cli
