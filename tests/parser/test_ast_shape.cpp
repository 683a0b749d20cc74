// The AST the parser builds, checked through its S-expression print (the format is in
// docs/language.md) and, for a few nodes, through the typed fields directly.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "parser_test_support.hpp"

using rts::testing::ast_of;
using rts::testing::parse_text;
namespace ast = rts::ast;

namespace {
// The body of "(program\n  X)" for a one-statement program.
std::string one(const std::string& text) {
  std::string printed = ast_of(text);
  const std::string head = "(program\n  ";
  REQUIRE(printed.rfind(head, 0) == 0);
  REQUIRE(printed.size() >= head.size() + 2);
  return printed.substr(head.size(), printed.size() - head.size() - 2);  // drop ")\n"
}
}  // namespace

TEST_CASE("empty input is an empty program", "[ast]") {
  CHECK(ast_of("") == "(program)\n");
  CHECK(ast_of("  // only a comment\n/* and another */ ;;") == "(program)\n");
}

TEST_CASE("literals", "[ast]") {
  CHECK(one("1") == "(expr 1)");
  CHECK(one("1.5") == "(expr 1.5)");
  CHECK(one(".5") == "(expr 0.5)");
  CHECK(one("1e-3") == "(expr 0.001)");
  CHECK(one("2.5E+4") == "(expr 25000)");
  CHECK(one("0.1") == "(expr 0.1)");
  CHECK(one("true") == "(expr true)");
  CHECK(one("false") == "(expr false)");
  CHECK(one("none") == "(expr none)");
  CHECK(one("\"hi\"") == "(expr \"hi\")");
}

TEST_CASE("string escapes are decoded in the AST and re-escaped in the print", "[ast]") {
  auto p = parse_text(R"(let s = "a\nb\t\"q\" \\ \u{41}\u{e9}\u{1F600}")");
  auto& let = static_cast<ast::LetStmt&>(*p.program.stmts().at(0));
  auto& str = static_cast<ast::StringExpr&>(*let.value);
  CHECK(str.value == "a\nb\t\"q\" \\ A\xc3\xa9\xf0\x9f\x98\x80");
  CHECK(one(R"(let s = "a\nb\0c\rd")") == R"((let s "a\nb\0c\rd"))");
  auto nul = parse_text(R"(let s = "x\0y")");
  CHECK(static_cast<ast::StringExpr&>(*static_cast<ast::LetStmt&>(*nul.program.stmts()[0]).value).value ==
        std::string("x\0y", 3));
}

TEST_CASE("let, assignment and compound assignment", "[ast]") {
  CHECK(one("let x = 1") == "(let x 1)");
  CHECK(one("x = 2") == "(assign x = 2)");
  CHECK(one("n += 1") == "(assign n += 1)");
  CHECK(one("n -= 1") == "(assign n -= 1)");
  CHECK(one("n *= 2") == "(assign n *= 2)");
  CHECK(one("n /= 2") == "(assign n /= 2)");
}

TEST_CASE("operator precedence and associativity", "[ast]") {
  CHECK(one("let x = 1 + 2 * 3") == "(let x (+ 1 (* 2 3)))");
  CHECK(one("let x = (1 + 2) * 3") == "(let x (* (+ 1 2) 3))");
  CHECK(one("let x = 1 - 2 - 3") == "(let x (- (- 1 2) 3))");
  CHECK(one("let x = a / b % c") == "(let x (% (/ a b) c))");
  CHECK(one("let x = 2 ^ 3 ^ 2") == "(let x (^ 2 (^ 3 2)))");
  CHECK(one("let x = -2 ^ 2") == "(let x (neg (^ 2 2)))");
  CHECK(one("let x = 2 ^ -1") == "(let x (^ 2 -1))");  // a minus before a literal: a negative literal
  CHECK(one("let x = --2") == "(let x (neg -2))");      // only once
  CHECK(one("let x = -(2)") == "(let x -2)");
  CHECK(one("let x = -0") == "(let x -0)");
  CHECK(one("let x = - -a") == "(let x (neg (neg a)))");
  CHECK(one("let x = +a") == "(let x (pos a))");
  CHECK(one("let x = not a == b") == "(let x (not (== a b)))");
  CHECK(one("let x = a or b and c") == "(let x (or a (and b c)))");
  CHECK(one("let x = not a and not b") == "(let x (and (not a) (not b)))");
  CHECK(one("let x = a + 1 < b * 2") == "(let x (< (+ a 1) (* b 2)))");
  CHECK(one("let x = a != b") == "(let x (!= a b))");
  CHECK(one("let x = a <= b or a >= b") == "(let x (or (<= a b) (>= a b)))");
  CHECK(one("let x = a > b") == "(let x (> a b))");
}

