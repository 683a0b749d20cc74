// Every node carries the 1-based line and byte column of its first character.
#include <catch2/catch.hpp>

#include "parser_test_support.hpp"

using rts::testing::parse_text;
namespace ast = rts::ast;

namespace {
void check_at(const rts::SourceLoc& loc, uint32_t line, uint32_t col) {
  CHECK(loc.valid());
  CHECK(loc.line == line);
  CHECK(loc.col == col);
}
}  // namespace

TEST_CASE("statements, names and operators carry their locations", "[locations]") {
  auto p = parse_text("// comment\n  let  width = 2 *\n\tsize\nn += 1");
  REQUIRE(p.program.stmts.size() == 2);
  auto& let = static_cast<ast::LetStmt&>(*p.program.stmts[0]);
  check_at(let.loc, 2, 3);
  check_at(let.name_loc, 2, 8);
  CHECK(let.loc.file == p.file);
  auto& mul = static_cast<ast::BinaryExpr&>(*let.value);
  check_at(mul.loc, 2, 16);     // a binary node starts where its left operand starts
  check_at(mul.op_loc, 2, 18);  // the operator itself
  check_at(mul.rhs->loc, 3, 2); // after a tab: byte columns
  auto& assign = static_cast<ast::AssignStmt&>(*p.program.stmts[1]);
  check_at(assign.loc, 4, 1);
}

TEST_CASE("blocks, bodies and items", "[locations]") {
  auto p = parse_text("group {\n  sphere { radius = 1 }\n}\nfor i in xs {\n  break\n}");
  auto& stmt = static_cast<ast::ExprStmt&>(*p.program.stmts[0]);
  auto& group = static_cast<ast::BlockExpr&>(*stmt.expr);
  check_at(group.loc, 1, 1);
  check_at(group.body.open_loc, 1, 7);
  REQUIRE(group.body.items.size() == 1);
  check_at(group.body.items[0].loc, 2, 3);
  auto& inner = static_cast<ast::ExprStmt&>(*group.body.items[0].stmt);
  auto& sphere = static_cast<ast::BlockExpr&>(*inner.expr);
  check_at(sphere.body.items[0].loc, 2, 12);  // the property name
  check_at(sphere.body.items[0].value->loc, 2, 21);
  auto& loop = static_cast<ast::ForStmt&>(*p.program.stmts[1]);
  check_at(loop.loc, 4, 1);
  check_at(loop.var_loc, 4, 5);
  check_at(loop.iterable->loc, 4, 10);
  check_at(loop.body.open_loc, 4, 13);
  check_at(loop.body.stmts[0]->loc, 5, 3);
}

TEST_CASE("postfix nodes, arguments, transforms and members", "[locations]") {
  auto p = parse_text("let t = f(1, h = 2).x translate <0, 1, 0>");
  auto& let = static_cast<ast::LetStmt&>(*p.program.stmts[0]);
  auto& tr = static_cast<ast::TransformExpr&>(*let.value);
  check_at(tr.loc, 1, 9);
  check_at(tr.op_loc, 1, 23);
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
  REQUIRE(p.program.stmts.size() == 2);
  check_at(p.program.stmts[1]->loc, 2, 1);
}

TEST_CASE("macro parameters and strings", "[locations]") {
  auto p = parse_text("macro m(a, b = \"s\") { }");
  auto& m = static_cast<ast::MacroStmt&>(*p.program.stmts[0]);
  REQUIRE(m.params.size() == 2);
  check_at(m.params[0].loc, 1, 9);
  check_at(m.params[1].loc, 1, 12);
  check_at(m.params[1].default_value->loc, 1, 16);
}
