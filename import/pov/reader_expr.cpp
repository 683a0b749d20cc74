// The POV-Ray reader's expressions: POV-Ray's operators and their binding, vectors, colour keywords, calls (reader_parser.hpp).
#include <cstdlib>
#include <set>
#include <string>

#include <fmt/format.h>

#include "import/pov/reader_parser.hpp"

namespace rts::import::pov::detail {

ExprPtr Reader::make(Expr::Kind k, Loc at, std::string text) {
  auto e = std::make_shared<Expr>();
  e->kind = k;
  e->loc = at;
  e->text = std::move(text);
  return e;
}

ExprPtr Reader::binary(const std::string& op, ExprPtr a, ExprPtr b, Loc at) {
  ExprPtr e = make(Expr::Binary, at, op);
  e->args = {std::move(a), std::move(b)};
  return e;
}

ExprPtr Reader::expr() {
  Deeper d(*this, peek().loc);
  ExprPtr c = or_expr();
  if (paren_ > 0 && is_punct("?")) {
    Loc at = next().loc;
    ExprPtr a = expr();
    expect(":", "in 'condition ? a : b'");
    ExprPtr b = expr();
    ExprPtr e = make(Expr::Ternary, at);
    e->args = {c, a, b};
    return e;
  }
  return c;
}

ExprPtr Reader::or_expr() {
  ExprPtr a = and_expr();
  while (paren_ > 0 && is_punct("|")) {
    Loc at = next().loc;
    a = binary("|", a, and_expr(), at);
  }
  return a;
}

ExprPtr Reader::and_expr() {
  ExprPtr a = cmp_expr();
  while (paren_ > 0 && is_punct("&")) {
    Loc at = next().loc;
    a = binary("&", a, cmp_expr(), at);
  }
  return a;
}

ExprPtr Reader::cmp_expr() {
  ExprPtr a = add_expr();
  while (paren_ > 0 && (is_punct("<") || is_punct("<=") || is_punct("=") || is_punct("!=") || is_punct(">=") ||
                        is_punct(">"))) {
    Token op = next();
    a = binary(op.text, a, add_expr(), op.loc);
  }
  return a;
}

ExprPtr Reader::add_expr() {
  ExprPtr a = mul_expr();
  while (is_punct("+") || is_punct("-")) {
    Token op = next();
    a = binary(op.text, a, mul_expr(), op.loc);
  }
  return a;
}

ExprPtr Reader::mul_expr() {
  ExprPtr a = unary_expr();
  while (is_punct("*") || is_punct("/")) {
    Token op = next();
    a = binary(op.text, a, unary_expr(), op.loc);
  }
  return a;
}

ExprPtr Reader::unary_expr() {
  Deeper d(*this, peek().loc);
  if (is_punct("-") || is_punct("+") || is_punct("!")) {
    Token op = next();
    ExprPtr e = make(Expr::Unary, op.loc, op.text);
    e->args.push_back(unary_expr());
    return e;
  }
  return postfix_expr();
}

ExprPtr Reader::postfix_expr() {
  ExprPtr e = primary();
  while (true) {
    if (is_punct(".") && peek(1).kind == Token::Name) {
      Loc at = next().loc;
      ExprPtr m = make(Expr::Member, at, next().text);
      m->args.push_back(e);
      e = m;
    } else if (is_punct("[") && e->kind != Expr::Number) {
      Loc at = next().loc;
      ExprPtr i = make(Expr::Index, at);
      ++paren_;
      i->args = {e, expr()};
      --paren_;
      expect("]", "to close the index");
      e = i;
    } else {
      return e;
    }
  }
}

bool Reader::is_color_keyword(const std::string& n) {
  return n == "rgb" || n == "rgbf" || n == "rgbt" || n == "rgbft" || n == "srgb" || n == "srgbf" ||
         n == "srgbt" || n == "srgbft";
}

ExprPtr Reader::primary() {
  const Token& t = peek();
  Loc at = t.loc;
  switch (t.kind) {
    case Token::Number: {
      ExprPtr e = make(Expr::Number, at, t.text);
      e->number = std::strtod(t.text.c_str(), nullptr);
      next();
      return e;
    }
    case Token::String: {
      ExprPtr e = make(Expr::String, at, t.text);
      next();
      return e;
    }
    case Token::Punct:
      if (t.text == "(") {
        next();
        ++paren_;
        ExprPtr e = expr();
        --paren_;
        expect(")", "to close '('");
        return e;
      }
      if (t.text == "<") {
        next();
        ExprPtr e = make(Expr::Vector, at);
        int saved = paren_;
        paren_ = 0;
        // Components may go without commas (<4 0 0>) and end with one (<1, 2, 3,>).
        e->args.push_back(expr());
        while (!is_punct(">")) {
          bool comma = accept(",");
          if (is_punct(">")) break;
          if (!comma && !starts_value()) break;
          e->args.push_back(expr());
        }
        paren_ = saved;
        if (!accept(">"))
          fail(peek().loc, fmt::format("expected ',' or '>' in the vector opened at line {}:{}, got {}", at.line,
                                       at.col, describe(peek())));
        // POV-Ray's vectors have 2 to 5 components (a one-component <x> was written to rts,
        // which cannot read it: fuzz_pov); a poly's coefficients up to 84.
        const std::size_t most = long_vectors_ ? kMaxPolyCoefficients : 5;
        if (e->args.size() < 2 || e->args.size() > most)
          fail(at, fmt::format("a vector has 2 to {} components, this one {}", most, e->args.size()));
        return e;
      }
      break;
    case Token::Name: {
      std::string n = next().text;
      if (is_color_keyword(n)) {
        ExprPtr e = make(Expr::Color, at, n);
        e->args.push_back(unary_expr());
        return e;
      }
      if (n == "color" || n == "colour") {
        ExprPtr e = make(Expr::Color, at, "color");
        if (peek().kind == Token::Name && (peek().text == "red" || peek().text == "green" ||
                                           peek().text == "blue" || peek().text == "filter" ||
                                           peek().text == "transmit" || peek().text == "alpha")) {
          // The old form: color red R green G blue B (missing channels are 0).
          ExprPtr v = make(Expr::Vector, peek().loc);
          for (int i = 0; i < 5; ++i) {
            ExprPtr zero = make(Expr::Number, at, "0");
            v->args.push_back(zero);
          }
          while (peek().kind == Token::Name) {
            const std::string c = peek().text;
            int slot = c == "red" ? 0 : c == "green" ? 1 : c == "blue" ? 2 : c == "filter" ? 3
                     : (c == "transmit" || c == "alpha") ? 4 : -1;
            if (slot < 0) break;
            next();
            v->args[static_cast<std::size_t>(slot)] = unary_expr();
          }
          e->text = "rgbft";
          e->args.push_back(v);
          return e;
        }
        e->args.push_back(add_expr());
        // `color Black transmit 0.6`: channels set after the colour (each an extra argument,
        // a Call named for its channel).
        while (peek().kind == Token::Name && (peek().text == "filter" || peek().text == "transmit") &&
               !is_punct("{", 1)) {
          ExprPtr channel = make(Expr::Call, peek().loc, next().text);
          channel->args.push_back(unary_expr());
          e->args.push_back(channel);
        }
        return e;
      }
      if (n == "array") {
        ExprPtr e = make(Expr::Array, at);
        std::vector<ExprPtr> sizes;
        while (is_punct("[")) {
          next();
          sizes.push_back(expr());
          expect("]", "to close the array's size");
        }
        if (sizes.empty()) fail(at, "'array' needs its size in brackets: array[N] (or array[N] { values })");
        // POV-Ray's limit; it also bounds the recursion that reads nested initial values.
        if (sizes.size() > 5) fail(at, fmt::format("an array has at most 5 dimensions, this one {}", sizes.size()));
        // An element: a value, or a block (`texture { ... }`).
        auto element = [&]() -> ExprPtr {
          if (peek().kind == Token::Name && is_punct("{", 1)) {
            ExprPtr b = make(Expr::BlockValue, peek().loc);
            b->block = block();
            return b;
          }
          return expr();
        };
        if (sizes.size() != 1) {
          // A multi-dimensional array: its sizes, or its initial values as nested rows
          // (`array[2][3] { {a, b, c}, {d, e, f} }`: args[0], text "rows" at each level).
          e->text = "multi";
          e->args = std::move(sizes);
          if (is_punct("{")) {
            const std::size_t dims = e->args.size();
            auto rows = [&](auto& self, std::size_t dim) -> ExprPtr {
              ExprPtr r = make(Expr::Array, peek().loc);
              r->text = "rows";
              expect("{", "to open the array's values");
              while (!is_punct("}")) {
                r->args.push_back(dim + 1 < dims ? self(self, dim + 1) : element());
                if (!accept(",")) break;
              }
              expect("}", "to close the array's values");
              return r;
            };
            e->text = "multi init";
            e->args = {rows(rows, 0)};
          }
          return e;
        }
        e->args.push_back(sizes[0]);
        if (accept("{")) {
          e->text = "init";
          while (!is_punct("}")) {
            e->args.push_back(element());
            if (!accept(",")) break;
          }
          expect("}", "to close the array's values");
        }
        return e;
      }
      if (is_punct("(")) {
        next();
        ExprPtr e = make(Expr::Call, at, n);
        ++paren_;
        while (!is_punct(")")) {
          if (peek().kind == Token::Name && is_punct("{", 1)) {
            ExprPtr b = make(Expr::BlockValue, peek().loc);
            b->block = block();
            e->args.push_back(b);
          } else {
            e->args.push_back(expr());
          }
          if (!accept(",")) break;
        }
        --paren_;
        expect(")", "to close the call's arguments");
        return e;
      }
      return make(Expr::Name, at, n);
    }
    default: break;
  }
  fail(at, fmt::format("expected a value, got {}", describe(t)));
}

}  // namespace rts::import::pov::detail
