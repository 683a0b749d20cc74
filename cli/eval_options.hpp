// Command-line flags shared by `rts check`, `rts eval` and `rts render`: include paths,
// defines and evaluation limits.
#pragma once

#include <CLI/CLI.hpp>

#include "runtime/evaluator.hpp"

namespace rts::cli {

// Registers -I/--include-path, -D/--define, --max-iterations, --max-recursion,
// --max-objects and --max-mesh-triangles on `cmd`, writing into `opts` when parsed.
// A malformed -D (no '=' or a bad name) is a CLI11 validation error (exit code 2).
void add_eval_options(CLI::App& cmd, EvalOptions& opts);

}  // namespace rts::cli
