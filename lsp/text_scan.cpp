#include "lsp/text_scan.hpp"

#include <algorithm>

namespace rts::lsp {

namespace {

bool is_continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// Bytes of the UTF-8 sequence starting with `c` (1 for anything malformed).
std::size_t sequence_bytes(unsigned char c) {
  if (c >= 0xF0 && c < 0xF8) return 4;
  if (c >= 0xE0) return c < 0xF0 ? 3 : 1;
  if (c >= 0xC0) return 2;
  return 1;
}

// Skips a comment or string starting at i (text[i] is '/' or '"'); returns the offset after it.
std::size_t skip_comment_or_string(std::string_view text, std::size_t i, bool& was_skipped) {
  was_skipped = true;
  if (text[i] == '"') {
    for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i)
      if (text[i] == '\\') ++i;
    return std::min(text.size(), i + 1);
  }
  if (i + 1 < text.size() && text[i + 1] == '/') {
    std::size_t eol = text.find('\n', i);
    return eol == std::string_view::npos ? text.size() : eol;
  }
  if (i + 1 < text.size() && text[i + 1] == '*') {
    std::size_t close = text.find("*/", i + 2);
    return close == std::string_view::npos ? text.size() : close + 2;
  }
  was_skipped = false;
  return i + 1;
}

}  // namespace

LineIndex::LineIndex(std::string_view text) : text_(text) {
  starts_.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') starts_.push_back(i + 1);
}

std::size_t LineIndex::offset(Position p, bool utf16) const {
  if (starts_.empty()) return 0;
  if (p.line >= starts_.size()) return text_.size();
  std::size_t i = starts_[p.line];
  std::size_t end = p.line + 1 < starts_.size() ? starts_[p.line + 1] - 1 : text_.size();
  if (end > i && text_[end - 1] == '\r') --end;
  uint64_t units = 0;
  while (i < end && units < p.character) {
    std::size_t n = std::min(sequence_bytes(static_cast<unsigned char>(text_[i])), end - i);
    uint64_t w = utf16 ? (n == 4 ? 2 : 1) : n;
    if (units + w > p.character) break;  // inside this character: its start
    units += w;
    i += n;
  }
  return i;
}

Position LineIndex::position(std::size_t offset, bool utf16) const {
  offset = std::min(offset, text_.size());
  if (starts_.empty()) return {};
  std::size_t line = std::upper_bound(starts_.begin(), starts_.end(), offset) - starts_.begin() - 1;
  uint32_t units = 0;
  for (std::size_t i = starts_[line]; i < offset;) {
    std::size_t n = std::min(sequence_bytes(static_cast<unsigned char>(text_[i])), offset - i);
    units += utf16 ? (n == 4 ? 2 : 1) : static_cast<uint32_t>(n);
    i += n;
  }
  return Position{static_cast<uint32_t>(line), units};
}

std::size_t LineIndex::offset_of_loc(uint32_t line, uint32_t col) const {
  if (line == 0 || starts_.empty()) return 0;
  if (line > starts_.size()) return text_.size();
  std::size_t end = line < starts_.size() ? starts_[line] : text_.size();
  return std::min(starts_[line - 1] + (col > 0 ? col - 1 : 0), end);
}

bool is_word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

std::string_view word_at(std::string_view text, std::size_t offset, std::size_t* start) {
  offset = std::min(offset, text.size());
  std::size_t a = offset, b = offset;
  while (a > 0 && is_word_char(text[a - 1])) --a;
  while (b < text.size() && is_word_char(text[b])) ++b;
  if (a == b || (text[a] >= '0' && text[a] <= '9')) return {};
  if (start) *start = a;
  return text.substr(a, b - a);
}

std::size_t token_end(std::string_view text, std::size_t offset) {
  if (offset >= text.size()) return text.size();
  std::size_t i = offset;
  char c = text[i];
  if (is_word_char(c)) {
    while (i < text.size() && (is_word_char(text[i]) || (text[i] == '.' && c >= '0' && c <= '9'))) ++i;
    return i;
  }
  if (c == '"') {
    bool skipped;
    return skip_comment_or_string(text, i, skipped);
  }
  if (is_continuation(static_cast<unsigned char>(c))) return i + 1;
  return std::min(text.size(), i + sequence_bytes(static_cast<unsigned char>(c)));
}

std::size_t matching_close(std::string_view text, std::size_t open) {
  if (open >= text.size()) return text.size();
  std::vector<char> stack;
  for (std::size_t i = open; i < text.size();) {
    char c = text[i];
    if (c == '"' || c == '/') {
      bool skipped;
      i = skip_comment_or_string(text, i, skipped);
      continue;
    }
    if (c == '{' || c == '(' || c == '[') stack.push_back(c);
    if (c == '}' || c == ')' || c == ']') {
      if (!stack.empty()) stack.pop_back();
      if (stack.empty()) return i;
    }
    ++i;
  }
  return text.size();
}

ScanState scan_to(std::string_view text, std::size_t offset) {
  ScanState st;
  offset = std::min(offset, text.size());
  std::string last_word;
  char last = 0;  // the last character that is not a blank ('a' for any word)
  for (std::size_t i = 0; i < offset;) {
    char c = text[i];
    if (c == '"' || c == '/') {
      bool skipped;
      std::size_t after = skip_comment_or_string(text, i, skipped);
      if (skipped && after > offset) {
        // The point is inside it (a line comment's end is its newline: still inside).
        (c == '"' ? st.in_string : st.in_comment) = true;
        break;
      }
      if (skipped && c == '/' && after == offset && text.substr(i, 2) == "//") st.in_comment = true;
      if (skipped && c == '"') last_word.clear();
      i = after;
      continue;
    }
    if (is_word_char(c)) {
      std::size_t b = i;
      while (b < text.size() && is_word_char(text[b])) ++b;
      last_word.assign(text.substr(i, b - i));
      last = 'a';
      i = b;
      continue;
    }
    // A '<' where an operand is expected opens a vector (its commas are not the call's); after
    // an operand it is a comparison.
    const bool opens_vector = c == '<' && !(last == 'a' || last == ')' || last == ']' || last == '>');
    if (c == '{' || c == '(' || c == '[' || opens_vector) {
      st.open.push_back(OpenBracket{c, i, last_word, 0});
    } else if (c == '>' && !st.open.empty() && st.open.back().ch == '<') {
      st.open.pop_back();
    } else if (c == '}' || c == ')' || c == ']') {
      while (!st.open.empty() && st.open.back().ch == '<') st.open.pop_back();  // an unclosed vector
      if (!st.open.empty()) st.open.pop_back();
    } else if (c == ',' && !st.open.empty()) {
      ++st.open.back().commas;
    }
    if (c != ' ' && c != '\t' && c != '\r' && c != '\n') {
      last_word.clear();
      last = c;
    }
    ++i;
  }
  return st;
}

char next_non_blank(std::string_view text, std::size_t offset) {
  for (std::size_t i = offset; i < text.size(); ++i)
    if (text[i] != ' ' && text[i] != '\t') return text[i];
  return 0;
}

char previous_non_blank_on_line(std::string_view text, std::size_t offset) {
  for (std::size_t i = std::min(offset, text.size()); i > 0; --i) {
    char c = text[i - 1];
    if (c == '\n') return 0;
    if (c != ' ' && c != '\t' && c != '\r') return c;
  }
  return 0;
}

}  // namespace rts::lsp
