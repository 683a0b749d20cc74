// The state the parser's actions share while PEGTL walks the grammar: one value stack per
// kind of AST piece, and the open brackets. Actions push finished pieces; the action of the
// enclosing rule pops them and pushes the node built from them (a manual value stack: no
// std::function, no parse tree). The grammar only backtracks over rules that fired no
// action (every action-bearing construct commits with must<> after its first token), so
// the stacks never hold pieces of an abandoned alternative.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "grammar/lexical.hpp"
#include "parser/ast.hpp"
#include "parser/diagnostics.hpp"
#include "parser/parser.hpp"
#include "parser/source.hpp"

namespace rts::parse_detail {

// Deepest syntax tree the parser builds (operator chains such as 1+1+...+1 included):
// everything that walks the tree afterwards (printer, evaluator, destructors) recurses, so
// the tree height is capped to keep their stacks safe. Each level of bracket nesting adds
// up to about three levels of tree, so a larger nesting limit raises the cap with it.
inline constexpr uint32_t kMaxTreeHeight = 1024;
inline constexpr uint32_t kTreeLevelsPerNesting = 4;

// A piece on a value stack, with the height of the subtree it roots.
template <typename T>
struct Sized {
  T node;
  uint32_t height;
};

struct NamePiece {
  ast::Symbol name;
  SourceLoc loc;
};

// An open bracket (or string quote) whose closer has not been seen yet: for the "to match
// this '{'" note, and the stack size to collect the bracket's children from.
struct Open {
  SourceLoc loc;
  uint32_t mark;
  char ch;
};

struct ParseState {
  ParseState(const SourceFile& f, const ParseLimits& l)
      : file(&f),
        limits(l),
        max_height(std::max(kMaxTreeHeight, kTreeLevelsPerNesting * l.max_nesting)),
        arena(std::make_unique<ast::NodeArena>(f.text().size())) {}

  const SourceFile* file;
  ParseLimits limits;
  uint32_t max_height;  // of the syntax tree
  uint32_t depth = 0;  // current nesting of brackets, bodies and prefix operators

  // The nodes' memory, handed to the Program at the end.
  std::unique_ptr<ast::NodeArena> arena;
  std::vector<Sized<ast::ExprPtr>> exprs;
  std::vector<Sized<ast::StmtPtr>> stmts;  // statements inside brackets, to be collected
  std::vector<ast::StmtPtr> top_level;     // the program's own statements, in order
  std::vector<Sized<ast::BlockItemPiece>> items;
  std::vector<Sized<ast::ArgumentPiece>> args;
  std::vector<Sized<ast::ParamPiece>> params;
  std::vector<Sized<ast::ListPiece<ast::Param>>> param_lists;
  std::vector<Sized<ast::BodyPiece>> bodies;
  std::vector<Sized<ast::BlockBodyPiece>> block_bodies;
  std::vector<NamePiece> names;
  std::vector<Open> opens;

  // Optional parts announce themselves to the action of the rule that contains them; each
  // flag is set by the optional part and consumed by the very next enclosing action.
  bool has_step = false;
  bool has_else = false;
  bool has_default = false;
  bool has_return_value = false;
  ast::AssignOp assign_op = ast::AssignOp::Set;  // the operator just matched
  // Operators of the assignments whose value is being parsed (the value may itself hold an
  // assignment, inside a block's if body).
  std::vector<ast::AssignOp> assign_ops;
  std::string_view string_body;  // raw text between the quotes of the last string
  SourceLoc string_body_loc;
  std::string include_path;

  // A small cache of interned names by spelling (views into file->text()), direct-mapped by
  // the name's hash: the names a scene repeats (properties, materials) are found without the
  // symbol table's lock; a name seen once costs the cache nothing (issue 24: a per-parse map
  // of every distinct name was 56 bytes a name and a cache miss a lookup).
  struct CachedSymbol {
    const char* spelling = nullptr;
    uint32_t size = 0;
    ast::Symbol symbol;
  };
  static constexpr std::size_t kSymbolCache = 1024;
  std::unique_ptr<CachedSymbol[]> symbols = std::make_unique<CachedSymbol[]>(kSymbolCache);

  // The location of a character of the text being parsed.
  SourceLoc loc(const char* at) const {
    return SourceLoc::at_offset(file, static_cast<std::size_t>(at - file->text().data()));
  }

  ast::Symbol symbol(std::string_view spelling) {
    const uint32_t hash = ast::symbol_hash(spelling);
    CachedSymbol& c = symbols[hash & (kSymbolCache - 1)];
    if (c.size == spelling.size() && c.spelling && std::memcmp(c.spelling, spelling.data(), c.size) == 0)
      return c.symbol;
    c = {spelling.data(), static_cast<uint32_t>(spelling.size()), ast::intern(spelling, hash)};
    return c.symbol;
  }
};

// The identifier at the start of a matched rule (rules include the whitespace after them).
inline std::string_view word_at(const char* begin, const char* end) {
  const char* p = begin;
  while (p != end && grammar::is_ident_char(*p)) ++p;
  return {begin, static_cast<std::size_t>(p - begin)};
}

}  // namespace rts::parse_detail
