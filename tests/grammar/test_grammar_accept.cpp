// Programs the grammar must accept, one table row per construct (the AST they produce is
// checked in tests/parser/).
#include <catch2/catch.hpp>

#include "grammar_test_support.hpp"

using rts::grammar::testing::run_grammar;

namespace {

struct Row {
  const char* construct;
  const char* text;
};

const Row kAccepted[] = {
    {"empty file", ""},
    {"only whitespace", " \t\r\n\f\v "},
    {"line comment", "// hello\n"},
    {"line comment at end of file without newline", "let x = 1 // done"},
    {"block comment", "/* a\n multi-line * / comment */ let x = 1"},
    {"block comments are not nested", "/* /* */ let x = 1"},
    {"integer", "1"},
    {"decimal", "1.5"},
    {"leading dot", ".5"},
    {"exponent", "1e-3"},
    {"exponent with sign and capital E", "2.5E+4"},
    {"string", "\"hello\""},
    {"string escapes", R"("a\nb\tc\rd\\e\"f\0g")"},
    {"unicode escape", R"("\u{1F600}\u{41}")"},
    {"UTF-8 in a string", "\"caf\xc3\xa9\""},
    {"true false none", "true false none"},
    {"let", "let x = 1"},
    {"names may contain keywords", "let letter = 1 let iffy = 2 let notable = 3 let format = 4"},
    {"assignment", "x = 1"},
    {"compound assignments", "x += 1 x -= 1 x *= 2 x /= 2"},
    {"semicolons", "let x = 1; x = 2;; ;"},
    {"if", "if a { }"},
    {"if else", "if a { x = 1 } else { x = 2 }"},
    {"else if chain", "if a { } else if b { } else if c { } else { }"},
    {"for over range", "for i in 0 .. 20 { }"},
    {"for over inclusive range with step", "for i in 0 ..= 1 step 0.25 { }"},
    {"for over list", "for c in [1, 2, 3] { }"},
    {"range without spaces", "for i in 0..20 { }"},
    {"while", "while n < limit { n += 1 }"},
    {"if condition name before brace is not a block", "if enabled { sphere { radius = 1 } }"},
    {"block allowed in a parenthesised condition", "if (group { }) == x { }"},
    {"macro", "macro f(a, b = 2, c = <0, 0, 0>) { return a + b }"},
    {"macro without parameters", "macro g() { }"},
    {"return forms", "macro f() { return } macro g() { return 1 }"},
    {"break continue", "while true { break continue }"},
    {"include", "include \"materials.rts\""},
    {"block", "sphere { center = <0, 1, 0> radius = 1 }"},
    {"empty block", "group { }"},
    {"nested blocks and statements in a block", "group { column(1, 2) sphere { radius = 1 } }"},
    {"let and if inside a block", "sphere { if big { let r = 2 } radius = 1 }"},
    {"with", "let glass = ivory with { diffuse = 0 transmit = 0.9 }"},
    {"transform chain", "group { } rotate <0, 45, 0> translate <0, 0, 5>"},
    {"all transforms", "s translate <1, 0, 0> rotate <0, 1, 0> scale 2 matrix m"},
    {"transform keyword as a property name", "checker { color1 = a color2 = b scale = 1 }"},
    {"transform keyword as a named argument", "f(x, scale = 2, step = 1)"},
    {"transform keyword as a member", "let s = t.scale"},
    {"call with named arguments", "column(1, 2, h = 3)"},
    {"call with trailing comma", "f(1, 2,)"},
    {"index and member", "let y = xs[i].x"},
    {"list", "let xs = [1, 2, 3]"},
    {"list with trailing comma", "let xs = [1, 2, 3,]"},
    {"empty list", "let xs = []"},
    {"vectors of 2, 3 and 4 components", "let a = <1, 2> let b = <1, 2, 3> let c = <1, 2, 3, 4>"},
    {"vector components are arithmetic", "let v = <-1, 2 * x, f(y)>"},
    {"comparison inside a vector needs parentheses", "let v = <(a > b), 0, 0>"},
    {"operators", "let x = a + b - c * d / e % f ^ g"},
    {"unary", "let x = -a + +b - -c"},
    {"power binds tighter than minus, negative exponent", "let x = -2 ^ -1"},
    {"comparisons", "let x = a == b let y = a != b let z = a <= b let w = a >= b"},
    {"logic", "let x = not a == b and c or d"},
    {"parentheses", "let x = ((1 + 2) * 3)"},
    {"example program column macro",
     "macro column(x, z, h = 3) {\n"
     "  cylinder { from = <x, 0, z> to = <x, h, z> radius = 0.2 material = ivory }\n"
     "  sphere { center = <x, h, z> radius = 0.3 material = glass }\n}"},
    {"if with a transformed mesh",
     "if quality > 1 { mesh { file = \"bunny.obj\" smooth = true material = ivory } scale 10 }"},
};

}  // namespace

TEST_CASE("the grammar accepts every construct", "[accept]") {
  for (const Row& row : kAccepted) {
    SECTION(row.construct) {
      auto r = run_grammar(row.text);
      INFO(row.text);
      INFO(r.message);
      CHECK(r.accepted);
    }
  }
}
