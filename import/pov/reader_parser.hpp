// The POV-Ray reader's parser (reader.hpp's read_program), shared by the files that define its
// parts: reader.cpp (tokens, items, blocks), reader_directives.cpp (#declare, #if, #while,
// #macro ...) and reader_expr.cpp (expressions). Private to import/pov.
#pragma once

#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "import/pov/ast.hpp"
#include "import/pov/lexer.hpp"
#include "import/pov/reader.hpp"

namespace rts::import::pov::detail {

// Blocks and directives nest at most this deep: the reader and the writer recurse, and a
// hostile file must not exhaust the stack.
inline constexpr int kMaxNesting = 200;

// Blocks whose contents are POV-Ray's function or spline syntax: skipped as a whole (the
// writer warns), never read as items.
bool is_raw_block(const std::string& kind);
// Names that begin a value without being declared: constants and built-in functions.
bool is_builtin_value(const std::string& n);
bool all_lowercase(const std::string& n);

class Reader {
 public:
  Reader(const std::string& text, std::set<std::string>& declared) : toks_(tokenize(text)), declared_(declared) {}

  Program program(const std::string& file) {
    Program p;
    p.file = file;
    p.items = items(nullptr, {});
    if (peek().kind != Token::End) {
      const Token& t = peek();
      if (t.kind == Token::Directive) fail(t.loc, fmt::format("'#{}' without a matching directive before it", t.text));
      fail(t.loc, fmt::format("unexpected '{}'", t.text));
    }
    p.trailing_comments = peek().comments;
    return p;
  }

 private:
  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  std::set<std::string>& declared_;  // names declared so far (this file and earlier ones)
  int depth_ = 0;
  // Inside parentheses (a condition, a call's arguments, an index): POV-Ray reads comparisons,
  // & | and ?: only there, so `box { <a> <b> }` is two vectors, not a comparison. A vector's
  // components are outside again.
  int paren_ = 0;
  // Inside a poly, quartic or cubic block: a vector may hold its coefficients (order 6: 84).
  bool long_vectors_ = false;
  static constexpr std::size_t kMaxPolyCoefficients = 84;

  // ---- tokens ----
  const Token& peek(std::size_t ahead = 0) const {
    std::size_t i = std::min(pos_ + ahead, toks_.size() - 1);
    return toks_[i];
  }
  Token next() {
    Token t = peek();
    if (pos_ < toks_.size() - 1) ++pos_;
    return t;
  }
  bool is_punct(const char* p, std::size_t ahead = 0) const {
    const Token& t = peek(ahead);
    return t.kind == Token::Punct && t.text == p;
  }
  bool accept(const char* p) {
    if (!is_punct(p)) return false;
    next();
    return true;
  }
  [[noreturn]] static void fail(Loc at, const std::string& message) { throw SyntaxError{at, message}; }
  static std::string describe(const Token& t) {
    switch (t.kind) {
      case Token::End: return "the end of the file";
      case Token::Directive: return "'#" + t.text + "'";
      case Token::String: return "a string";
      default: return "'" + t.text + "'";
    }
  }
  void expect(const char* p, const std::string& what) {
    if (!accept(p)) fail(peek().loc, fmt::format("expected '{}' {}, got {}", p, what, describe(peek())));
  }
  std::string expect_name(const std::string& what) {
    if (peek().kind != Token::Name) fail(peek().loc, fmt::format("expected {}, got {}", what, describe(peek())));
    return next().text;
  }
  struct Deeper {
    Reader& r;
    Deeper(Reader& reader, Loc at) : r(reader) {
      if (++r.depth_ > kMaxNesting) fail(at, fmt::format("nesting too deep (more than {} levels)", kMaxNesting));
    }
    ~Deeper() { --r.depth_; }
  };

  // Whether the next token can begin a value (after a keyword: is what follows its value?).
  bool starts_value() const {
    const Token& t = peek();
    switch (t.kind) {
      case Token::Number:
      case Token::String: return true;
      case Token::Punct: return t.text == "<" || t.text == "(" || t.text == "-" || t.text == "+" || t.text == "!";
      case Token::Name: return name_is_value(t.text);
      default: return false;
    }
  }

  // A name begins a value when declared, built in, or spelled like an identifier (POV-Ray's
  // keywords are lower case); an undeclared lower-case name is a keyword rts may not know.
  bool name_is_value(const std::string& n) const {
    if (is_punct("{", 1)) return false;
    if (declared_.count(n) || is_builtin_value(n)) return true;
    if (is_statement_keyword(n)) return false;
    return !all_lowercase(n) || is_punct("(", 1);
  }


  // ---- items ----
  // Reads items until '}' (in a block), the end of the file, or one of the directives in
  // `stops` (not consumed).
  std::vector<Item> items(const Block* in_block, std::set<std::string> stops);

  Item item(const Block* in_block);

  std::shared_ptr<Block> block();

  // What comes between `function` and its body: the parameters `(a, b, c)` (a Keyword item
  // "params", Name arguments) or a height field's resolution `W, H` (Keyword "resolution").
  // Anything else up to the body is skipped, as before.
  void function_header(Block& f);

  // A function's body `{ expression }` as the block's Value item, when it reads as one
  // expression of the scene language (arithmetic, calls, x, y, z); otherwise (POV-Ray's
  // function-only syntax, a pattern { } inside) skipped, and the block has no body.
  void function_body(Block& f);

  // Skips a balanced { ... } starting at the current '{'.
  void skip_braces();

  // ---- directives ----
  std::vector<Item> body(std::set<std::string> stops) { return items(nullptr, std::move(stops)); }

  void expect_directive(const char* name, Loc opened, const std::string& what);

  ExprPtr paren_expr();

  Item directive();

  Item directive_elseif(const Token&);

  void accept_break();

  // ---- expressions ----
  ExprPtr make(Expr::Kind k, Loc at, std::string text = {});
  ExprPtr binary(const std::string& op, ExprPtr a, ExprPtr b, Loc at);

  ExprPtr expr();
  ExprPtr or_expr();
  ExprPtr and_expr();
  ExprPtr cmp_expr();
  ExprPtr add_expr();
  ExprPtr mul_expr();
  ExprPtr unary_expr();
  ExprPtr postfix_expr();
  static bool is_color_keyword(const std::string& n);
  ExprPtr primary();
};

}  // namespace rts::import::pov::detail
