#include "import/tokens.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace rts::import {
namespace {

bool is_punct(char c) { return c == '{' || c == '}' || c == '(' || c == ')' || c == ',' || c == ';' || c == '='; }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

std::string trim(std::string s) {
  while (!s.empty() && is_space(s.back())) s.pop_back();
  std::size_t i = 0;
  while (i < s.size() && is_space(s[i])) ++i;
  return s.substr(i);
}

}  // namespace

Tokens::Tokens(const std::string& text) {
  std::size_t i = 0;
  int line = 1, col = 1;
  std::vector<std::string> pending;
  auto advance = [&](std::size_t n) {
    for (std::size_t k = 0; k < n && i < text.size(); ++k, ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
  };
  while (i < text.size()) {
    char c = text[i];
    if (is_space(c)) {
      advance(1);
    } else if (c == '#' || (c == '/' && i + 1 < text.size() && text[i + 1] == '/')) {
      std::size_t start = i + (c == '#' ? 1 : 2);
      std::size_t end = text.find('\n', i);
      if (end == std::string::npos) end = text.size();
      pending.push_back(trim(text.substr(start, end - start)));
      advance(end - i);
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      std::size_t end = text.find("*/", i + 2);
      if (end == std::string::npos) fail(Token{"/*", false, line, col, {}}, "unterminated comment");
      std::string body = text.substr(i + 2, end - i - 2);
      // One comment per line of the block, so it can be written as // lines.
      std::size_t a = 0;
      while (a <= body.size()) {
        std::size_t b = body.find('\n', a);
        if (b == std::string::npos) b = body.size();
        std::string piece = trim(body.substr(a, b - a));
        while (!piece.empty() && piece[0] == '*') piece = trim(piece.substr(1));
        if (!piece.empty()) pending.push_back(piece);
        a = b + 1;
      }
      advance(end + 2 - i);
    } else {
      Token t;
      t.line = line;
      t.col = col;
      t.comments = std::move(pending);
      pending.clear();
      if (c == '"') {
        std::size_t end = text.find('"', i + 1);
        if (end == std::string::npos) fail(t, "unterminated string");
        t.text = text.substr(i + 1, end - i - 1);
        t.string = true;
        advance(end + 1 - i);
      } else if (is_punct(c)) {
        t.text = std::string(1, c);
        advance(1);
      } else {
        std::size_t end = i;
        while (end < text.size() && !is_space(text[end]) && !is_punct(text[end]) && text[end] != '"' &&
               !(text[end] == '/' && end + 1 < text.size() && (text[end + 1] == '/' || text[end + 1] == '*')))
          ++end;
        t.text = text.substr(i, end - i);
        advance(end - i);
      }
      tokens_.push_back(std::move(t));
    }
  }
  end_.line = line;
  end_.col = col;
  end_.comments = std::move(pending);
}

std::string Tokens::fmt_nesting() { return fmt::format("nested more than {} levels deep", kMaxNesting); }

const Token& Tokens::peek() const { return done() ? end_ : tokens_[pos_]; }

Token Tokens::next() {
  if (done()) fail(end_, "unexpected end of file");
  return tokens_[pos_++];
}

void Tokens::fail(const Token& at, const std::string& message) const { throw ImportError(at.line, at.col, message); }

void Tokens::expect(const std::string& text) {
  const Token& t = peek();
  if (done() || t.string || t.text != text)
    fail(t, fmt::format("expected '{}', got {}", text, done() ? "the end of the file" : "'" + t.text + "'"));
  ++pos_;
}

bool Tokens::accept(const std::string& text) {
  if (!peek_is(text)) return false;
  ++pos_;
  return true;
}

double Tokens::number() {
  const Token& t = peek();
  if (done()) fail(t, "expected a number, got the end of the file");
  char* end = nullptr;
  double v = std::strtod(t.text.c_str(), &end);
  if (t.string || t.text.empty() || end != t.text.c_str() + t.text.size() || !std::isfinite(v))
    fail(t, fmt::format("expected a number, got '{}'", t.text));
  ++pos_;
  return v;
}

int Tokens::integer() {
  const Token t = peek();
  double v = number();
  if (v != std::floor(v) || v < 0 || v > 1e9) fail(t, fmt::format("expected a count, got '{}'", t.text));
  return static_cast<int>(v);
}

glm::dvec3 Tokens::vec3() {
  double x = number(), y = number(), z = number();
  return {x, y, z};
}

std::string Tokens::word() {
  const Token& t = peek();
  if (done() || (!t.string && t.text.size() == 1 && is_punct(t.text[0])))
    fail(t, fmt::format("expected a name, got {}", done() ? "the end of the file" : "'" + t.text + "'"));
  return tokens_[pos_++].text;
}

}  // namespace rts::import
