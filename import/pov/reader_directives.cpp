// The POV-Ray reader's #declare and #local, #if/#ifdef/#ifndef, #switch, #while, #for, #macro, #include and the other directives (reader_parser.hpp).
#include <algorithm>
#include <cstdlib>
#include <set>
#include <string>

#include <fmt/format.h>

#include "import/pov/reader_parser.hpp"

namespace rts::import::pov::detail {

void Reader::expect_directive(const char* name, Loc opened, const std::string& what) {
  const Token& t = peek();
  if (t.kind != Token::Directive || t.text != name)
    fail(t.loc, fmt::format("expected '#{}' to close the {} at line {}, got {}", name, what, opened.line,
                            describe(t)));
  next();
}

ExprPtr Reader::paren_expr() {
  expect("(", "after the directive");
  ++paren_;
  ExprPtr e = expr();
  --paren_;
  expect(")", "to close the condition");
  return e;
}

Item Reader::directive() {
  Token t = next();
  Item it;
  it.loc = t.loc;
  it.comments = t.comments;
  const std::string& d = t.text;
  if (d == "declare" || d == "local") {
    it.kind = Item::Declare;
    it.local = d == "local";
    it.name = expect_name("a name after '#" + d + "'");
    declared_.insert(it.name);
    if (is_punct("[")) {  // an array element: #declare A[i] = v, A[i][j] = v: args 1.. the indices
      it.args.resize(1);
      while (accept("[")) {
        ++paren_;
        it.args.push_back(expr());
        --paren_;
        expect("]", "to close the index");
      }
    } else {
      it.args.resize(1);
    }
    expect("=", "after the name in '#" + d + "'");
    if (peek().kind == Token::Name && peek().text == "function") {
      Item f = item(nullptr);
      auto e = std::make_shared<Expr>();
      e->kind = Expr::BlockValue;
      e->loc = f.loc;
      e->block = f.block;
      it.args[0] = e;
    } else if (peek().kind == Token::Name && is_punct("{", 1)) {
      auto e = std::make_shared<Expr>();
      e->kind = Expr::BlockValue;
      e->loc = peek().loc;
      e->block = block();
      if (e->block->kind == "texture" && peek().kind == Token::Name && peek().text == "texture" && is_punct("{", 1)) {
        // A layered texture: `texture { A } texture { B } ...`, B over A (the last on top).
        auto layers = std::make_shared<Block>();
        layers->kind = "layered_texture";
        layers->loc = e->block->loc;
        auto add = [&](std::shared_ptr<Block> b) {
          Item layer;
          layer.kind = Item::Nested;
          layer.loc = b->loc;
          layer.block = std::move(b);
          layers->items.push_back(std::move(layer));
        };
        add(e->block);
        while (peek().kind == Token::Name && peek().text == "texture" && is_punct("{", 1)) add(block());
        e->block = layers;
      }
      it.args[0] = e;
    } else {
      it.args[0] = expr();
    }
    accept(";");
    return it;
  }
  if (d == "macro") {
    it.kind = Item::Macro;
    it.name = expect_name("the macro's name");
    declared_.insert(it.name);
    expect("(", "to open the macro's parameters");
    while (!is_punct(")")) {
      const Loc at = peek().loc;
      std::string name = expect_name("a parameter name");
      // A name twice has no meaning (which argument would it hold?); rts refuses it too.
      if (std::find(it.params.begin(), it.params.end(), name) != it.params.end())
        fail(at, fmt::format("the macro's parameter '{}' is named twice", name));
      it.params.push_back(std::move(name));
      declared_.insert(it.params.back());
      if (!accept(",")) break;
    }
    expect(")", "to close the macro's parameters");
    it.body = body({"end"});
    expect_directive("end", t.loc, "'#macro'");
    return it;
  }
  if (d == "while") {
    it.kind = Item::While;
    it.args.push_back(paren_expr());
    it.body = body({"end", "break"});
    accept_break();
    expect_directive("end", t.loc, "'#while'");
    return it;
  }
  if (d == "for") {
    it.kind = Item::For;
    expect("(", "after '#for'");
    ++paren_;
    it.name = expect_name("the loop variable");
    declared_.insert(it.name);
    expect(",", "after the loop variable");
    it.args.push_back(expr());
    expect(",", "after the start value");
    it.args.push_back(expr());
    if (accept(",")) it.args.push_back(expr());
    --paren_;
    expect(")", "to close '#for'");
    it.body = body({"end", "break"});
    accept_break();
    expect_directive("end", t.loc, "'#for'");
    return it;
  }
  if (d == "if" || d == "ifdef" || d == "ifndef") {
    it.kind = Item::If;
    if (d == "if") {
      it.args.push_back(paren_expr());
    } else {
      expect("(", "after '#" + d + "'");
      auto e = std::make_shared<Expr>();
      e->kind = Expr::Name;
      e->loc = peek().loc;
      e->text = expect_name("a name");
      ExprPtr index;
      if (accept("[")) {  // #ifdef(A[i]): whether that element has been given a value
        index = expr();
        expect("]", "to close the index");
      }
      expect(")", "to close '#" + d + "'");
      it.args.push_back(e);
      if (index) it.args.push_back(index);
      it.ifdef = true;
      it.negate = d == "ifndef";
    }
    it.body = body({"else", "elseif", "end"});
    if (peek().kind == Token::Directive && peek().text == "elseif") {
      // #elseif (c) ... is an #if nested in the #else, closed by the same #end.
      Token e = peek();
      toks_[pos_].text = "if";
      Item inner = directive_elseif(e);
      it.else_body.push_back(std::move(inner));
      return it;
    }
    if (peek().kind == Token::Directive && peek().text == "else") {
      next();
      it.else_body = body({"end"});
    }
    expect_directive("end", t.loc, "'#" + d + "'");
    return it;
  }
  if (d == "switch") {
    it.kind = Item::Switch;
    it.args.push_back(paren_expr());
    while (true) {
      const Token& c = peek();
      if (c.kind != Token::Directive) {
        if (c.kind == Token::End) break;
        fail(c.loc, fmt::format("expected '#case', '#range', '#else' or '#end' in '#switch', got {}", describe(c)));
      }
      if (c.text == "end") break;
      Item cs;
      cs.kind = Item::Case;
      cs.loc = c.loc;
      cs.name = c.text;
      next();
      if (cs.name == "case") {
        cs.args.push_back(paren_expr());
      } else if (cs.name == "range") {
        expect("(", "after '#range'");
        ++paren_;
        cs.args.push_back(expr());
        expect(",", "between the range's ends");
        cs.args.push_back(expr());
        --paren_;
        expect(")", "to close '#range'");
      } else if (cs.name != "else") {
        fail(cs.loc, fmt::format("expected '#case', '#range', '#else' or '#end' in '#switch', got '#{}'", cs.name));
      }
      cs.body = body({"case", "range", "else", "break", "end"});
      accept_break();
      it.body.push_back(std::move(cs));
    }
    expect_directive("end", t.loc, "'#switch'");
    return it;
  }
  if (d == "include") {
    it.kind = Item::Include;
    if (peek().kind != Token::String) {
      // #include Name: a computed file name; the writer warns.
      it.kind = Item::Ignored;
      it.name = "include (a computed name)";
      expr();
      return it;
    }
    it.name = next().text;
    return it;
  }
  if (d == "version") {
    it.kind = Item::Version;
    it.args.push_back(expr());
    accept(";");
    return it;
  }
  if (d == "default") {
    it.kind = Item::Default;
    Loc open = peek().loc;
    expect("{", "after '#default'");
    it.block = std::make_shared<Block>();
    it.block->kind = "default";
    it.block->loc = open;
    it.block->items = items(it.block.get(), {});
    expect("}", "to close '#default'");
    return it;
  }
  if (d == "debug" || d == "warning" || d == "error" || d == "render" || d == "statistics") {
    it.kind = Item::Message;
    it.name = d;
    it.args.push_back(expr());
    return it;
  }
  if (d == "undef") {
    it.kind = Item::Ignored;
    it.name = d;
    expect_name("a name after '#undef'");
    return it;
  }
  if (d == "fopen" || d == "fclose" || d == "read" || d == "write") {
    // File input/output: skipped to the end of the statement (the writer warns).
    it.kind = Item::Ignored;
    it.name = d;
    if (d == "fopen") {
      expect_name("a file identifier");
      if (peek().kind == Token::String) next();
      if (peek().kind == Token::Name) next();
    } else if (d == "fclose") {
      expect_name("a file identifier");
    } else {
      Loc open = peek().loc;
      expect("(", "after '#" + d + "'");
      int depth = 1;
      while (depth > 0) {
        const Token& x = next();
        if (x.kind == Token::End) fail(open, "'(' without ')'");
        if (x.kind == Token::Punct && x.text == "(") ++depth;
        if (x.kind == Token::Punct && x.text == ")") --depth;
      }
    }
    return it;
  }
  if (d == "end" || d == "else" || d == "elseif" || d == "case" || d == "range" || d == "break")
    fail(t.loc, fmt::format("'#{}' without a matching directive before it", d));
  fail(t.loc, fmt::format("unknown directive '#{}'", d));
}

Item Reader::directive_elseif(const Token&) {
  // The current token was renamed to #if: read it as one; its #end closes the outer #if too.
  return directive();
}

void Reader::accept_break() {
  if (peek().kind == Token::Directive && peek().text == "break") next();
}

}  // namespace rts::import::pov::detail
