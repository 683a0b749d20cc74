// Reads POV-Ray scene text into a Program (ast.hpp). The reader knows POV-Ray's syntax, not
// its meaning: which keywords take values, where directives go, how expressions bind. The
// writer decides what each block means in rts.
#pragma once

#include <set>
#include <string>

#include "import/pov/ast.hpp"
#include "import/pov/lexer.hpp"

namespace rts::import::pov {

// Throws SyntaxError (located) on text that is not POV-Ray's syntax. `declared` holds the names
// declared so far (an include's names count in the file that includes it) and receives this
// file's: an undeclared lower-case name is read as a keyword, a declared one as a value.
Program read_program(const std::string& text, const std::string& file, std::set<std::string>& declared);

// True for POV-Ray's reserved words that never start a value (modifiers, block kinds,
// options): after a keyword, a following name is read as its value only when it is not one.
bool is_statement_keyword(const std::string& name);

}  // namespace rts::import::pov