TEST_CASE("ranges", "[ast]") {
  CHECK(one("let r = 0 .. 20") == "(let r (range .. 0 20))");
  CHECK(one("let r = 0..20") == "(let r (range .. 0 20))");
  CHECK(one("let r = 0 ..= 1 step 0.25") == "(let r (range ..= 0 1 step 0.25))");
  CHECK(one("let r = a + 1 .. b * 2 step -1") == "(let r (range .. (+ a 1) (* b 2) step -1))");
  CHECK(one("let r = 0 .. 3 == x") == "(let r (== (range .. 0 3) x))");
}

TEST_CASE("vectors and lists", "[ast]") {
  CHECK(one("let v = <1, 2>") == "(let v (vec 1 2))");
  CHECK(one("let v = <-1, 2 * x, f(y)>") == "(let v (vec -1 (* 2 x) (call f y)))");
  CHECK(one("let v = <1, 2, 3, 4>") == "(let v (vec 1 2 3 4))");
  CHECK(one("let v = <(a > b), 0, 0>") == "(let v (vec (> a b) 0 0))");
  CHECK(one("let xs = []") == "(let xs (list))");
  CHECK(one("let xs = [1, [2, 3],]") == "(let xs (list 1 (list 2 3)))");
}

TEST_CASE("a vector of number literals keeps the literals, not a list of links to them", "[ast]") {
  auto p = parse_text("let a = <1.5, -2, 3e2>\nlet b = <1, +2, 3>\nlet c = <x, 2, 3>\n");
  REQUIRE(p.program.stmts().size() == 3);
  auto vec = [&](int k) -> const ast::VectorExpr& {
    return static_cast<const ast::VectorExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[k]).value);
  };
  const ast::ComponentList& a = vec(0).components;
  CHECK(a.literals());
  REQUIRE(a.size() == 3);
  const double expected[] = {1.5, -2, 300};
  std::size_t k = 0;
  for (const ast::ExprPtr& c : a) {  // read as links all the same
    REQUIRE(c->kind == ast::ExprKind::Number);
    CHECK(static_cast<const ast::NumberExpr&>(*c).value() == expected[k]);
    CHECK(c.get() == a[k].get());
    ++k;
  }
  CHECK(k == 3);
  CHECK(a[1]->loc.col() == 15);  // the minus
  CHECK_FALSE(vec(1).components.literals());  // +2 is an operator above a literal
  CHECK_FALSE(vec(2).components.literals());
  CHECK(vec(2).components[0]->kind == ast::ExprKind::Name);
  CHECK(static_cast<const ast::NumberExpr&>(*vec(2).components[2]).value() == 3);
}

