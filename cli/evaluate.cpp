#include "cli/evaluate.hpp"

#include <iostream>

#include <fmt/format.h>

#include "render/scene/scene.hpp"
#include "runtime/scene_warnings.hpp"

namespace rts::cli {

bool evaluate_reporting(SourceManager& sources, const std::string& path, const EvalOptions& options,
                        DiagnosticSink& sink, EvalResult& out, SceneWarnings warnings) {
  try {
    // A file already added in memory (`rts render scene.pov`: the translation) is evaluated as
    // it is; any other is read from disk.
    const SourceFile* added = sources.find(path);
    out = added ? evaluate_source(sources, *added, options, sink) : evaluate_file(sources, path, options, sink);
    // The same warnings as `rts check`, `rts render` and the language server give.
    if (warnings.report)
      for (const Diagnostic& d : scene_warnings(out, sources, sources.find(path), warnings.integrator)) sink.report(d);
    return true;
  } catch (const LanguageError& e) {
    sink.report(e.diag);
  } catch (const SourceError& e) {
    std::cerr << e.message << "\n";  // already "path: error: ..."
  } catch (const render::SceneError& e) {  // not expected: the evaluator converts these
    print_error(e.where, e.what(), sources, sink);
  }
  return false;
}

void print_error(const render::SourceRef& where, const std::string& message, const SourceManager& sources,
                 DiagnosticSink& sink) {
  if (where.file && *where.file) {
    if (const SourceFile* f = sources.find(where.file)) {
      sink.error(SourceLoc::at(f, where.line, where.col), message);
      return;
    }
    std::cerr << fmt::format("{}:{}:{}: error: {}\n", where.file, where.line, where.col, message);
  } else {
    std::cerr << "rts: error: " << message << "\n";
  }
}

}  // namespace rts::cli
