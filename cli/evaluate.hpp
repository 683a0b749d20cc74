// Evaluating a scene file for a command, and reporting what went wrong: the one path `rts
// check`, `rts eval`, `rts render` and `rts converge` share.
#pragma once

#include <string>
#include <string_view>

#include "parser/diagnostics.hpp"
#include "parser/source.hpp"
#include "render/scene/source_ref.hpp"
#include "runtime/evaluator.hpp"

namespace rts::cli {

// Which scene warnings (runtime/scene_warnings.hpp) to report after evaluating.
struct SceneWarnings {
  bool report = false;
  std::string_view integrator;  // --integrator, "" for the scene's own
};

// Evaluates `path` into `out`. Returns true, or reports the located error (with the source
// line and a caret) and returns false: the command then exits with kExitLanguageError.
bool evaluate_reporting(SourceManager& sources, const std::string& path, const EvalOptions& options,
                        DiagnosticSink& sink, EvalResult& out, SceneWarnings warnings = {});

// An error located by a SourceRef (render errors, exit 3, are shown like language errors):
// with the source line and a caret when it points into a loaded scene file.
void print_error(const render::SourceRef& where, const std::string& message, const SourceManager& sources,
                 DiagnosticSink& sink);

}  // namespace rts::cli
