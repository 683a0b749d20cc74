// NodeArena (parser/ast.hpp): the AST's nodes share their program's memory blocks. Each node's
// destructor still runs (strings and child vectors are freed: the sanitizer builds would
// report a leak), a program moved elsewhere keeps its nodes, and a parse that fails part-way
// frees what it had built.
#include <catch2/catch.hpp>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "parser/ast.hpp"
#include "parser_test_support.hpp"

namespace ast = rts::ast;
using rts::testing::error_of;
using rts::testing::parse_text;

namespace {
int destroyed = 0;
struct Counted : ast::Expr {
  std::string payload;
  explicit Counted(std::string p) : Expr(ast::ExprKind::String, rts::SourceLoc{}), payload(std::move(p)) {}
  ~Counted() override { ++destroyed; }
};
}  // namespace

TEST_CASE("an arena's nodes are constructed aligned, destroyed by their owners, freed with it", "[ast]") {
  destroyed = 0;
  ast::NodeArena arena;
  {
    std::vector<ast::ExprPtr> owners;
    for (int i = 0; i < 10000; ++i) {
      owners.push_back(arena.make<Counted>(std::string(i % 7 == 0 ? 100 : 3, 'x')));  // some strings on the heap
      CHECK(reinterpret_cast<std::uintptr_t>(owners.back().get()) % alignof(Counted) == 0);
    }
    CHECK(static_cast<Counted&>(*owners[9999]).payload == "xxx");
    CHECK(static_cast<Counted&>(*owners[7]).payload.size() == 100);
    owners.erase(owners.begin(), owners.begin() + 10);  // one by one: destructors only
    CHECK(destroyed == 10);
  }
  CHECK(destroyed == 10000);
  // Blocks grow, so 10,000 nodes of ~56 bytes take a few blocks, not one per node.
  CHECK(arena.reserved() >= 10000 * sizeof(Counted));
  CHECK(arena.reserved() < 2 * 10000 * sizeof(Counted) + (std::size_t{1} << 20));
}

TEST_CASE("a program holds its arena: moved, it keeps its nodes", "[ast]") {
  rts::testing::Parsed p = parse_text("let a = [1, 2, <3, 4, 5>]\nsphere { center = <0, 1, 0> radius = a[0] }\n");
  REQUIRE(p.program.arena);
  const std::string before = rts::testing::ast_of("let a = [1, 2, <3, 4, 5>]\nsphere { center = <0, 1, 0> radius = a[0] }\n");
  ast::Program moved = std::move(p.program);
  REQUIRE(moved.stmts.size() == 2);
  CHECK(moved.stmts[0]->kind == ast::StmtKind::Let);
  CHECK(moved.stmts[1]->kind == ast::StmtKind::ExprStmt);
  std::ostringstream out;
  rts::print_ast(out, moved, false);
  CHECK(out.str() == before);
}

TEST_CASE("a parse that fails part-way frees the nodes it built", "[ast]") {
  // Under the sanitizers: no use after free (the stacks' nodes go before their arena) and no leak.
  CHECK_FALSE(error_of("let a = [1, 2, <3, 4, 5>]\nsphere { center = <0, 1, 0> radius = \"a long string to own\" ").empty());
  CHECK_FALSE(error_of("macro f(p) { return <p.x, p.y + 1, 2 * (3 + 4)> }\nlet b = f(<1, 2, 3>) +").empty());
}
