// `rts check` (evaluate and summarise) and `rts eval` (evaluate and dump the scene), plus the
// flags they share with `rts render` (add_eval_options, declared in cli/eval_options.hpp).
#include <iostream>
#include <functional>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/command.hpp"
#include "cli/eval_options.hpp"
#include "cli/evaluate.hpp"
#include "cli/number_flags.hpp"
#include "parser/diagnostics.hpp"
#include "render/scene/resource_limits.hpp"
#include "render/builder/scene_summary.hpp"
#include "render/scene/source_ref.hpp"
#include "runtime/evaluator.hpp"

namespace rts::cli {

namespace {
// Flag ranges (docs/reliability.md). Counts stop at 10^12: more would run for days anyway,
// and every value in range is honoured, never wrapped into "unlimited".
constexpr uint64_t kMaxCount = 1'000'000'000'000;
constexpr uint64_t kMaxObjects = 1'000'000'000;
// Deeper recursion than the 8 GiB evaluation stack can hold (64 KiB a level) is refused.
constexpr uint64_t kMaxRecursion = 100'000;
constexpr std::size_t kMinMemory = 64u << 20;
}  // namespace

void add_eval_options(CLI::App& cmd, EvalOptions& opts) {
  cmd.add_option("-I,--include-path", opts.include_paths,
                 "Folder searched for `include` files (after the including file's own folder)")
      ->type_name("DIR");
  cmd.add_option_function<std::vector<std::string>>(
         "-D,--define",
         [&opts](const std::vector<std::string>& texts) {
           for (const std::string& t : texts) {
             Define d;
             if (!parse_define(t, d)) throw CLI::ValidationError("--define", "expected NAME=VALUE, got '" + t + "'");
             opts.defines.push_back(d);
           }
         },
         "Replace the value of the first top-level `let NAME` of the main file (VALUE is an rts expression)")
      ->type_name("NAME=VALUE");
  // The CLI reads files as POV-Ray does: only under the scene's folder, -I and the current
  // folder unless --allow-read widens it; memory is bounded by default.
  opts.restrict_reads = true;
  opts.limits.max_memory = render::default_max_memory();
  cmd.add_option("--allow-read", opts.allow_read,
                 "Also let the scene read files under DIR (meshes, textures, includes); '/' allows every file")
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory);
  add_whole_option(cmd, "--max-iterations", opts.limits.max_iterations, 1, kMaxCount, "Loop iterations allowed, in total");
  add_whole_option(cmd, "--max-steps", opts.limits.max_steps, 1, kMaxCount,
                   "Evaluation steps allowed: loop iterations, macro calls, list elements and string bytes built");
  add_whole_option(cmd, "--max-recursion", opts.limits.max_recursion, 1, kMaxRecursion, "Macro call depth allowed");
  add_whole_option(cmd, "--max-objects", opts.limits.max_objects, 1, kMaxObjects,
                   "Objects allowed: placements, and objects in the world once groups are expanded");
  add_whole_option(cmd, "--max-mesh-triangles", opts.limits.max_mesh_triangles, 1, kMaxObjects,
                   "Mesh triangles allowed, in total (checked while a file loads)");
  add_size_option(cmd, "--max-memory", opts.limits.max_memory, kMinMemory,
                  "Memory the process may use, e.g. 8G (checked where lists, strings, meshes, groups and the image "
                  "are made)")
      ->default_str("half the RAM (" + render::size_in_words(opts.limits.max_memory) + " here)");
}

namespace {

struct EvalCommand {
  std::string file;
  EvalOptions options;
};

// Evaluates `cmd.file`, reporting errors; returns false (and sets the exit code) on failure.
bool run_eval(const EvalCommand& cmd, CommandContext& ctx, SourceManager& sources, EvalResult& result) {
  DiagnosticSink sink(std::cerr, ctx.color);
  // `rts check` warns as `rts render` does, before rendering (runtime/scene_warnings.hpp).
  if (evaluate_reporting(sources, cmd.file, cmd.options, sink, result, SceneWarnings{cmd.options.warn_unused, {}}))
    return true;
  ctx.exit_code = kExitLanguageError;
  return false;
}

// `check` and `eval` share their arguments and evaluation; they differ only in what they print.
void add_evaluating_command(CLI::App& app, CommandContext& ctx, const char* name, const char* help,
                            std::function<void(const EvalResult&)> print, bool warn_unused = false) {
  auto cmd = std::make_shared<EvalCommand>();
  cmd->options.warn_unused = warn_unused;
  CLI::App* sub = app.add_subcommand(name, help);
  sub->add_option("file", cmd->file, "Scene file (.rts)")->required();
  add_eval_options(*sub, cmd->options);
  sub->callback([cmd, &ctx, print = std::move(print)] {
    SourceManager sources;
    EvalResult result;
    if (!run_eval(*cmd, ctx, sources, result)) return;
    print(result);
    ctx.exit_code = kExitOk;
  });
}

}  // namespace

void add_check_command(CLI::App& app, CommandContext& ctx) {
  add_evaluating_command(app, ctx, "check", "Evaluate a scene without rendering and summarise it",
                         [](const EvalResult& result) {
                           render::SceneSummary s = render::summarize(result.scene);
                           render::print_summary(std::cout, result.scene, s, result.seconds);
                         },
                         /*warn_unused=*/true);
}

void add_eval_command(CLI::App& app, CommandContext& ctx) {
  add_evaluating_command(app, ctx, "eval", "Evaluate a scene and print the scene description it builds",
                         [](const EvalResult& result) { result.scene.dump(std::cout); });
}

}  // namespace rts::cli
