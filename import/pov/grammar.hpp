// POV-Ray's scene language, lexical level: the tokens the reader (reader.cpp) builds its
// syntax tree from. PEGTL rules only, one named rule per struct, no actions (as grammar/).
//
// POV-Ray's syntax above the tokens is keyword-driven (a keyword decides how many values
// follow, modifiers come in any order, directives may appear between any two tokens), so the
// structure is read by a recursive-descent reader over these tokens rather than by one PEG.
#pragma once

#include <tao/pegtl.hpp>

namespace rts::import::pov::grammar {

namespace pegtl = tao::pegtl;
using pegtl::alpha;
using pegtl::any;
using pegtl::digit;
using pegtl::eof;
using pegtl::eolf;
using pegtl::identifier_other;
using pegtl::not_at;
using pegtl::not_one;
using pegtl::one;
using pegtl::opt;
using pegtl::plus;
using pegtl::seq;
using pegtl::sor;
using pegtl::star;
using pegtl::string;
using pegtl::until;

// Whitespace: POV-Ray also accepts form feeds and DOS end-of-file marks (0x1a).
struct space_char : one<' ', '\t', '\r', '\n', '\f', '\v', '\x1a'> {};
// `// to the end of the line`
struct line_comment : seq<string<'/', '/'>, until<eolf>> {};
// `/* block */` comments nest in POV-Ray; the lexer scans them with a depth count (a PEG rule
// here retried every unterminated inner comment as text: exponential in their number).

// A number: 12, 1.5, .5, 1e-3, 2.E4 (no sign: unary minus is an operator).
struct exponent : seq<one<'e', 'E'>, opt<one<'+', '-'>>, plus<digit>> {};
struct fraction : seq<one<'.'>, star<digit>> {};
struct number_with_int : seq<plus<digit>, opt<fraction>, opt<exponent>> {};
struct number_with_dot : seq<one<'.'>, plus<digit>, opt<exponent>> {};
struct number : sor<number_with_int, number_with_dot> {};

// Names (identifiers and keywords alike: the reader tells them apart).
struct name : seq<sor<alpha, one<'_'>>, star<identifier_other>> {};

// A directive: `#declare`, `# declare` (POV-Ray allows the space).
struct directive : seq<one<'#'>, star<one<' ', '\t'>>, name> {};

// "strings" with backslash escapes, on one line.
struct string_escape : seq<one<'\\'>, any> {};
struct string_char : sor<string_escape, not_one<'"', '\n'>> {};
struct string_literal : seq<one<'"'>, star<string_char>, one<'"'>> {};

// Two-character operators first, so that `<=` is not `<` then `=`.
struct operator2 : sor<string<'<', '='>, string<'>', '='>, string<'!', '='>> {};
struct operator1 : one<'{', '}', '(', ')', '[', ']', '<', '>', ',', ';', '=', '+', '-', '*', '/', '.', '?', ':',
                       '!', '&', '|'> {};
struct punctuation : sor<operator2, operator1> {};

// One token (after the reader skipped whitespace and comments).
struct token : sor<number, name, directive, string_literal, punctuation> {};

}  // namespace rts::import::pov::grammar