TEST_CASE("a number literal gives exactly its text's double, short or wide", "[ast]") {
  // {spelling, kept short (12 bytes) rather than wide}: the value must be strtod's, bit for bit.
  const std::pair<const char*, bool> cases[] = {
      {"0", true},          {"0.0", true},        {"1", true},           {"1000", true},
      {"0.499", true},      {"10.50", true},      {"100.0e2", true},     {"000123.4500", true},
      {".5", true},         {"2.5E+4", true},     {"0.1", true},         {"123456789", true},
      {"1e22", true},       {"1e-22", true},      {"0.000000000000000000000001", false},
      {"1e23", false},      {"1e-23", false},     {"1234567890", true}, {"1234567891", true}, {"12345678912", false}, {"3.141592653589793", false},
      {"4294967296", false}, {"1e-320", false},    {"1.7976931348623157e308", false},
      {"9007199254740993", false},                {"0e999", true},
  };
  for (const auto& [spelling, short_form] : cases) {
    CAPTURE(spelling);
    auto p = parse_text(std::string("let a = ") + spelling + "\nlet b = -" + spelling + "\n");
    for (int k = 0; k < 2; ++k) {
      const auto& n = static_cast<const ast::NumberExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[k]).value);
      REQUIRE(n.kind == ast::ExprKind::Number);
      const double want = (k == 0 ? 1 : -1) * std::strtod(spelling, nullptr);
      const double got = n.value();
      CHECK(std::memcmp(&got, &want, sizeof got) == 0);  // -0 included
      CHECK(n.wide() == !short_form);
    }
  }
  // Random spellings of the grammar's shape, in one file: each literal's value is strtod's.
  std::mt19937 rng(24);
  std::string text, spelling;
  std::vector<std::string> spellings;
  for (int i = 0; i < 4000; ++i) {
    spelling.clear();
    const int digits = 1 + static_cast<int>(rng() % 12);
    const int point = static_cast<int>(rng() % (digits + 2)) - 1;  // -1: none; digits: ".5" style
    for (int d = 0; d < digits; ++d) {
      if (d == point) spelling += d == 0 ? "0." : ".";
      spelling += static_cast<char>('0' + (rng() % 4 == 0 ? 0 : rng() % 10));
    }
    if (rng() % 3 == 0) spelling += fmt::format("e{}", static_cast<int>(rng() % 61) - 30);
    spellings.push_back(spelling);
    text += fmt::format("let n{} = {}\n", i, spelling);
  }
  auto all = parse_text(text);
  REQUIRE(all.program.stmts().size() == spellings.size());
  for (std::size_t i = 0; i < spellings.size(); ++i) {
    CAPTURE(spellings[i]);
    const auto& n = static_cast<const ast::NumberExpr&>(*static_cast<ast::LetStmt&>(*all.program.stmts()[i]).value);
    const double want = std::strtod(spellings[i].c_str(), nullptr), got = n.value();
    REQUIRE(std::memcmp(&got, &want, sizeof got) == 0);
  }
  // Four digits or fewer: the 8-byte form.
  auto tiny = parse_text("let a = 0.499\nlet b = -38.2\nlet c = 32767\nlet d = 32768\nlet e = -0\n");
  const bool expect_tiny[] = {true, true, true, false, true};
  for (int k = 0; k < 5; ++k) {
    CAPTURE(k);
    CHECK(static_cast<const ast::NumberExpr&>(*static_cast<ast::LetStmt&>(*tiny.program.stmts()[k]).value).tiny() ==
          expect_tiny[k]);
  }
  // A vector's literals are read at the tiny form's stride: a longer one can only come last.
  auto p = parse_text("let a = <1, 2, 3.141592653589793>\nlet b = <3.141592653589793, 2, -0>\n"
                      "let c = <1, 123456, 2>\nlet d = <1, 2, 123456>\n");
  const auto& c = static_cast<const ast::VectorExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[2]).value);
  const auto& d = static_cast<const ast::VectorExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[3]).value);
  CHECK_FALSE(c.components.literals());
  CHECK(d.components.literals());
  CHECK(static_cast<const ast::NumberExpr&>(*c.components[1]).value() == 123456);
  CHECK(static_cast<const ast::NumberExpr&>(*c.components[2]).value() == 2);
  CHECK(static_cast<const ast::NumberExpr&>(*d.components[2]).value() == 123456);
  const auto& a = static_cast<const ast::VectorExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[0]).value);
  const auto& b = static_cast<const ast::VectorExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[1]).value);
  CHECK(a.components.literals());
  CHECK_FALSE(b.components.literals());
  const double pi = 3.141592653589793;
  CHECK(static_cast<const ast::NumberExpr&>(*a.components[2]).value() == pi);
  CHECK(static_cast<const ast::NumberExpr&>(*b.components[0]).value() == pi);
  CHECK(static_cast<const ast::NumberExpr&>(*b.components[1]).value() == 2);
  CHECK(std::signbit(static_cast<const ast::NumberExpr&>(*b.components[2]).value()));
}

TEST_CASE("calls, indexing and members", "[ast]") {
  CHECK(one("f()") == "(expr (call f))");
  CHECK(one("column(1, 2, h = 3)") == "(expr (call column 1 2 (named h 3)))");
  CHECK(one("f(x, scale = 2)") == "(expr (call f x (named scale 2)))");
  CHECK(one("let y = xs[i + 1]") == "(let y (index xs (+ i 1)))");
  CHECK(one("let y = v.x") == "(let y (member v x))");
  CHECK(one("let y = a.b(c)[0].d") == "(let y (member (index (call (member a b) c) 0) d))");
  CHECK(one("let y = f(1)(2)") == "(let y (call (call f 1) 2))");
}

TEST_CASE("blocks: properties and statements keep their order", "[ast]") {
  CHECK(one("group { }") == "(expr (block group))");
  CHECK(one("sphere { radius = 1 }") ==
        "(expr\n"
        "    (block sphere\n"
        "      (prop radius 1)))");
  CHECK(one("material { color = rgb(1, 0, 0) diffuse = 0.7 }") ==
        "(expr\n"
        "    (block material\n"
        "      (prop color (call rgb 1 0 0))\n"
        "      (prop diffuse 0.7)))");
  CHECK(one("sphere { if big { let r = 2 } radius = 1 }") ==
        "(expr\n"
        "    (block sphere\n"
        "      (if big\n"
        "        (then\n"
        "          (let r 2)))\n"
        "      (prop radius 1)))");
  CHECK(one("group { column(-2, 0, 3) sphere { radius = 1 } }") ==
        "(expr\n"
        "    (block group\n"
        "      (expr (call column -2 0 3))\n"
        "      (expr\n"
        "        (block sphere\n"
        "          (prop radius 1)))))");
}

