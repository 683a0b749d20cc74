// The rts grammar: PEGTL 3.2 rules, one named rule per struct, no actions. The parser in
// parser/ attaches actions and an error control to these rules; docs/language.md shows the
// same grammar in PEG notation (a test keeps the two in step).
//
//   lexical.hpp      whitespace, comments, names, reserved words, numbers, strings
//   expressions.hpp  the precedence levels, each templated on "blocks allowed"
//   statements.hpp   statements, block bodies, the program
//   errors.hpp       one message per rule that appears under must<>
#pragma once

#include "grammar/lexical.hpp"
#include "grammar/expressions.hpp"
#include "grammar/statements.hpp"
#include "grammar/errors.hpp"
