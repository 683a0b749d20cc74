// NodeArena (parser/ast.hpp): the AST's nodes, their lists and their strings share their
// program's range of memory and have nothing to destroy; links inside it are 4-byte
// distances back; a program moved elsewhere keeps its nodes, and a parse that fails part-way
// frees what it had built (the sanitizer builds would report a leak or a use after free).
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
    numbers.push_back(ast::make_number(arena, rts::SourceLoc{}, 0.5 * i));
    CHECK(reinterpret_cast<std::uintptr_t>(numbers.back().get()) % alignof(ast::NumberExpr) == 0);
    texts.push_back(arena.text(std::string(i % 7 == 0 ? 100 : 3, static_cast<char>('a' + i % 26))));
  }
  for (int i = 0; i < 10000; i += 997) {
    CHECK(numbers[i]->value() == 0.5 * i);
    CHECK(numbers[i]->kind == ast::ExprKind::Number);
    CHECK(texts[i] == std::string(i % 7 == 0 ? 100 : 3, static_cast<char>('a' + i % 26)));
  }
  // A list, and a node after it that links to it (a link reaches back only).
  const ast::ListPiece<ast::ExprLink> piece =
      arena.list<ast::ExprLink>(numbers.begin() + 10, numbers.begin() + 20, [](auto n) { return ast::ExprPtr(n); });
  auto holder = arena.make<ast::ListExpr>(rts::SourceLoc{});
  holder->elements = piece;
  const ast::NodeList<ast::ExprLink>& list = holder->elements;
  REQUIRE(list.size() == 10);
  CHECK(reinterpret_cast<std::uintptr_t>(list.begin()) % alignof(ast::ExprLink) == 0);
  CHECK(static_cast<const ast::NumberExpr&>(*list[3]).value() == 6.5);
  CHECK(list.back().get() == numbers[19].get());
  CHECK_THROWS_AS(list.at(10), std::out_of_range);
  auto empty = arena.make<ast::ListExpr>(rts::SourceLoc{});
  empty->elements = arena.list<ast::ExprLink>(numbers.begin(), numbers.begin(), [](auto n) { return ast::ExprPtr(n); });
  CHECK(empty->elements.empty());
  CHECK(empty->elements.begin() == empty->elements.end());
  // Pages are committed as the arena fills, not all at once.
  const std::size_t payload = 10000 * sizeof(ast::NumberExpr) + 1500 * 100 + 10000 * 3;  // at least
  CHECK(arena.committed() >= payload);
  CHECK(arena.committed() < 2 * payload + (std::size_t{1} << 20));
  CHECK(arena.reserved() >= ast::NodeArena::kMinReserve);
  // When the parse ends, the range shrinks to what it holds; the nodes stay.
  arena.release_unused();
  CHECK(arena.reserved() == arena.committed());
  CHECK(numbers[9999]->value() == 0.5 * 9999);
  CHECK(list.back().get() == numbers[19].get());
}

TEST_CASE("links are 4 bytes and reach back only; a tree that outgrows its range is an error", "[ast]") {
  static_assert(sizeof(ast::ExprLink) == 4);
  static_assert(sizeof(ast::NodeList<ast::ExprLink>) == 8);
  static_assert(sizeof(ast::BlockItem) == 12);
  static_assert(sizeof(ast::NumberExpr) == 8 && alignof(ast::NumberExpr) == 4);
  ast::NodeArena arena;
  auto number = ast::make_number(arena, rts::SourceLoc{}, 2.0);
  auto neg = arena.make<ast::UnaryExpr>(rts::SourceLoc{}, ast::UnaryOp::Neg, number);
  CHECK(neg->operand.get() == number.get());
  CHECK(static_cast<const ast::NumberExpr&>(*neg->operand).value() == 2.0);
  CHECK_FALSE(number->wide());
  ast::ExprPtr copied = neg->operand;  // read out as a pointer, it points where the link does
  CHECK(copied.get() == number.get());
  // A link to a node built after it is a builder's bug, caught where it is made.
  auto later = ast::make_number(arena, rts::SourceLoc{}, 3.0);
  CHECK_THROWS_AS(neg->operand = later, std::logic_error);
  auto null_operand = arena.make<ast::UnaryExpr>(rts::SourceLoc{}, ast::UnaryOp::Neg, ast::ExprPtr());
  CHECK_FALSE(null_operand->operand);
  CHECK(null_operand->operand == nullptr);
  // The range of an arena for no text is kMinReserve: more than that is refused with a message.
  const std::string mib(std::size_t{1} << 20, 'x');
  try {
    for (std::size_t i = 0; i <= (ast::NodeArena::kMinReserve >> 20); ++i) arena.text(mib);
    FAIL("the arena's range did not run out");
  } catch (const std::length_error& e) {
    CHECK(std::string(e.what()).find("split the file") != std::string::npos);
  }
}

TEST_CASE("a program holds its arena: moved, it keeps its nodes", "[ast]") {
  rts::testing::Parsed p = parse_text("let a = [1, 2, <3, 4, 5>]\nsphere { center = <0, 1, 0> radius = a[0] }\n");
  REQUIRE(p.program.arena);
  const std::string before = rts::testing::ast_of("let a = [1, 2, <3, 4, 5>]\nsphere { center = <0, 1, 0> radius = a[0] }\n");
  ast::Program moved = std::move(p.program);
  REQUIRE(moved.stmts().size() == 2);
  CHECK(moved.stmts()[0]->kind == ast::StmtKind::Let);
  CHECK(moved.stmts()[1]->kind == ast::StmtKind::ExprStmt);
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
