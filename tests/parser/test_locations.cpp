// Every node carries the 1-based line and byte column of its first character, as a SourceLoc
// (a file number and a byte offset; line and column are resolved from the file's line table).
#include <catch2/catch.hpp>

#include <string>

#include "parser/position_space.hpp"
#include "parser_test_support.hpp"

#include <cstdint>
#include <utility>

using rts::testing::parse_text;
namespace ast = rts::ast;

namespace {
void check_at(const rts::SourceLoc& loc, uint32_t line, uint32_t col) {
  CHECK(loc.valid());
  CHECK(loc.line() == line);
  CHECK(loc.col() == col);
}
}  // namespace

TEST_CASE("statements, names and operators carry their locations", "[locations]") {
  auto p = parse_text("// comment\n  let  width = 2 *\n\tsize\nn += 1");
  REQUIRE(p.program.stmts().size() == 2);
  auto& let = static_cast<ast::LetStmt&>(*p.program.stmts()[0]);
  check_at(let.loc, 2, 3);
  check_at(let.name_loc, 2, 8);
  CHECK(let.loc.file() == p.file);
  auto& mul = static_cast<ast::BinaryExpr&>(*let.value);
  check_at(mul.loc, 2, 16);     // a binary node starts where its left operand starts
  check_at(mul.op_loc(), 2, 18);  // the operator itself
  check_at(mul.rhs->loc, 3, 2); // after a tab: byte columns
  auto& assign = static_cast<ast::AssignStmt&>(*p.program.stmts()[1]);
  check_at(assign.loc, 4, 1);
}

TEST_CASE("an operator far from its node's start keeps its place", "[locations]") {
  // The place is kept as a 16-bit distance from the node's own, or after the node when further.
  const std::string far(70000, ' ');
  auto p = parse_text("let a = x" + far + "+ 1 * y\nlet b = x\n" + far + "scale 2\nlet c = x +" + far + "1\n");
  auto& a = static_cast<ast::BinaryExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[0]).value);
  check_at(a.loc, 1, 9);
  check_at(a.op_loc(), 1, 10 + 70000);
  CHECK(a.op() == ast::BinaryOp::Add);
  auto& mul = static_cast<ast::BinaryExpr&>(*a.rhs);
  check_at(mul.op_loc(), 1, 10 + 70000 + 4);
  auto& b = static_cast<ast::TransformExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[1]).value);
  check_at(b.op_loc(), 3, 70001);
  CHECK(b.op() == ast::TransformOp::Scale);
  CHECK(static_cast<const ast::NumberExpr&>(*b.arg).value() == 2);
  auto& c = static_cast<ast::BinaryExpr&>(*static_cast<ast::LetStmt&>(*p.program.stmts()[2]).value);
  check_at(c.op_loc(), 4, 11);
  check_at(c.rhs->loc, 4, 12 + 70000);
}

TEST_CASE("blocks, bodies and items", "[locations]") {
  auto p = parse_text("group {\n  sphere { radius = 1 }\n}\nfor i in xs {\n  break\n}");
  auto& stmt = static_cast<ast::ExprStmt&>(*p.program.stmts()[0]);
  auto& group = static_cast<ast::BlockExpr&>(*stmt.expr);
  check_at(group.loc, 1, 1);
  check_at(group.body.open_loc, 1, 7);
  REQUIRE(group.body.items.size() == 1);
  check_at(group.body.items[0].loc, 2, 3);
  auto& inner = static_cast<ast::ExprStmt&>(*group.body.items[0].stmt());
  auto& sphere = static_cast<ast::BlockExpr&>(*inner.expr);
  check_at(sphere.body.items[0].loc, 2, 12);  // the property name
  check_at(sphere.body.items[0].value()->loc, 2, 21);
  auto& loop = static_cast<ast::ForStmt&>(*p.program.stmts()[1]);
  check_at(loop.loc, 4, 1);
  check_at(loop.var_loc, 4, 5);
  check_at(loop.iterable->loc, 4, 10);
  check_at(loop.body.open_loc, 4, 13);
  check_at(loop.body.stmts[0]->loc, 5, 3);
}

TEST_CASE("postfix nodes, arguments, transforms and members", "[locations]") {
  auto p = parse_text("let t = f(1, h = 2).x translate <0, 1, 0>");
  auto& let = static_cast<ast::LetStmt&>(*p.program.stmts()[0]);
  auto& tr = static_cast<ast::TransformExpr&>(*let.value);
  check_at(tr.loc, 1, 9);
  check_at(tr.op_loc(), 1, 23);
  check_at(tr.arg->loc, 1, 33);
  auto& member = static_cast<ast::MemberExpr&>(*tr.object);
  check_at(member.member_loc, 1, 21);
  auto& call = static_cast<ast::CallExpr&>(*member.object);
  check_at(call.loc, 1, 9);
  REQUIRE(call.args.size() == 2);
  check_at(call.args[0].loc, 1, 11);
  check_at(call.args[1].loc, 1, 14);
  CHECK(*call.args[1].name == "h");
}

TEST_CASE("CRLF line endings count as one line break", "[locations]") {
  auto p = parse_text("let a = 1\r\nlet b = 2\r\n");
  REQUIRE(p.program.stmts().size() == 2);
  check_at(p.program.stmts()[1]->loc, 2, 1);
}

