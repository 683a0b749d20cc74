// Helpers for runtime tests: evaluate scene text held in memory.
#pragma once

#include <string>

#include "parser/diagnostics.hpp"
#include "render/scene/scene.hpp"
#include "runtime/evaluator.hpp"

namespace rts::test {

// Evaluates `text` as a file named `name` (in a SourceManager that lives for the test run).
render::SceneDesc eval_text(const std::string& text, const EvalOptions& options = {},
                            const std::string& name = "test.rts");

// Evaluates `text` expecting a LanguageError; returns its diagnostic, formatted as the sink
// prints it (REQUIREs that evaluation failed).
std::string eval_error(const std::string& text, const EvalOptions& options = {});
Diagnostic eval_diagnostic(const std::string& text, const EvalOptions& options = {});

// The dump of a scene.
std::string dump(const render::SceneDesc& scene);

// What print() and warnings wrote while evaluating (stderr captured).
std::string eval_warnings(const std::string& text, const EvalOptions& options);

}  // namespace rts::test
