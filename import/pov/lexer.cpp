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

// A comment's text without its markers and surrounding blanks.
std::string comment_text(const std::string& c) {
  std::string s = c.substr(2);
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
        if (!match<grammar::block_comment>(in, m)) throw SyntaxError{at, "unterminated comment: '/*' without '*/'"};
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
      m = m.substr(1, m.size() - 2);
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
