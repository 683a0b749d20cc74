// `rts fmt`: scene text in one canonical layout (docs/language.md, "Formatting").
//
// The formatter works on tokens, not on the tree: it keeps every token (comments included)
// in its order and only rewrites the whitespace between them, so a comment stays where it
// was written. The parsed tree tells it what the tokens alone cannot: where each statement
// and property begins, which '-' is unary and which '<' opens a vector. The author's line
// breaks are kept (a packed block stays packed, one property per line stays so); the
// indentation, the spaces inside a line and the blank lines are canonical.
//
// Meaning never changes: the result is parsed again and its tree compared with the
// original's; a difference is reported as an internal error instead of returned.
#pragma once

#include <string>

#include "parser/source.hpp"

namespace rts {

// The formatted text of `file`. Throws LanguageError (located) when the file does not parse;
// throws std::logic_error if the formatted text would parse to a different tree (a bug).
std::string format_source(const SourceFile& file);

}  // namespace rts
