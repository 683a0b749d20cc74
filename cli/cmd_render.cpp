// `rts render SCENE.rts [-o OUT.png|.pfm|.exr] ...`: evaluate the scene, render it, write the
// image(s). Nothing is written unless evaluation and rendering both succeed; each file is
// written atomically, so a failure never truncates an existing image.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/command.hpp"
#include "cli/eval_options.hpp"
#include "parser/diagnostics.hpp"
#include "render/image_output.hpp"
#include "render/renderer.hpp"
#include "runtime/evaluator.hpp"

namespace rts::cli {
namespace {

namespace fs = std::filesystem;

struct RenderCommand {
  std::string scene;
  std::string output;
  int threads = 0;
  uint64_t seed = 0;
  int width = 0, height = 0, samples = 0, max_depth = 0;
  std::vector<std::string> aovs;
  int bits = 0;  // 0: the format's default
  bool linear = false, aov_files = false;
  std::vector<double> depth_range;
  float depth_miss = 0.0f, normal_miss = 0.0f;
  bool no_progress = false;
  EvalOptions eval;
};

void print_error(const render::SourceRef& where, const std::string& message) {
  if (where.file && *where.file)
    std::cerr << fmt::format("{}:{}:{}: error: {}\n", where.file, where.line, where.col, message);
  else
    std::cerr << "rts: error: " << message << "\n";
}

// Fails early (before spending time rendering) when the output folder cannot take the file.
void check_output_writable(const std::string& out) {
  std::error_code ec;
  fs::file_status st = fs::status(out, ec);
  if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st)) {
    // A device or pipe (-o /dev/stdout): written in place, so it must itself be writable.
    if (access(out.c_str(), W_OK) != 0)
      throw render::RenderError({}, fmt::format("cannot write '{}': not writable", out));
    return;
  }
  fs::path dir = fs::path(out).parent_path();
  if (dir.empty()) dir = ".";
  if (!fs::is_directory(dir, ec))
    throw render::RenderError({}, fmt::format("cannot write '{}': directory '{}' does not exist", out, dir.string()));
  if (access(dir.c_str(), W_OK) != 0)
    throw render::RenderError({}, fmt::format("cannot write '{}': directory '{}' is not writable", out, dir.string()));
  if (fs::is_directory(out, ec))
    throw render::RenderError({}, fmt::format("cannot write '{}': it is a directory", out));
}

int run(const RenderCommand& c, const CLI::App& cmd, const CommandContext& ctx) {
  std::string out = c.output;
  if (out.empty()) out = fs::path(c.scene).stem().string() + ".png";
  // A usage error, before any work: never write one format's bytes under another's name.
  render::OutputSpecResult spec = render::output_spec(out, c.bits, c.linear, c.aov_files);
  if (!spec.spec) throw CLI::ValidationError("--output", spec.error);
  if (!c.depth_range.empty() && !(std::isfinite(c.depth_range[0]) && std::isfinite(c.depth_range[1]) &&
                                  c.depth_range[0] <= c.depth_range[1]))
    throw CLI::ValidationError("--depth-range", "expects two finite numbers NEAR,FAR with NEAR <= FAR");
  if (!std::isfinite(c.depth_miss) || !std::isfinite(c.normal_miss))
    throw CLI::ValidationError("--depth-miss/--normal-miss", "expects a finite number");

  SourceManager sources;
  DiagnosticSink sink(std::cerr, ctx.color);
  render::SceneDesc scene;
  double eval_seconds = 0;
  try {
    EvalResult evaluated = evaluate_file(sources, c.scene, c.eval, sink);
    scene = std::move(evaluated.scene);
    eval_seconds = evaluated.seconds;
  } catch (const LanguageError& e) {
    sink.report(e.diag);
    return kExitLanguageError;
  } catch (const SourceError& e) {
    std::cerr << e.message << "\n";  // already "path: error: ..."
    return kExitLanguageError;
  } catch (const render::SceneError& e) {
    print_error(e.where, e.what());
    return kExitLanguageError;
  }

  render::RenderOptions opts;
  opts.threads = c.threads;
  if (cmd.count("--seed")) opts.seed = c.seed;
  if (cmd.count("--width")) opts.width = c.width;
  if (cmd.count("--height")) opts.height = c.height;
  if (cmd.count("--samples")) opts.samples = c.samples;
  if (cmd.count("--max-depth")) opts.max_depth = c.max_depth;
  opts.aovs = c.aovs;
  if (!c.depth_range.empty()) opts.depth_range = std::make_pair(c.depth_range[0], c.depth_range[1]);
  opts.depth_miss = c.depth_miss;
  opts.normal_miss = c.normal_miss;
  opts.progress = !c.no_progress && isatty(STDERR_FILENO);

  try {
    check_output_writable(out);
    render::RenderResult result = render::render(scene, opts);
    result.stats.eval_seconds = eval_seconds;
    auto write_start = std::chrono::steady_clock::now();
    render::write_images(out, *spec.spec, result.color, result.aovs);
    result.stats.write_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
    std::cerr << "rts: " << out << ": " << result.stats.summary() << "\n";
  } catch (const render::RenderError& e) {
    print_error(e.where, e.what());
    return kExitRenderError;
  } catch (const std::bad_alloc&) {
    print_error({}, "out of memory");
    return kExitRenderError;
  }
  return kExitOk;
}

}  // namespace

void add_render_command(CLI::App& app, CommandContext& ctx) {
  auto c = std::make_shared<RenderCommand>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to an image (PNG, PFM or EXR)");
  cmd->add_option("scene", c->scene, "The scene file (.rts)")->required();
  cmd->add_option("-o,--output", c->output,
                  "Output image: .png, .pfm or .exr, by extension (default: the scene's name with .png, here)");
  cmd->add_option("--threads", c->threads, "Worker threads (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed", c->seed, "Random seed (overrides the scene's settings.seed)");
  cmd->add_option("--width", c->width, "Image width in pixels")->check(CLI::PositiveNumber);
  cmd->add_option("--height", c->height, "Image height in pixels")->check(CLI::PositiveNumber);
  cmd->add_option("--samples", c->samples, "Samples per pixel")->check(CLI::PositiveNumber);
  cmd->add_option("--max-depth", c->max_depth, "Reflection/refraction depth")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--aov", c->aovs, "Extra images: normal,depth,albedo (written as OUT.<name>.<ext>)")
      ->delimiter(',')
      ->check(CLI::IsMember({"normal", "depth", "albedo"}));
  cmd->add_option("--bits", c->bits, "Bits per channel: png 8 (default) or 16; exr 32 (default) or 16 (half)")
      ->check(CLI::IsMember({8, 16, 32}));
  cmd->add_flag("--linear", c->linear, "PNG: store linear values, not sRGB (as the courses do)");
  cmd->add_flag("--aov-files", c->aov_files, "EXR: write AOVs as separate files, not layers");
  cmd->add_option("--depth-range", c->depth_range, "Depth AOV: NEAR,FAR map linearly to black..white")
      ->delimiter(',')
      ->expected(2)
      ->check(CLI::Number);
  cmd->add_option("--depth-miss", c->depth_miss, "Depth AOV value where nothing is hit (default 0)");
  cmd->add_option("--normal-miss", c->normal_miss, "Normal AOV value where nothing is hit (default 0)");
  cmd->add_flag("--no-progress", c->no_progress, "Never draw the progress bar");
  add_eval_options(*cmd, c->eval);
  cmd->callback([c, cmd, &ctx] { ctx.exit_code = run(*c, *cmd, ctx); });
}

}  // namespace rts::cli
