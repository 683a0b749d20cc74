// One tokenizer for the three course formats: words (names, numbers, file paths), the
// punctuation { } ( ) , ; = and "strings"; comments (// ..., /* ... */, # ...) are kept and
// attached to the token after them so the translation can carry them over.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "import/import.hpp"

namespace rts::import {

struct Token {
  std::string text;
  bool string = false;                 // came from "..."
  int line = 1, col = 1;
  std::vector<std::string> comments;   // comments just before this token, without markers
};

// Nesting deeper than this (blocks, tuples, groups, transforms) is refused: the translators
// recurse, and a hostile file must not exhaust the stack.
inline constexpr int kMaxNesting = 256;

class Tokens {
 public:
  explicit Tokens(const std::string& text);

  bool done() const { return pos_ >= tokens_.size(); }
  const Token& peek() const;            // the end token at the end of input
  bool peek_is(const std::string& text) const { return !done() && !peek().string && peek().text == text; }
  Token next();
  // Consumes `text` or throws "expected 'text', got 'x'".
  void expect(const std::string& text);
  bool accept(const std::string& text);
  double number();                      // a word that is a finite number
  int integer();
  glm::dvec3 vec3();                    // three numbers
  std::string word();                   // a word or string
  [[noreturn]] void fail(const Token& at, const std::string& message) const;
  // Comments at the end of the file, after the last token.
  const std::vector<std::string>& trailing_comments() const { return end_.comments; }
  // Enter one more level of nesting at `at` (throws past kMaxNesting); leave() on the way out.
  void enter(const Token& at) {
    if (++depth_ > kMaxNesting) fail(at, fmt_nesting());
  }
  void leave() { --depth_; }

 private:
  std::vector<Token> tokens_;
  Token end_;
  std::size_t pos_ = 0;
  int depth_ = 0;
  static std::string fmt_nesting();
};

// Counts one level of nesting for the lifetime of a scope.
struct Nesting {
  Nesting(Tokens& t, const Token& at) : tokens(t) { tokens.enter(at); }
  ~Nesting() { tokens.leave(); }
  Nesting(const Nesting&) = delete;
  Nesting& operator=(const Nesting&) = delete;
  Tokens& tokens;
};

}  // namespace rts::import