TEST_CASE("macro parameters and strings", "[locations]") {
  auto p = parse_text("macro m(a, b = \"s\") { }");
  auto& m = static_cast<ast::MacroStmt&>(*p.program.stmts()[0]);
  REQUIRE(m.params.size() == 2);
  check_at(m.params[0].loc, 1, 9);
  check_at(m.params[1].loc, 1, 12);
  check_at(m.params[1].default_value->loc, 1, 16);
}

TEST_CASE("a SourceLoc is 4 bytes and resolves its line and column through its file", "[locations]") {
  static_assert(sizeof(rts::SourceLoc) == 4);
  rts::SourceManager sources;
  const rts::SourceFile* a = sources.add("a.rts", "one\ntwo\r\n\nfour");
  const rts::SourceFile* b = sources.add("b.rts", "x\n  y\n");
  CHECK(a->first_position() != b->first_position());
  // Alternating between files and lines: the per-thread cache of the last line must not leak
  // one file's line into another's.
  for (int round = 0; round < 3; ++round) {
    check_at(rts::SourceLoc::at(a, 2, 3), 2, 3);
    check_at(rts::SourceLoc::at(b, 2, 3), 2, 3);
    check_at(rts::SourceLoc::at_offset(a, 0), 1, 1);
    check_at(rts::SourceLoc::at_offset(a, 4), 2, 1);
    check_at(rts::SourceLoc::at_offset(a, 9), 3, 1);     // the empty line after "two\r\n"
    check_at(rts::SourceLoc::at_offset(a, 10), 4, 1);
    check_at(rts::SourceLoc::at_offset(a, 14), 4, 5);    // the end of the text: after "four"
    check_at(rts::SourceLoc::at_offset(b, 4), 2, 3);
  }
  CHECK(rts::SourceLoc::at(b, 2, 3).file() == b);
  CHECK(rts::SourceLoc::at(a, 2, 3) == rts::SourceLoc::at_offset(a, 6));
  CHECK(rts::SourceLoc::at(a, 2, 3).advanced(-2) == rts::SourceLoc::at(a, 2, 1));
  // A column at the end of a line (a caret after its last character) stays on that line.
  check_at(rts::SourceLoc::at(a, 1, 4), 1, 4);

  const rts::SourceLoc none;
  CHECK_FALSE(none.valid());
  CHECK(none.file() == nullptr);
  CHECK(none.line() == 0);
  CHECK(none.col() == 0);
  const rts::SourceLoc whole = rts::SourceLoc::whole(b);
  CHECK_FALSE(whole.valid());
  CHECK(whole.file() == b);
  CHECK(whole.line() == 0);
  CHECK(rts::SourceLoc::at(b, 0, 0) == whole);
}

TEST_CASE("a SourceLoc whose file is gone resolves to nothing, never to another file", "[locations]") {
  rts::SourceLoc stale;
  {
    rts::SourceManager gone;
    stale = rts::SourceLoc::at(gone.add("gone.rts", "let a = 1\nlet b = 2\n"), 2, 5);
    check_at(stale, 2, 5);  // resolved (and cached) while the file lives
  }
  rts::SourceManager later;
  const rts::SourceFile* f = later.add("later.rts", "let a = 1\nlet b = 2\n");
  check_at(rts::SourceLoc::at(f, 2, 5), 2, 5);
  CHECK(stale.file() == nullptr);
  CHECK(stale.line() == 0);
  CHECK(stale.col() == 0);
}

TEST_CASE("when the position space runs out, a freed file's positions go to the first gap that fits", "[locations]") {
  // Files are only named here, never read: the space stores and returns their addresses.
  const auto* a = reinterpret_cast<const rts::SourceFile*>(std::uintptr_t{0x1000});
  const auto* b = reinterpret_cast<const rts::SourceFile*>(std::uintptr_t{0x2000});
  const auto* c = reinterpret_cast<const rts::SourceFile*>(std::uintptr_t{0x3000});
  rts::source_detail::PositionSpace space(101);  // positions 1 to 100
  CHECK(space.add(a, 30) == 1);
  CHECK(space.add(b, 40) == 31);
  CHECK(space.find(0).first == nullptr);
  CHECK(space.find(30) == std::pair<const rts::SourceFile*, uint32_t>{a, 1});
  CHECK(space.find(31) == std::pair<const rts::SourceFile*, uint32_t>{b, 31});
  CHECK(space.find(70).first == b);
  CHECK(space.find(71).first == nullptr);
  space.remove(1);
  CHECK(space.find(5).first == nullptr);  // gone, and not yet given to another file
  // 30 fresh positions left: a file of 20 takes them in order while they last.
  CHECK(space.add(c, 20) == 71);
  const uint32_t generation = rts::source_detail::space_generation();
  // 10 fresh positions left: a file of 25 takes the freed gap at 1, and the generation moves
  // so that no thread's cache keeps naming a's lines.
  CHECK(space.add(a, 25) == 1);
  CHECK(rts::source_detail::space_generation() != generation);
  CHECK(space.find(25).first == a);
  CHECK(space.find(26).first == nullptr);
  CHECK(space.add(b, 5) == 91);  // fresh positions first, while any fit
  CHECK(space.add(c, 5) == 96);
  CHECK(space.add(b, 5) == 26);  // then the rest of the gap
  CHECK_THROWS_AS(space.add(c, 1), rts::SourceError);  // full
  CHECK(space.find(95).first == b);
  CHECK(space.find(100).first == c);
  CHECK(space.find(30) == std::pair<const rts::SourceFile*, uint32_t>{b, 26});
}
