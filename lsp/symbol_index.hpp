// The names a parsed file declares (lets, macros, macro parameters, loop variables) with the
// part of the text where each is visible, its includes and the objects it places: what go to
// definition, document symbols, hover and completion look names up in.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "lsp/text_scan.hpp"
#include "parser/ast.hpp"

namespace rts::lsp {

struct Declaration {
  enum Kind { Let, Macro, Param, LoopVar } kind;
  std::string name;
  std::size_t begin = 0, end = 0;              // the name's bytes
  std::size_t scope_begin = 0, scope_end = 0;  // where it can be named
  std::size_t stmt_begin = 0, stmt_end = 0;    // the whole declaration (a macro with its body)
  bool top_level = false;
  const ast::LetStmt* let = nullptr;      // Let
  const ast::MacroStmt* macro = nullptr;  // Macro, and a Param's macro
};

struct IncludeRef {
  std::string path;             // as written
  std::size_t begin = 0, end = 0;  // the statement's bytes
};

struct PlacedObject {
  std::string kind;  // "sphere", or the macro called
  std::size_t begin = 0, end = 0;
};

struct SymbolIndex {
  std::vector<Declaration> declarations;
  std::vector<IncludeRef> includes;
  std::vector<PlacedObject> objects;  // top-level statements that place something

  // The declaration `name` means at `offset`: the innermost visible one, else nullptr.
  const Declaration* resolve(std::string_view name, std::size_t offset) const;
  // Every declaration visible at `offset` (innermost first, each name once).
  std::vector<const Declaration*> visible_at(std::size_t offset) const;
};

SymbolIndex index_program(const ast::Program& program, std::string_view text, const LineIndex& lines);

// The source text of the macro's header, `name(a, b = 2)`, and its parameters' texts.
std::string macro_signature(const Declaration& macro, std::string_view text, std::vector<std::string>* params);

}  // namespace rts::lsp
