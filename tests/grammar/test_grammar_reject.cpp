// Programs the grammar must reject, with the worded message and the column it points at.
#include <catch2/catch.hpp>

#include "grammar_test_support.hpp"

using rts::grammar::testing::run_grammar;

namespace {

struct Row {
  const char* text;
  const char* message;
  std::size_t line, column;
};

const Row kRejected[] = {
    {"sphere { radius = 1", "expected '}' to close the block", 1, 20},
    {"let x = 1 +", "expected an expression after '+'", 1, 12},
    {"let x = 2 * ", "expected an expression after '*'", 1, 13},
    {"let = 1", "expected a name after 'let'", 1, 5},
    {"let if = 1", "expected a name after 'let'", 1, 5},
    {"let x 1", "expected '=' after the name in 'let'", 1, 7},
    {"let x == 1", "expected '=' after the name in 'let'", 1, 7},
    {"let x =", "expected an expression after '=' in 'let'", 1, 8},
    {"a < b < c", "comparisons cannot be chained; combine them with 'and'", 1, 7},
    {"let x = (1 + 2", "expected ')' to close the parenthesis", 1, 15},
    {"let x = ()", "expected an expression after '('", 1, 10},
    {"let x = [1, 2", "expected ',' or ']' to close the list", 1, 14},
    {"let v = <1>", "expected ',' after the first vector component (vectors have 2 to 4 components)", 1, 11},
    {"let v = <1, 2, 3, 4, 5>", "expected '>' to close the vector (vectors have 2 to 4 components)", 1, 20},
    {"let v = <1, 2", "expected '>' to close the vector (vectors have 2 to 4 components)", 1, 14},
    {"f(1, 2", "expected ',' or ')' to close the argument list", 1, 7},
    {"f(a = )", "expected an expression after '=' in the argument", 1, 7},
    {"let y = xs[", "expected an index expression after '['", 1, 12},
    {"let y = xs[1", "expected ']' to close the index", 1, 13},
    {"let y = v.", "expected a member name after '.'", 1, 11},
    {"let y = m with", "expected '{' after 'with'", 1, 15},
    {"if { }", "expected a condition after 'if'", 1, 4},
    {"if a", "expected '{' to start the body of 'if'", 1, 5},
    {"if a { } else", "expected '{' or 'if' after 'else'", 1, 14},
    {"for in x { }", "expected a loop variable name after 'for'", 1, 5},
    {"for i x { }", "expected 'in' after the loop variable", 1, 7},
    {"for i in { }", "expected a range or list after 'in'", 1, 10},
    {"for i in 0 .. { }", "expected the end of the range after '..'", 1, 15},
    {"for i in 0 .. 1 step { }", "expected an expression after 'step'", 1, 22},
    {"for i in xs", "expected '{' to start the body of 'for'", 1, 12},
    {"while { }", "expected a condition after 'while'", 1, 7},
    {"while x", "expected '{' to start the body of 'while'", 1, 8},
    {"while x { ", "expected '}' to close the body", 1, 11},
    {"macro (a) { }", "expected a macro name after 'macro'", 1, 7},
    {"macro f { }", "expected '(' after the macro name", 1, 9},
    {"macro f(a b) { }", "expected ',' or ')' to close the parameter list", 1, 11},
    {"macro f(a = ) { }", "expected a default value after '='", 1, 13},
    {"macro f(a)", "expected '{' to start the body of 'macro'", 1, 11},
    {"include materials", "expected a file name string after 'include'", 1, 9},
    {"let s = \"abc", "expected '\"' to close the string (strings cannot span lines)", 1, 13},
    {"let s = \"ab\ncd\"", "expected '\"' to close the string (strings cannot span lines)", 1, 12},
    {"let s = \"a\\qb\"", "unknown escape sequence in a string (use \\n \\t \\r \\\\ \\\" \\0 or \\u{...})", 1, 12},
    {"let s = \"\\u41\"", "expected '{' after '\\u' in a string", 1, 12},
    {"let s = \"\\u{}\"", "expected 1 to 6 hexadecimal digits in '\\u{...}'", 1, 13},
    {"let s = \"\\u{1234567}\"", "expected 1 to 6 hexadecimal digits in '\\u{...}'", 1, 13},
    {"let s = \"\\u{12\"", "expected '}' to close '\\u{...}'", 1, 15},
    {"let x = 3x", "unexpected letter right after a number", 1, 10},
    {"let x = 1e", "unexpected letter right after a number", 1, 10},
    // The grammar points just after the `/*` (where the rest was expected); the parser moves
    // the caret back onto the `/*` itself.
    {"let x = 1 /* never closed", "unterminated block comment (missing '*/')", 1, 13},
    {"let x = - ", "expected an expression after '-'", 1, 11},
    {"let x = not", "expected an expression after 'not'", 1, 12},
    {"let x = a and", "expected an expression after 'and'", 1, 14},
    {"let x = a or", "expected an expression after 'or'", 1, 13},
    {"let x = 2 ^", "expected an expression after '^'", 1, 12},
    {"s translate", "expected an expression after 'translate'", 1, 12},
    {"s rotate", "expected an expression after 'rotate'", 1, 9},
    {"sphere { radius = }", "expected an expression after '=' in the property", 1, 19},
    {"x += ", "expected an expression after the assignment operator", 1, 6},
    {")", "expected a statement", 1, 1},
    {"let x = 1 }", "expected a statement", 1, 11},
    {"sphere { radius = 1 ) }", "expected '}' to close the block", 1, 21},
    {"if a { } { }", "expected a statement", 1, 10},
    {"for i in 0..3 {\n  sphere {\n}", "expected '}' to close the body", 3, 2},
};

}  // namespace

TEST_CASE("the grammar rejects malformed programs with a worded message", "[reject]") {
  for (const Row& row : kRejected) {
    SECTION(row.text) {
      auto r = run_grammar(row.text);
      CHECK_FALSE(r.accepted);
      CHECK(r.message == row.message);
      CHECK(r.line == row.line);
      CHECK(r.column == row.column);
    }
  }
}
