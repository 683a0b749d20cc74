// One analysis of a buffer: parse it, index its names, and (if it parses) evaluate it under
// small budgets, collecting every error and warning as data. The buffer's own text is
// analysed (unsaved edits included) under the file's path, so includes resolve relative to it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lsp/symbol_index.hpp"
#include "lsp/text_scan.hpp"
#include "parser/ast.hpp"
#include "parser/diagnostics.hpp"
#include "parser/source.hpp"
#include "runtime/evaluator.hpp"

namespace rts::lsp {

// Budgets far below the render defaults (docs/reliability.md): a runaway loop costs the editor
// a fraction of a second, never a freeze.
struct AnalysisOptions {
  bool evaluate = true;
  std::vector<std::string> include_paths;
  EvalLimits limits = [] {
    EvalLimits l;
    l.max_steps = 5'000'000;
    l.max_iterations = 2'000'000;
    l.max_recursion = 200;
    l.max_objects = 1'000'000;
    l.max_mesh_triangles = 2'000'000;
    l.max_memory = std::size_t(1) << 30;
    l.max_seconds = 2.0;
    return l;
  }();
};

struct Analysis {
  std::unique_ptr<SourceManager> sources;  // owns the files locations point into
  const SourceFile* file = nullptr;        // the buffer
  std::optional<ast::Program> program;     // empty when the buffer does not parse
  // The buffer's names; while it does not parse (mid-edit), those of the last text that did,
  // so completion and signature help keep working (their offsets may be a little off).
  SymbolIndex symbols;
  bool symbols_stale = false;
  std::vector<Diagnostic> diagnostics;     // errors and warnings, in order
  std::vector<GlobalValue> globals;        // top-level values after a successful evaluation
  bool evaluated = false;                  // evaluation ran to the end
  double seconds = 0;                      // parse + index + evaluation
};

// `previous`: the symbols to keep when the text does not parse.
Analysis analyze(const std::string& path, const std::string& text, const LineIndex& lines,
                 const AnalysisOptions& options, SymbolIndex previous = {});

}  // namespace rts::lsp
