#include "lsp/analysis.hpp"

#include <chrono>
#include <exception>
#include <sstream>

#include "parser/parser.hpp"
#include "runtime/scene_warnings.hpp"

namespace rts::lsp {

namespace {

// Hover shows a value, not a dump: longer texts are cut.
constexpr std::size_t kGlobalValueBytes = 200;

}  // namespace

Analysis analyze(const std::string& path, const std::string& text, const LineIndex& lines,
                 const AnalysisOptions& options, SymbolIndex previous) {
  auto start = std::chrono::steady_clock::now();
  Analysis a;
  a.sources = std::make_unique<SourceManager>();
  a.file = a.sources->add(path, text);
  auto error_at_start = [&](std::string message) {
    a.diagnostics.push_back(Diagnostic{Severity::Error, SourceLoc::at(a.file, 1, 1), std::move(message), {}});
  };
  if (std::size_t bad = find_invalid_utf8(text); bad != std::string::npos) {
    // The parser would refuse it the same way; say where.
    uint32_t line = 1, col = 1;
    for (std::size_t i = 0; i < bad; ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
    a.diagnostics.push_back(Diagnostic{Severity::Error, SourceLoc::at(a.file, line, col),
                                       "the text is not valid UTF-8 (or contains a NUL byte) here", {}});
    return a;
  }
  try {
    a.program = parse(*a.file);
    a.symbols = index_program(*a.program, a.file->text(), lines);
  } catch (const LanguageError& e) {
    a.diagnostics.push_back(e.diag);
  } catch (const std::exception& e) {
    error_at_start(std::string("internal error while parsing: ") + e.what());
  }
  if (!a.program) {
    a.symbols = std::move(previous);
    a.symbols_stale = true;
  }
  if (a.program && options.evaluate) {
    EvalOptions eo;
    eo.include_paths = options.include_paths;
    eo.limits = options.limits;
    eo.warn_unused = true;
    eo.restrict_reads = true;
    eo.describe_globals = kGlobalValueBytes;
    std::ostringstream ignored;  // the warnings are collected, not printed
    DiagnosticSink sink(ignored);
    sink.collect_into(&a.diagnostics);
    try {
      EvalResult r = evaluate_source(*a.sources, *a.file, eo, sink);
      a.globals = std::move(r.globals);
      a.evaluated = true;
      // The warnings `rts check` and `rts render` show (no lights, camera inside an object...).
      for (const Diagnostic& d : scene_warnings(r, *a.sources, a.file)) a.diagnostics.push_back(d);
    } catch (const LanguageError& e) {
      a.diagnostics.push_back(e.diag);
    } catch (const SourceError& e) {
      error_at_start(e.message);
    } catch (const std::bad_alloc&) {
      error_at_start("out of memory while evaluating the scene");
    } catch (const std::exception& e) {
      error_at_start(std::string("internal error while evaluating: ") + e.what());
    }
  }
  a.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return a;
}

}  // namespace rts::lsp
