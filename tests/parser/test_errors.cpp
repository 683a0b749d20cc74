// Syntax errors: the message in words, where it points, and the notes.
#include <catch2/catch.hpp>

#include "parser_test_support.hpp"

using rts::testing::error_of;
using rts::testing::first_line_of_error;

TEST_CASE("an unclosed block points after the last token and notes where it opened", "[errors]") {
  CHECK(error_of("sphere {\n  radius = 1\n\n  ") ==
        "test.rts:2:13: error: expected '}' to close the block\n"
        "      radius = 1\n"
        "                ^\n"
        "test.rts:1:8: note: to match this '{'\n");
  CHECK(first_line_of_error("let x = 1 +  // comment\n") == "1:24: error: expected an expression after '+'");
}

TEST_CASE("the note names the innermost unclosed bracket", "[errors]") {
  CHECK(error_of("let x = f(1, [2, (3 + 4]") ==
        "test.rts:1:24: error: expected ')' to close the parenthesis\n"
        "    let x = f(1, [2, (3 + 4]\n"
        "                           ^\n"
        "test.rts:1:18: note: to match this '('\n");
  CHECK(error_of("if a {\n  x = [1, 2\n}") ==
        "test.rts:3:1: error: expected ',' or ']' to close the list\n"
        "    }\n"
        "    ^\n"
        "test.rts:2:7: note: to match this '['\n");
}

TEST_CASE("an unterminated string notes its opening quote", "[errors]") {
  CHECK(error_of("include \"a.rts\nlet x = 1") ==
        "test.rts:1:15: error: expected '\"' to close the string (strings cannot span lines)\n"
        "    include \"a.rts\n"
        "                  ^\n"
        "test.rts:1:9: note: to match this '\"'\n");
}

TEST_CASE("errors in the middle point at the offending token", "[errors]") {
  CHECK(first_line_of_error("sphere { radius = 1 + }") == "1:23: error: expected an expression after '+'");
  CHECK(first_line_of_error("let x = 1\nlet y = x * * 2\n") == "2:13: error: expected an expression after '*'");
  CHECK(first_line_of_error("for i in 0..10 {\n  let = 3\n}") == "2:7: error: expected a name after 'let'");
  CHECK(first_line_of_error("a < b < c") == "1:7: error: comparisons cannot be chained; combine them with 'and'");
  CHECK(first_line_of_error("let x = 1 ) ") == "1:11: error: expected a statement, found ')'");
  CHECK(first_line_of_error("let x = 1 @") == "1:11: error: expected a statement, found '@'");
  CHECK(first_line_of_error("let x = 1 \xc3\xa9") == "1:11: error: expected a statement, found '\xc3\xa9'");
  CHECK(first_line_of_error("let x = 1 /* open") == "1:11: error: unterminated block comment (missing '*/')");
  CHECK(first_line_of_error("if x { } else ") == "1:14: error: expected '{' or 'if' after 'else'");
}

TEST_CASE("semantic checks done while parsing", "[errors]") {
  CHECK(error_of("macro f(a = 1, b) { }") ==
        "test.rts:1:16: error: required parameter 'b' follows a parameter with a default value\n"
        "    macro f(a = 1, b) { }\n"
        "                   ^\n"
        "test.rts:1:9: note: the first parameter with a default is here\n");
  CHECK(first_line_of_error("macro f(a, a) { }") == "1:12: error: duplicate parameter 'a'");
  CHECK(first_line_of_error("f(x = 1, 2)") == "1:10: error: positional argument after a named argument");
  CHECK(first_line_of_error("let s = \"\\u{D800}\"") == "1:10: error: '\\u{D800}' is not a valid Unicode code point");
  CHECK(first_line_of_error("let s = \"ab\\u{110000}\"") == "1:12: error: '\\u{110000}' is not a valid Unicode code point");
  CHECK(first_line_of_error("let x = 1e999") == "1:9: error: number '1e999' is too large");
}

TEST_CASE("tiny numbers underflow to zero instead of failing", "[errors]") {
  CHECK(error_of("let x = 1e-999") == "");
}
