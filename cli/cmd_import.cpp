// `rts import FILE [-o OUT.rts] [--format mit|csci420|uw]`: translates a course scene file
// (MIT 6.837, USC CSCI 420, UW CSE 457) into a readable .rts scene; meshes go beside OUT as
// OBJ files. Without -o the scene goes to standard output (meshes beside the input's name in
// the current folder). Files are written whole or not at all.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "cli/command.hpp"
#include "import/import.hpp"
#include "parser/diagnostics.hpp"

namespace rts::cli {
namespace {

namespace fs = std::filesystem;

struct ImportCommandOptions {
  std::string file;
  std::string output;
  std::string format;
};

// Writes `text` to `path` through a temporary file renamed over it.
bool write_whole(const fs::path& path, const std::string& text, std::string& why) {
  fs::path temp = path;
  temp += ".tmp-import";
  {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    out.flush();
    if (!out) {
      why = "cannot write " + temp.string();
      std::error_code ec;
      fs::remove(temp, ec);
      return false;
    }
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    why = fmt::format("cannot write {}: {}", path.string(), ec.message());
    fs::remove(temp, ec);
    return false;
  }
  return true;
}

// "file:line:col: error: message", the line, and a caret under the column.
void report(const std::string& file, const std::string& text, const import::ImportError& e) {
  std::cerr << fmt::format("{}:{}:{}: error: {}\n", file, e.line, e.col, e.what());
  std::istringstream lines(text);
  std::string line;
  for (int i = 1; std::getline(lines, line); ++i) {
    if (i != e.line) continue;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::cerr << "    " << line << "\n    " << std::string(static_cast<std::size_t>(std::max(0, e.col - 1)), ' ')
              << "^\n";
    break;
  }
}

int run_import(const ImportCommandOptions& o) {
  std::ifstream in(o.file, std::ios::binary);
  if (!in) {
    std::cerr << fmt::format("rts: cannot open '{}'\n", o.file);
    return kExitUsage;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  try {
    import::Format format;
    if (o.format == "mit") format = import::Format::Mit;
    else if (o.format == "csci420") format = import::Format::Csci420;
    else if (o.format == "uw") format = import::Format::UwRay;
    else format = import::detect_format(text, o.file);

    import::ImportOptions opt;
    opt.source_name = fs::path(o.file).filename().string();
    opt.source_dir = fs::path(o.file).parent_path().string();
    fs::path out_path = o.output.empty() ? fs::path() : fs::path(o.output);
    opt.output_dir = o.output.empty() ? std::string(".") : out_path.parent_path().string();
    if (opt.output_dir.empty()) opt.output_dir = ".";
    opt.mesh_prefix = (o.output.empty() ? fs::path(o.file) : out_path).stem().string();
    import::ImportResult result = import::import_scene(text, format, opt);

    std::string why;
    for (const import::MeshFile& m : result.meshes) {
      if (!write_whole(fs::path(opt.output_dir) / m.name, m.text, why)) {
        std::cerr << "rts: " << why << '\n';
        return kExitRenderError;
      }
    }
    if (o.output.empty()) {
      std::cout << result.rts;
      std::cout.flush();
    } else if (!write_whole(out_path, result.rts, why)) {
      std::cerr << "rts: " << why << '\n';
      return kExitRenderError;
    } else {
      std::cerr << fmt::format("rts: wrote {} ({}{})\n", out_path.string(), import::format_name(result.format),
                               result.meshes.empty() ? "" : fmt::format(", {} mesh files", result.meshes.size()));
    }
    return kExitOk;
  } catch (const import::ImportError& e) {
    report(o.file, text, e);
    return kExitLanguageError;
  }
}

}  // namespace

void add_import_command(CLI::App& app, CommandContext& ctx) {
  auto opts = std::make_shared<ImportCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "import", "Translate a course scene file (MIT 6.837, CSCI 420 .scene, UW .ray) into an .rts scene");
  cmd->add_option("file", opts->file, "Course scene file")->required();
  cmd->add_option("-o,--output", opts->output, "The .rts file to write (default: standard output)");
  cmd->add_option("--format", opts->format, "The input's format when it cannot be recognised")
      ->check(CLI::IsMember({"mit", "csci420", "uw"}));
  cmd->callback([opts, &ctx] { ctx.exit_code = run_import(*opts); });
}

}  // namespace rts::cli
