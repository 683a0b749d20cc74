#include "eval_helpers.hpp"

#include <sstream>

#include <catch2/catch.hpp>

namespace rts::test {

namespace {
SourceManager& sources() {
  static SourceManager s;  // SourceRefs in scenes point into it: keep it for the whole run
  return s;
}
}  // namespace

render::SceneDesc eval_text(const std::string& text, const EvalOptions& options, const std::string& name) {
  std::ostringstream warnings_out;
  DiagnosticSink warnings(warnings_out);
  const SourceFile* f = sources().add(name, text);
  return evaluate_source(sources(), *f, options, warnings).scene;
}

Diagnostic eval_diagnostic(const std::string& text, const EvalOptions& options) {
  try {
    eval_text(text, options);
  } catch (const LanguageError& e) {
    return e.diag;
  }
  FAIL("evaluation succeeded but an error was expected:\n" << text);
  return {};
}

std::string eval_error(const std::string& text, const EvalOptions& options) {
  return format_diagnostic(eval_diagnostic(text, options));
}

std::string dump(const render::SceneDesc& scene) {
  std::ostringstream ss;
  scene.dump(ss);
  return ss.str();
}

std::string eval_warnings(const std::string& text, const EvalOptions& options) {
  std::ostringstream out;
  DiagnosticSink warnings(out);
  const SourceFile* f = sources().add("test.rts", text);
  evaluate_source(sources(), *f, options, warnings);
  return out.str();
}

}  // namespace rts::test
