// What the language server reads from a buffer's text directly, without parsing it: positions
// (LSP's line/character in UTF-16 or UTF-8 units against byte offsets), the word at a point,
// where a token ends, and which brackets are open at a point (the block a cursor is in, the
// call whose arguments it is typing). A buffer being typed rarely parses, so completion and
// signature help work from this; comments and strings are skipped as the grammar skips them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rts::lsp {

struct Position {
  uint32_t line = 0;       // 0-based
  uint32_t character = 0;  // 0-based, in the negotiated units
};

// Line starts of a text, and conversions between byte offsets and LSP positions.
class LineIndex {
 public:
  LineIndex() = default;
  explicit LineIndex(std::string_view text);
  // The byte offset of `p`, clamped into the text: a line past the end is the end, a
  // character past the end of its line is the line's end (LSP says so), and a position inside
  // a UTF-16 surrogate pair or a UTF-8 sequence moves to the character's start.
  std::size_t offset(Position p, bool utf16) const;
  Position position(std::size_t offset, bool utf16) const;
  // The byte offset of a 1-based line and byte column (a SourceLoc), clamped.
  std::size_t offset_of_loc(uint32_t line, uint32_t col) const;
  uint32_t line_count() const { return static_cast<uint32_t>(starts_.size()); }

 private:
  std::string_view text_;
  std::vector<std::size_t> starts_;
};

bool is_word_char(char c);
// The identifier around `offset` (touching it on either side) and where it starts; empty when none.
std::string_view word_at(std::string_view text, std::size_t offset, std::size_t* start = nullptr);
// Where the token starting at `offset` ends: a word, a number, a string, else one character.
std::size_t token_end(std::string_view text, std::size_t offset);
// The offset of the bracket closing the one at `open` (strings and comments skipped), or the
// text's end when it is never closed.
std::size_t matching_close(std::string_view text, std::size_t open);

// A bracket open at some point of the text, innermost last.
struct OpenBracket {
  char ch;              // '{', '(', '[' or '<' (a vector)
  std::size_t offset;   // of the bracket
  std::string head;     // the word just before it ("sphere", "ball", "with", "if"...)
  unsigned commas = 0;  // commas directly inside it before the point
};
struct ScanState {
  std::vector<OpenBracket> open;
  bool in_comment = false;
  bool in_string = false;
};
// Scans from the start to `offset`.
ScanState scan_to(std::string_view text, std::size_t offset);

// The next character at or after `offset` that is not a blank (0 at the end).
char next_non_blank(std::string_view text, std::size_t offset);
// The last character before `offset` that is not a blank, on the same line (0 when none).
char previous_non_blank_on_line(std::string_view text, std::size_t offset);

}  // namespace rts::lsp