TEST_CASE("name = value is a property in a block body but an assignment in a statement body", "[ast]") {
  auto p = parse_text("sphere { r = 1 if c { r = 2 } r += 3 }");
  auto& stmt = static_cast<ast::ExprStmt&>(*p.program.stmts().at(0));
  auto& block = static_cast<ast::BlockExpr&>(*stmt.expr);
  REQUIRE(block.body.items.size() == 3);
  CHECK(*block.body.items[0].property == "r");
  CHECK(block.body.items[0].stmt() == nullptr);
  REQUIRE(block.body.items[1].stmt());
  auto& cond = static_cast<ast::IfStmt&>(*block.body.items[1].stmt());
  REQUIRE(cond.then_body.stmts.size() == 1);
  CHECK(cond.then_body.stmts[0]->kind == ast::StmtKind::Assign);
  REQUIRE(block.body.items[2].stmt());
  CHECK(block.body.items[2].property == nullptr);
  auto& add = static_cast<ast::AssignStmt&>(*block.body.items[2].stmt());
  CHECK(add.op == ast::AssignOp::Add);
}

TEST_CASE("with derivation", "[ast]") {
  CHECK(one("let glass = ivory with { diffuse = 0 transmit = 0.9 }") ==
        "(let glass\n"
        "    (with ivory\n"
        "      (prop diffuse 0)\n"
        "      (prop transmit 0.9)))");
  CHECK(one("let m = a with { } with { }") == "(let m (with (with a)))");
}

TEST_CASE("transforms are the loosest postfix and left-associative", "[ast]") {
  CHECK(one("tree translate <1, 0, 0>") == "(expr (translate tree (vec 1 0 0)))");
  CHECK(one("group { } rotate <0, 45, 0> translate <0, 0, 5>") ==
        "(expr (translate (rotate (block group) (vec 0 45 0)) (vec 0 0 5)))");
  CHECK(one("s scale 2 * k matrix m") == "(expr (matrix (scale s (* 2 k)) m))");
  CHECK(one("s scale a or b") == "(expr (scale s (or a b)))");
  CHECK(one("checker { color1 = a scale = 2 }") ==
        "(expr\n"
        "    (block checker\n"
        "      (prop color1 a)\n"
        "      (prop scale 2)))");
}

TEST_CASE("the ambiguity rule: no bare block in conditions and iterables", "[ast]") {
  CHECK(one("if enabled { }") == "(if enabled (then))");
  CHECK(one("while n < limit { n += 1 }") ==
        "(while (< n limit)\n"
        "    (assign n += 1))");
  CHECK(one("for m in materials { }") == "(for m materials)");
  CHECK(one("if (group { }) == x { }") == "(if (== (block group) x) (then))");
}

TEST_CASE("if / else if / else", "[ast]") {
  CHECK(one("if a { x = 1 } else if b { x = 2 } else { x = 3 }") ==
        "(if a\n"
        "    (then\n"
        "      (assign x = 1))\n"
        "    (else\n"
        "      (if b\n"
        "        (then\n"
        "          (assign x = 2))\n"
        "        (else\n"
        "          (assign x = 3)))))");
  auto p = parse_text("if a { } else if b { }");
  auto& outer = static_cast<ast::IfStmt&>(*p.program.stmts().at(0));
  REQUIRE(outer.else_body);
  REQUIRE(outer.else_body->stmts.size() == 1);
  auto& inner = static_cast<ast::IfStmt&>(*outer.else_body->stmts[0]);
  CHECK(inner.else_body == nullptr);
}

TEST_CASE("loops, macros, return, break, continue, include", "[ast]") {
  CHECK(one("for i in 0 .. 3 { break continue }") ==
        "(for i (range .. 0 3)\n"
        "    (break)\n"
        "    (continue))");
  CHECK(one("macro f(a, b = 2, c = <0, 0, 0>) { return a + b }") ==
        "(macro f (params a (default b 2) (default c (vec 0 0 0)))\n"
        "    (return (+ a b)))");
  CHECK(one("macro g() { return }") ==
        "(macro g (params)\n"
        "    (return))");
  CHECK(one("include \"materials.rts\"") == "(include \"materials.rts\")");
}

TEST_CASE("statements need no separators; semicolons are optional", "[ast]") {
  CHECK(ast_of("let a = 1 let b = a; a = b;") ==
        "(program\n"
        "  (let a 1)\n"
        "  (let b a)\n"
        "  (assign a = b))\n");
}

TEST_CASE("locations are printed after each head with --locations", "[ast]") {
  CHECK(ast_of("let x = 1 +\n  f(y)", true) ==
        "(program\n"
        "  (let @1:1 x (+ @1:9 1@1:9 (call @2:3 f@2:3 y@2:5))))\n");
}
