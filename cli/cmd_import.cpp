// `rts import FILE [-o OUT.rts] [--format mit|csci420|uw|pov]`: translates a POV-Ray scene
// (import/pov/) or a course scene file (MIT 6.837, USC CSCI 420, UW CSE 457) into a readable
// .rts scene; meshes and a POV-Ray scene's own include files go beside OUT. Without -o the scene
// goes to standard output (meshes beside the input's name in the current folder). Files are
// written whole or not at all.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "cli/command.hpp"
#include "cli/pov_scene.hpp"
#include "import/import.hpp"
#include "parser/diagnostics.hpp"
#include "runtime/stdlib_path.hpp"

namespace rts::cli {
namespace {

namespace fs = std::filesystem;

struct ImportCommandOptions {
  std::string file;
  std::string output;
  std::string format;
  std::vector<std::string> include_dirs;  // -I: POV-Ray's Library_Path
  bool strict = false;
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

// A POV-Ray scene: the .rts and, beside it, one .rts per include file of the user's own.
int run_pov_import(const ImportCommandOptions& o) {
  import::pov::PovOptions opt;
  opt.source_path = o.file;
  opt.include_dirs = o.include_dirs;
  opt.strict = o.strict;
  opt.stdlib_dir = runtime::find_standard_library();
  import::pov::PovResult result;
  std::string why;
  if (!import_pov_file(o.file, opt, result, why)) {
    if (!why.empty()) {
      std::cerr << "rts: " << why << "\n";
      return kExitUsage;
    }
    return kExitLanguageError;
  }
  fs::path out_path = o.output.empty() ? fs::path() : fs::path(o.output);
  fs::path out_dir = o.output.empty() ? fs::path(".") : out_path.parent_path();
  if (out_dir.empty()) out_dir = ".";
  for (const import::pov::PovOutputFile& f : result.includes) {
    if (!write_whole(out_dir / f.name, f.text, why)) {
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
    std::cerr << fmt::format("rts: wrote {} (POV-Ray scene{}{})\n", out_path.string(),
                             result.includes.empty() ? "" : fmt::format(", {} include files", result.includes.size()),
                             result.warnings.empty() ? "" : fmt::format(", {} warnings", result.warnings.size()));
  }
  return kExitOk;
}

// .pov by name, or POV-Ray's directives and blocks in a file no course format claims.
bool is_pov_input(const ImportCommandOptions& o, const std::string& text) {
  if (o.format == "pov") return true;
  if (!o.format.empty()) return false;
  if (is_pov_path(o.file)) return true;
  try {
    import::detect_format(text, "");
    return false;  // a course format by its content
  } catch (const import::ImportError&) {
    return import::pov::looks_like_pov(text);
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
  if (is_pov_input(o, text)) return run_pov_import(o);
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
      "import", "Translate a POV-Ray scene (.pov) or a course scene file (MIT 6.837, CSCI 420 .scene, UW .ray) into an .rts scene");
  cmd->add_option("file", opts->file, "POV-Ray or course scene file")->required();
  cmd->add_option("-o,--output", opts->output, "The .rts file to write (default: standard output)");
  cmd->add_option("--format", opts->format, "The input's format when it cannot be recognised")
      ->check(CLI::IsMember({"mit", "csci420", "uw", "pov"}));
  cmd->add_option("-I", opts->include_dirs, "POV-Ray: a folder searched for #include files (Library_Path)");
  cmd->add_flag("--strict", opts->strict, "POV-Ray: what rts cannot express is an error, not a warning");
  cmd->callback([opts, &ctx] { ctx.exit_code = run_import(*opts); });
}

}  // namespace rts::cli
