// Parsing scene text into the typed AST. Syntax errors are thrown as LanguageError with the
// location, a message in words, and notes (e.g. where an unclosed bracket opened).
#pragma once

#include <ostream>

#include "parser/ast.hpp"
#include "parser/diagnostics.hpp"
#include "parser/source.hpp"

namespace rts {

struct ParseLimits {
  unsigned max_nesting = 256;  // brackets, blocks and bodies nested deeper are a syntax error
};

ast::Program parse(const SourceFile& file, const ParseLimits& limits = {});

// S-expression dump, one form per node, indented two spaces per level; deterministic.
// With `with_locations`, each form carries @line:col after its head.
void print_ast(std::ostream& out, const ast::Program& program, bool with_locations = false);

}  // namespace rts
