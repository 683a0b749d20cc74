// The one diagnostics sink. Format (clang's):
//   scene.rts:12:7: error: expected '}' to close the block
//       sphere { radius = 1
//             ^
//   scene.rts:10:1: note: the block opened here
//   main.rts:3:1: note: in file included from here
// Notes come innermost first (the call or include nearest the error first).
#pragma once

#include <exception>
#include <ostream>
#include <string>
#include <vector>

#include "parser/source.hpp"

namespace rts {

enum class Severity { Error, Warning, Note };

struct Note {
  SourceLoc loc;
  std::string message;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLoc loc;
  std::string message;
  std::vector<Note> notes;
};

// Thrown for errors in the scene language: syntax errors from the parser and runtime errors
// from the evaluator. The CLI catches it, reports it through the sink, and exits with
// kExitLanguageError.
struct LanguageError : std::exception {
  Diagnostic diag;
  explicit LanguageError(Diagnostic d) : diag(std::move(d)) {}
  LanguageError(SourceLoc loc, std::string message) {
    diag.loc = loc;
    diag.message = std::move(message);
  }
  const char* what() const noexcept override { return diag.message.c_str(); }
};

class DiagnosticSink {
 public:
  explicit DiagnosticSink(std::ostream& out, bool color = false) : out_(out), color_(color) {}

  void report(const Diagnostic& d);
  void error(SourceLoc loc, const std::string& message);
  void warning(SourceLoc loc, const std::string& message);

  // Also keeps a copy of every diagnostic reported (the language server publishes them as
  // data rather than text); null: print only.
  void collect_into(std::vector<Diagnostic>* out) { collected_ = out; }

  int error_count() const { return errors_; }
  int warning_count() const { return warnings_; }

 private:
  void print_one(Severity sev, SourceLoc loc, const std::string& message, bool with_source);

  std::ostream& out_;
  bool color_;
  int errors_ = 0;
  int warnings_ = 0;
  std::vector<Diagnostic>* collected_ = nullptr;
};

// Renders one diagnostic to a string exactly as the sink prints it (no color); used by the
// golden error tests.
std::string format_diagnostic(const Diagnostic& d);

// Process exit codes, distinct per kind of failure.
inline constexpr int kExitOk = 0;
inline constexpr int kExitLanguageError = 1;  // syntax or runtime error in the scene program
inline constexpr int kExitUsage = 2;          // bad command line
inline constexpr int kExitRenderError = 3;    // the scene is valid but cannot be rendered/written
inline constexpr int kExitInternal = 70;      // a bug in rts (EX_SOFTWARE)

}  // namespace rts
