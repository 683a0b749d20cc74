// `rts import FILE [-o OUT.rts] [--format mit|csci420|uw|pov] [course flags]`: translates a
// POV-Ray scene (import/pov/) or a course scene file (MIT 6.837, USC CSCI 420, UW CSE 457) into
// a readable .rts scene; meshes and a POV-Ray scene's own include files go beside OUT. The
// course programs' flags (MIT a2's --size --bounces --shadows, CSCI 420's --reflection
// --antialias --soft-shadows, --aov/--depth-range) become the scene's settings. Without -o the
// scene goes to standard output (meshes beside the input's name in the current folder). Files
// are written whole or not at all.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

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
  std::string ini;  // POV-Ray: its render options (Width, Height, Antialias)
  std::vector<int> size;           // MIT a2 -size W H
  int bounces = 0;                 // MIT a2 -bounces N
  bool shadows = false;            // MIT a2 -shadows
  int reflection = 0;              // CSCI 420 maxReflection
  int antialias = 1;               // CSCI 420 sampleRate
  int soft_shadows = 0;            // CSCI 420 subLightPerPointLight
  double soft_shadow_radius = 0.1;
  std::vector<std::string> aovs;   // normal, depth
  std::vector<double> depth_range; // NEAR,FAR
};

// Flags that belong to one course's program: given with another format's file, a usage error
// (the flag would silently do nothing).
std::string misplaced_flag(const CLI::App& cmd, import::Format format) {
  const char* mit[] = {"--size", "--bounces", "--shadows"};
  const char* csci[] = {"--reflection", "--antialias", "--soft-shadows", "--soft-shadow-radius"};
  if (format != import::Format::Mit)
    for (const char* f : mit)
      if (cmd.count(f)) return fmt::format("{} is MIT 6.837 a2's flag; this is a {}", f, import::format_name(format));
  if (format != import::Format::Csci420)
    for (const char* f : csci)
      if (cmd.count(f)) return fmt::format("{} is a CSCI 420 switch; this is a {}", f, import::format_name(format));
  if (format == import::Format::UwRay)
    for (const char* f : {"--aov", "--depth-range"})
      if (cmd.count(f))
        return fmt::format("{} applies to MIT and CSCI 420 scenes; for a {} give it to rts render", f,
                           import::format_name(format));
  return "";
}

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
  if (!o.ini.empty() && !read_pov_ini(o.ini, opt, why)) {
    if (!why.empty()) std::cerr << "rts: " << why << "\n";
    return why.empty() ? kExitLanguageError : kExitUsage;
  }
  if (!o.output.empty()) {
    // An image the scene names beside itself is then named from where the .rts goes.
    std::error_code ec;
    fs::path dir = fs::path(o.output).parent_path();
    opt.output_dir = fs::absolute(dir.empty() ? fs::path(".") : dir, ec).string();
  }
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

int run_import(const ImportCommandOptions& o, const CLI::App& cmd) {
  std::ifstream in(o.file, std::ios::binary);
  if (!in) {
    std::cerr << fmt::format("rts: cannot open '{}'\n", o.file);
    return kExitUsage;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (is_pov_input(o, text)) {
    for (const char* f : {"--size", "--bounces", "--shadows", "--reflection", "--antialias", "--soft-shadows",
                          "--soft-shadow-radius", "--aov", "--depth-range"})
      if (cmd.count(f)) {
        std::cerr << fmt::format("rts: import: {} is a course program's flag; this is a POV-Ray scene\n", f);
        return kExitUsage;
      }
    return run_pov_import(o);
  }
  try {
    import::Format format;
    if (o.format == "mit") format = import::Format::Mit;
    else if (o.format == "csci420") format = import::Format::Csci420;
    else if (o.format == "uw") format = import::Format::UwRay;
    else format = import::detect_format(text, o.file);
    if (std::string why = misplaced_flag(cmd, format); !why.empty()) {
      std::cerr << "rts: import: " << why << '\n';
      return kExitUsage;
    }

    import::ImportOptions opt;
    opt.source_name = fs::path(o.file).filename().string();
    opt.source_dir = fs::path(o.file).parent_path().string();
    fs::path out_path = o.output.empty() ? fs::path() : fs::path(o.output);
    opt.output_dir = o.output.empty() ? std::string(".") : out_path.parent_path().string();
    if (opt.output_dir.empty()) opt.output_dir = ".";
    opt.mesh_prefix = (o.output.empty() ? fs::path(o.file) : out_path).stem().string();
    if (o.size.size() == 2) opt.width = o.size[0], opt.height = o.size[1];
    opt.bounces = o.bounces;
    opt.shadows = o.shadows;
    opt.reflection = o.reflection;
    opt.antialias = o.antialias;
    opt.soft_shadows = o.soft_shadows;
    opt.soft_shadow_radius = o.soft_shadow_radius;
    for (const std::string& a : o.aovs) opt.aovs += (opt.aovs.empty() ? "" : ",") + a;
    if (o.depth_range.size() == 2) {
      opt.has_depth_range = true;
      opt.depth_near = o.depth_range[0];
      opt.depth_far = o.depth_range[1];
    }
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
  cmd->add_option("--ini", opts->ini, "POV-Ray: an .ini file whose Width, Height and Antialias go into the scene's settings");
  // The course programs' flags, written into the scene as settings (docs/from-courses.md).
  cmd->add_option("--size", opts->size, "MIT a2 -size: the image's width and height")
      ->expected(2)
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--bounces", opts->bounces, "MIT a2 -bounces: mirror reflection (ks · I_reflected), N bounces")
      ->check(CLI::Range(0, 1000));
  cmd->add_flag("--shadows", opts->shadows, "MIT a2 -shadows: cast shadow rays (none without it)");
  cmd->add_option("--reflection", opts->reflection,
                  "CSCI 420: recursive reflection (1 - ks)·local + ks·reflected, up to depth N")
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--antialias", opts->antialias, "CSCI 420: N x N samples per pixel")->check(CLI::Range(1, 256));
  cmd->add_option("--soft-shadows", opts->soft_shadows, "CSCI 420: split each point light into N jittered sub-lights")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--soft-shadow-radius", opts->soft_shadow_radius,
                  "CSCI 420: the sub-lights lie within this distance of their light (default 0.1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--aov", opts->aovs, "Extra images the scene asks for: normal,depth (MIT -normals, -depth)")
      ->delimiter(',')
      ->check(CLI::IsMember({"normal", "depth"}));
  cmd->add_option("--depth-range", opts->depth_range, "Depth image: NEAR,FAR map to black..white (MIT -depth)")
      ->delimiter(',')
      ->expected(2);
  cmd->callback([opts, cmd, &ctx] {
    if (opts->depth_range.size() == 2 &&
        !(std::isfinite(opts->depth_range[0]) && std::isfinite(opts->depth_range[1]) &&
          opts->depth_range[0] <= opts->depth_range[1]))
      throw CLI::ValidationError("--depth-range", "expects two finite numbers NEAR,FAR with NEAR <= FAR");
    ctx.exit_code = run_import(*opts, *cmd);
  });
}

}  // namespace rts::cli
