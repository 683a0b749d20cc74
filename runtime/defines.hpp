// The -D defines: each replaces the value of a top-level `let` of the main file. Parsed up
// front (errors point into a "<define name>" file of their own), handed out as the main file
// runs, and the ones no `let` matched are warned about at the end. Internal to runtime/.
#pragma once

#include <string>
#include <vector>

#include "parser/ast.hpp"
#include "parser/diagnostics.hpp"
#include "runtime/evaluator.hpp"
#include "runtime/includes.hpp"

namespace rts::runtime {

class Defines {
 public:
  // Parses each define as `let name = value`; a located error unless it is a single value.
  void parse(const std::vector<Define>& defines, Includes& files);
  // The expression that replaces the value of the main file's top-level `let name = ...`, or
  // null. The last -D of a name wins (like repeated command-line options); it applies once.
  const ast::Expr* take(ast::Symbol name);
  // Warns about each define that matched no top-level `let` of `main`.
  void warn_unmatched(const SourceFile& main, DiagnosticSink& warnings) const;

 private:
  struct Entry {
    ast::Symbol name;
    const ast::Expr* expr;
    std::string text;  // name=value, as given
    bool used = false;
  };
  std::vector<Entry> entries_;
};

}  // namespace rts::runtime
