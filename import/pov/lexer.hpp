// Splits POV-Ray scene text into tokens with the rules of grammar.hpp. Comments are kept and
// attached to the token after them, so the translation can carry them over.
#pragma once

#include <string>
#include <vector>

#include "import/pov/ast.hpp"

namespace rts::import::pov {

struct Token {
  enum Kind { Number, Name, Directive, String, Punct, End };
  Kind kind = End;
  std::string text;    // Directive: the name without '#'; String: the contents as written
  Loc loc;
  std::vector<std::string> comments;
};

// A POV-Ray syntax error, located in the file being read.
struct SyntaxError {
  Loc loc;
  std::string message;
};

// Throws SyntaxError for a character no token starts with, or an unterminated comment/string.
std::vector<Token> tokenize(const std::string& text);

}  // namespace rts::import::pov
