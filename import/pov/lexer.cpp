#include "import/pov/lexer.hpp"

#include <fmt/format.h>

#include "import/pov/grammar.hpp"

namespace rts::import::pov {

namespace {

namespace pegtl = tao::pegtl;
using Input = pegtl::memory_input<pegtl::tracking_mode::eager, pegtl::eol::lf_crlf>;

// Matches `Rule` at the input's position; on success `out` is the text it consumed.
template <typename Rule>
bool match(Input& in, std::string& out) {
  const char* start = in.current();
  if (!pegtl::parse<Rule>(in)) return false;
  out.assign(start, in.current());
  return true;
}

Loc here(const Input& in) {
  auto p = in.position();
  return Loc{static_cast<int>(p.line), static_cast<int>(p.column)};
}

// A `/* ... */` comment at the input's position, nested ones inside it (POV-Ray's rule: each
// `/*` needs its own `*/`), scanned once with a depth count. False when it is not closed.
bool block_comment(Input& in, std::string& out) {
  const char* start = in.current();
  const char* p = start + 2;
  const char* end = in.end();
  int depth = 1;
  while (p < end && depth > 0) {
    if (p + 1 < end && p[0] == '/' && p[1] == '*') {
      ++depth;
      p += 2;
    } else if (p + 1 < end && p[0] == '*' && p[1] == '/') {
      --depth;
      p += 2;
    } else {
      ++p;
    }
  }
  if (depth > 0) return false;
  out.assign(start, p);
  in.bump(static_cast<std::size_t>(p - start));
  return true;
}

// Text carried into the translation (comments, strings) as valid UTF-8, which rts requires:
// a byte that does not start a valid UTF-8 sequence is read as Latin-1 (POV-Ray scenes of the
// 1990s often are), and a NUL byte, which rts refuses, becomes a space.
std::string to_utf8(const std::string& s) {
  auto cont = [&](std::size_t i, unsigned char lo = 0x80, unsigned char hi = 0xBF) {
    if (i >= s.size()) return false;
    unsigned char c = static_cast<unsigned char>(s[i]);
    return c >= lo && c <= hi;
  };
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    if (c < 0x80) n = 1;
    else if (c >= 0xC2 && c <= 0xDF && cont(i + 1)) n = 2;
    else if (c == 0xE0 && cont(i + 1, 0xA0) && cont(i + 2)) n = 3;
    else if (((c >= 0xE1 && c <= 0xEC) || c == 0xEE || c == 0xEF) && cont(i + 1) && cont(i + 2)) n = 3;
    else if (c == 0xED && cont(i + 1, 0x80, 0x9F) && cont(i + 2)) n = 3;
    else if (c == 0xF0 && cont(i + 1, 0x90) && cont(i + 2) && cont(i + 3)) n = 4;
    else if (c >= 0xF1 && c <= 0xF3 && cont(i + 1) && cont(i + 2) && cont(i + 3)) n = 4;
    else if (c == 0xF4 && cont(i + 1, 0x80, 0x8F) && cont(i + 2) && cont(i + 3)) n = 4;
    if (n == 0) {  // Latin-1
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
      ++i;
      continue;
    }
    if (c == 0) out += ' ';
    else out.append(s, i, n);
    i += n;
  }
  return out;
}

// A comment's text without its markers and surrounding blanks.
std::string comment_text(const std::string& c) {
  std::string s = to_utf8(c.substr(2));
  if (c[1] == '*') s = s.substr(0, s.size() >= 2 ? s.size() - 2 : 0);
  std::size_t b = s.find_first_not_of(" \t\r\n");
  std::size_t e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

}  // namespace

std::vector<Token> tokenize(const std::string& text) {
  Input in(text.data(), text.size(), "pov");
  std::vector<Token> out;
  std::vector<std::string> comments;
  std::string m;
  Loc after_last{1, 1};  // just after the last token: where "the end of the file" is shown
  while (true) {
    // Whitespace and comments.
    while (!in.empty()) {
      if (match<grammar::space_char>(in, m)) continue;
      if (in.size(2) >= 2 && in.peek_char(0) == '/' && in.peek_char(1) == '*') {
        Loc at = here(in);
        if (!block_comment(in, m)) throw SyntaxError{at, "unterminated comment: '/*' without '*/'"};
        // A long block comment (a licence header) is kept only in its first lines.
        std::string c = comment_text(m);
        for (std::size_t start = 0, lines = 0; start <= c.size() && lines < 40; ++lines) {
          std::size_t nl = c.find('\n', start);
          std::string line = c.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
          while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
          comments.push_back(line);
          if (nl == std::string::npos) break;
          start = nl + 1;
        }
        continue;
      }
      if (match<grammar::line_comment>(in, m)) {
        comments.push_back(comment_text(m));
        continue;
      }
      break;
    }
    Token t;
    t.loc = here(in);
    t.comments = std::move(comments);
    comments.clear();
    if (in.empty()) {
      t.kind = Token::End;
      t.loc = after_last;
      out.push_back(std::move(t));
      return out;
    }
    if (match<grammar::number>(in, m)) {
      t.kind = Token::Number;
    } else if (match<grammar::name>(in, m)) {
      t.kind = Token::Name;
    } else if (match<grammar::directive>(in, m)) {
      t.kind = Token::Directive;
      std::size_t i = 1;
      while (i < m.size() && (m[i] == ' ' || m[i] == '\t')) ++i;
      m = m.substr(i);
    } else if (in.peek_char() == '"') {
      if (!match<grammar::string_literal>(in, m)) throw SyntaxError{t.loc, "unterminated string: '\"' without a closing '\"' on its line"};
      t.kind = Token::String;
      m = to_utf8(m.substr(1, m.size() - 2));
    } else if (match<grammar::punctuation>(in, m)) {
      t.kind = Token::Punct;
    } else {
      unsigned char c = static_cast<unsigned char>(in.peek_char());
      throw SyntaxError{t.loc, c >= 0x20 && c < 0x7f ? fmt::format("unexpected character '{}'", char(c))
                                                     : fmt::format("unexpected byte 0x{:02x}", c)};
    }
    t.text = m;
    after_last = here(in);
    out.push_back(std::move(t));
  }
}

}  // namespace rts::import::pov
