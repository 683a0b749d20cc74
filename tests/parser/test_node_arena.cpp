// NodeArena (parser/ast.hpp): the AST's nodes, their lists and their strings share their
// program's memory blocks and have nothing to destroy; a program moved elsewhere keeps its
// nodes, and a parse that fails part-way frees what it had built (the sanitizer builds would
// report a leak or a use after free).
#include <catch2/catch.hpp>

#include <cstdint>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "parser/ast.hpp"
#include "parser_test_support.hpp"

namespace ast = rts::ast;
using rts::testing::error_of;
using rts::testing::parse_text;

TEST_CASE("an arena's nodes, lists and texts are aligned, intact and freed with it", "[ast]") {
  ast::NodeArena arena;
  std::vector<ast::NodePtr<ast::NumberExpr>> numbers;
  std::vector<std::string_view> texts;
  for (int i = 0; i < 10000; ++i) {
    numbers.push_back(arena.make<ast::NumberExpr>(rts::SourceLoc{}, 0.5 * i));
    CHECK(reinterpret_cast<std::uintptr_t>(numbers.back().get()) % alignof(ast::NumberExpr) == 0);
    texts.push_back(arena.text(std::string(i % 7 == 0 ? 100 : 3, static_cast<char>('a' + i % 26))));
  }
  for (int i = 0; i < 10000; i += 997) {
    CHECK(numbers[i]->value == 0.5 * i);
    CHECK(numbers[i]->kind == ast::ExprKind::Number);
    CHECK(texts[i] == std::string(i % 7 == 0 ? 100 : 3, static_cast<char>('a' + i % 26)));
  }
  const ast::NodeList<ast::ExprPtr> list =
      arena.list<ast::ExprPtr>(numbers.begin() + 10, numbers.begin() + 20, [](auto n) { return ast::ExprPtr(n); });
  REQUIRE(list.size() == 10);
  CHECK(reinterpret_cast<std::uintptr_t>(list.begin()) % alignof(ast::ExprPtr) == 0);
  CHECK(static_cast<const ast::NumberExpr&>(*list[3]).value == 6.5);
  CHECK(list.back().get() == numbers[19].get());
  CHECK_THROWS_AS(list.at(10), std::out_of_range);
  const ast::NodeList<ast::ExprPtr> none = arena.list<ast::ExprPtr>(numbers.begin(), numbers.begin(), [](auto n) { return ast::ExprPtr(n); });
  CHECK(none.empty());
  CHECK(none.begin() == none.end());
  // Blocks grow, so 10,000 nodes take a few blocks, not one per node.
  const std::size_t payload = 10000 * (sizeof(ast::NumberExpr) + 3) + 1500 * 100;
  CHECK(arena.reserved() >= payload);
  CHECK(arena.reserved() < 2 * payload + (std::size_t{1} << 20));
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

TEST_CASE("symbols are 4-byte numbers naming their interned strings, from any thread", "[ast]") {
  static_assert(sizeof(ast::Symbol) == 4);
  const ast::Symbol a = ast::intern("symbol_test_alpha");
  const ast::Symbol b = ast::intern("symbol_test_beta");
  CHECK(a != b);
  CHECK(a == ast::intern(std::string("symbol_test_") + "alpha"));
  CHECK(*a == "symbol_test_alpha");
  CHECK(a->size() == 17);
  CHECK(std::hash<ast::Symbol>{}(a) != std::hash<ast::Symbol>{}(b));
  const ast::Symbol none;
  CHECK_FALSE(none);
  CHECK(none == nullptr);
  CHECK(a != nullptr);
  // More names than one table chunk holds, interned from two threads at once: each keeps its
  // number and its name.
  std::vector<ast::Symbol> first(6000), second(6000);
  std::thread other([&] {
    for (int i = 0; i < 6000; ++i) second[i] = ast::intern("symbol_test_t2_" + std::to_string(i));
  });
  for (int i = 0; i < 6000; ++i) first[i] = ast::intern("symbol_test_t1_" + std::to_string(i));
  other.join();
  for (int i = 0; i < 6000; i += 599) {
    CHECK(*first[i] == "symbol_test_t1_" + std::to_string(i));
    CHECK(*second[i] == "symbol_test_t2_" + std::to_string(i));
    CHECK(first[i] == ast::intern("symbol_test_t1_" + std::to_string(i)));
  }
}
