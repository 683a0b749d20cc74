// Helpers for parser tests: parse a string, print its AST, or capture its syntax error.
#pragma once

#include <sstream>
#include <string>

#include "parser/diagnostics.hpp"
#include "parser/parser.hpp"
#include "parser/source.hpp"

namespace rts::testing {

// Keeps the SourceFile alive as long as the AST that points into it.
struct Parsed {
  SourceManager sources;
  const SourceFile* file = nullptr;
  ast::Program program;
};

inline Parsed parse_text(const std::string& text, const std::string& path = "test.rts") {
  Parsed p;
  p.file = p.sources.add(path, text);
  p.program = parse(*p.file);
  return p;
}

inline std::string ast_of(const std::string& text, bool locations = false) {
  Parsed p = parse_text(text);
  std::ostringstream out;
  print_ast(out, p.program, locations);
  return out.str();
}

// The diagnostic a syntax error produces, formatted exactly as `rts parse` prints it.
// Returns "" when the text parses.
inline std::string error_of(const std::string& text, const ParseLimits& limits = {}) {
  SourceManager sources;
  const SourceFile* file = sources.add("test.rts", text);
  try {
    parse(*file, limits);
  } catch (const LanguageError& e) {
    return format_diagnostic(e.diag);
  }
  return "";
}

// Just the first line of the diagnostic without the "test.rts:" prefix, e.g.
// "1:7: error: expected '}' to close the block".
inline std::string first_line_of_error(const std::string& text, const ParseLimits& limits = {}) {
  std::string d = error_of(text, limits);
  std::string first = d.substr(0, d.find('\n'));
  const std::string prefix = "test.rts:";
  if (first.rfind(prefix, 0) == 0) first = first.substr(prefix.size());
  return first;
}

}  // namespace rts::testing
