// Values and operators in isolation: arithmetic, type errors, equality, text, random streams.
#include <cmath>

#include <catch2/catch.hpp>

#include "parser/diagnostics.hpp"
#include "runtime/ops.hpp"
#include "runtime/value.hpp"

using namespace rts;
using namespace rts::runtime;
using ast::BinaryOp;

namespace {
std::string op_error(BinaryOp op, const Value& a, const Value& b) {
  try {
    binary_op(op, a, b, SourceLoc{});
  } catch (const LanguageError& e) {
    return e.diag.message;
  }
  return "(no error)";
}
}  // namespace

TEST_CASE("number arithmetic and comparison", "[values]") {
  auto n = Value::number;
  CHECK(binary_op(BinaryOp::Add, n(2), n(3), {}).num() == 5);
  CHECK(binary_op(BinaryOp::Pow, n(2), n(10), {}).num() == 1024);
  CHECK(binary_op(BinaryOp::Mod, n(7), n(3), {}).num() == 1);
  CHECK(binary_op(BinaryOp::Mod, n(-7), n(3), {}).num() == -1);  // fmod: sign of the dividend
  CHECK(binary_op(BinaryOp::Lt, n(2), n(3), {}).truth());
  CHECK(binary_op(BinaryOp::Ge, n(2), n(3), {}).type == Type::Bool);
  CHECK_FALSE(binary_op(BinaryOp::Ge, n(2), n(3), {}).truth());
}

TEST_CASE("vectors and colors are component-wise and scale by numbers", "[values]") {
  Value a = Value::vector({1, 2, 3}), b = Value::vector({4, 5, 6});
  CHECK(binary_op(BinaryOp::Add, a, b, {}).v == glm::dvec3(5, 7, 9));
  CHECK(binary_op(BinaryOp::Mul, a, b, {}).v == glm::dvec3(4, 10, 18));
  CHECK(binary_op(BinaryOp::Mul, Value::number(2), a, {}).v == glm::dvec3(2, 4, 6));
  CHECK(binary_op(BinaryOp::Div, b, Value::number(2), {}).v == glm::dvec3(2, 2.5, 3));
  Value c = binary_op(BinaryOp::Mul, Value::color({1, 0.5, 0}), Value::number(0.5), {});
  CHECK(c.type == Type::Color);
  CHECK(c.v == glm::dvec3(0.5, 0.25, 0));
  CHECK(unary_op(ast::UnaryOp::Neg, a, {}).v == glm::dvec3(-1, -2, -3));
  // A number with a vector or color stands for all three components (POV-Ray, GLSL).
  CHECK(binary_op(BinaryOp::Add, a, Value::number(1), {}).v == glm::dvec3(2, 3, 4));
  CHECK(binary_op(BinaryOp::Sub, Value::number(1), a, {}).v == glm::dvec3(0, -1, -2));
  CHECK(binary_op(BinaryOp::Div, Value::number(6), a, {}).v == glm::dvec3(6, 3, 2));
  Value d = binary_op(BinaryOp::Sub, Value::color({1, 0.5, 0.25}), Value::number(0.25), {});
  CHECK(d.type == Type::Color);
  CHECK(d.v == glm::dvec3(0.75, 0.25, 0));
}

TEST_CASE("operator type errors name both operands", "[values]") {
  CHECK(op_error(BinaryOp::Add, Value::vector({1, 2, 3}), Value::string("x")) == "cannot add a vector and a string");
  CHECK(op_error(BinaryOp::Add, Value::vector({1, 2, 3}), Value::color({1, 2, 3})) ==
        "cannot add a vector and a color");
  CHECK(op_error(BinaryOp::Sub, Value::string("x"), Value::vector({1, 2, 3})) == "cannot subtract a string and a vector");
  CHECK(op_error(BinaryOp::Mod, Value::vector({1, 2, 3}), Value::number(2)) == "cannot take the remainder of a vector and a number");
  CHECK(op_error(BinaryOp::Lt, Value::vector({1, 2, 3}), Value::number(1)).find("cannot compare") == 0);
}

