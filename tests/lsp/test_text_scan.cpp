// lsp/text_scan: positions in UTF-16 and UTF-8 units, clamping, words, open brackets.
#include <catch2/catch.hpp>

#include "lsp/text_scan.hpp"

using namespace rts::lsp;

TEST_CASE("positions: UTF-16 and UTF-8 units against byte offsets", "[text]") {
  const std::string text = "ab\n\xC3\xA9\xF0\x9F\x98\x80x\r\nend";  // é (2 bytes, 1 unit), 😀 (4 bytes, 2 units)
  LineIndex lines(text);
  CHECK(lines.line_count() == 3);
  CHECK(lines.offset({1, 0}, true) == 3);
  CHECK(lines.offset({1, 1}, true) == 5);   // after é
  CHECK(lines.offset({1, 3}, true) == 9);   // after 😀
  CHECK(lines.offset({1, 2}, true) == 5);   // inside the surrogate pair: the character's start
  CHECK(lines.offset({1, 6}, false) == 9);  // UTF-8 units are bytes
  CHECK(lines.position(9, true).character == 3);
  CHECK(lines.position(9, false).character == 6);
  // Out of range: clamped to the line's end (before \r\n) and to the text's end.
  CHECK(lines.offset({1, 999}, true) == 10);
  CHECK(lines.offset({999, 0}, true) == text.size());
  CHECK(lines.offset({2, 1}, true) == 13);
}

TEST_CASE("words, token ends and brackets skip comments and strings", "[text]") {
  const std::string text = "sphere { // {\n  radius = \"{(\" foo(1, bar(2), ";
  CHECK(word_at(text, 3) == "sphere");
  CHECK(word_at(text, 6) == "sphere");  // touching its end
  CHECK(word_at(text, 7).empty());
  CHECK(token_end(text, 0) == 6);
  ScanState st = scan_to(text, text.size());
  REQUIRE(st.open.size() == 2);
  CHECK(st.open[0].head == "sphere");
  CHECK(st.open[1].head == "foo");
  CHECK(st.open[1].commas == 2);
  CHECK(scan_to(text, 12).in_comment);
  CHECK(scan_to(text, 27).in_string);
  CHECK(matching_close("a { b { } \"}\" }", 2) == 14);
}
