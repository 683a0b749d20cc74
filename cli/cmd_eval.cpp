// `rts check` (evaluate and summarise) and `rts eval` (evaluate and dump the scene), plus the
// flags they share with `rts render` (add_eval_options, declared in cli/eval_options.hpp).
#include <iostream>
#include <functional>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/command.hpp"
#include "cli/eval_options.hpp"
#include "parser/diagnostics.hpp"
#include "render/source_ref.hpp"
#include "runtime/evaluator.hpp"
#include "runtime/scene_summary.hpp"

namespace rts::cli {

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
  cmd.add_option("--max-iterations", opts.limits.max_iterations, "Loop iterations allowed, in total")
      ->capture_default_str();
  cmd.add_option("--max-recursion", opts.limits.max_recursion, "Macro call depth allowed")
      ->capture_default_str()
      ->check(CLI::Range(1u, 10'000'000u));
  cmd.add_option("--max-objects", opts.limits.max_objects, "Object placements allowed, in total")
      ->capture_default_str();
  cmd.add_option("--max-mesh-triangles", opts.limits.max_mesh_triangles, "Mesh triangles allowed, in total")
      ->capture_default_str();
}

namespace {

struct EvalCommand {
  std::string file;
  EvalOptions options;
};

// Evaluates `cmd.file`, reporting errors; returns false (and sets the exit code) on failure.
bool run_eval(const EvalCommand& cmd, CommandContext& ctx, SourceManager& sources, EvalResult& result) {
  DiagnosticSink sink(std::cerr, ctx.color);
  try {
    result = evaluate_file(sources, cmd.file, cmd.options, sink);
    return true;
  } catch (const LanguageError& e) {
    sink.report(e.diag);
  } catch (const SourceError& e) {
    std::cerr << e.message << "\n";
  } catch (const render::SceneError& e) {  // not expected: the evaluator converts these
    std::cerr << fmt::format("{}:{}:{}: error: {}\n", e.where.file, e.where.line, e.where.col, e.what());
  }
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
                           runtime::SceneSummary s = runtime::summarize(result.scene);
                           runtime::print_summary(std::cout, result.scene, s, result.seconds);
                         },
                         /*warn_unused=*/true);
}

void add_eval_command(CLI::App& app, CommandContext& ctx) {
  add_evaluating_command(app, ctx, "eval", "Evaluate a scene and print the scene description it builds",
                         [](const EvalResult& result) { result.scene.dump(std::cout); });
}

}  // namespace rts::cli