TEST_CASE("division by zero and non-finite results are errors", "[values]") {
  CHECK(op_error(BinaryOp::Div, Value::number(1), Value::number(0)) == "division by zero");
  CHECK(op_error(BinaryOp::Div, Value::vector({1, 1, 1}), Value::number(0)) == "division by zero");
  CHECK(op_error(BinaryOp::Div, Value::number(1), Value::vector({1, 0, 1})) == "division by zero");
  CHECK(op_error(BinaryOp::Pow, Value::number(10), Value::number(400)) == "arithmetic produced an infinite value");
  CHECK(op_error(BinaryOp::Pow, Value::number(-8), Value::number(1.0 / 3)) == "arithmetic produced NaN (not a number)");
}

TEST_CASE("strings and lists concatenate", "[values]") {
  CHECK(as_string(binary_op(BinaryOp::Add, Value::string("ab"), Value::string("cd"), {})) == "abcd");
  Value l = binary_op(BinaryOp::Add, Value::list({Value::number(1)}), Value::list({Value::number(2)}), {});
  CHECK(as_list(l).size() == 2);
  CHECK(as_list(l)[1].num() == 2);
}

TEST_CASE("equality is structural for plain values", "[values]") {
  CHECK(
      equal(Value::list({Value::number(1), Value::string("a")}), Value::list({Value::number(1), Value::string("a")})));
  CHECK_FALSE(equal(Value::number(1), Value::boolean(true)));
  CHECK_FALSE(equal(Value::vector({1, 2, 3}), Value::color({1, 2, 3})));
}

TEST_CASE("text forms", "[values]") {
  CHECK(to_text(Value::number(3)) == "3");
  CHECK(to_text(Value::number(0.25)) == "0.25");
  CHECK(to_text(Value::number(-0.0)) == "0");
  CHECK(to_text(Value::vector({1, -2, 0.5})) == "<1, -2, 0.5>");
  CHECK(to_text(Value::color({1, 0, 0})) == "rgb(1, 0, 0)");
  CHECK(to_text(Value::list({Value::number(1), Value::string("a")})) == "[1, \"a\"]");
  CHECK(to_text(Value::boolean(false)) == "false");
}

TEST_CASE("range counts follow the end rule", "[values]") {
  auto range = [](double a, double b, double s, bool inc) {
    Value r;
    r.type = Type::Range;
    r.v = {a, b, s};
    r.inclusive = inc;
    return r;
  };
  CHECK(range_count(range(0, 20, 1, false)) == 20);
  CHECK(range_count(range(0, 20, 1, true)) == 21);
  CHECK(range_count(range(0, 20, 2, false)) == 10);
  CHECK(range_count(range(0, 1, 0.1, true)) == 11);  // 1.0 included despite rounding
  CHECK(range_count(range(0, 1, 0.25, false)) == 4);
  CHECK(range_count(range(5, 0, -1, false)) == 5);
  CHECK(range_count(range(5, 0, 1, false)) == 0);
  CHECK(range_at(range(0, 1, 0.1, true), 10) == Approx(1.0));
}

TEST_CASE("random streams are splitmix64: deterministic and uniform", "[values][random]") {
  RandomValue a(0), b(0), c(1);
  // The reference splitmix64 output for seed 0 (Vigna's splitmix64.c).
  CHECK(a.next_u64() == 0xE220A8397B1DCDAFull);
  b.next_u64();
  for (int i = 0; i < 100; ++i) CHECK(a.next_u64() == b.next_u64());
  RandomValue d(1);
  CHECK(c.next_u64() == d.next_u64());
  RandomValue e(42);
  double sum = 0;
  constexpr int kDraws = 10000;
  for (int i = 0; i < kDraws; ++i) {
    double u = e.next_unit();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    sum += u;
  }
  CHECK(sum / kDraws == Approx(0.5).margin(0.02));
}
