#include "runtime/ops.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "parser/diagnostics.hpp"

namespace rts::runtime {

namespace {

// A range end this close (relative to the step) to a value counts as reached, so that
// `0 ..= 1 step 0.1` includes 1 despite 0.1 not being exact in binary.
constexpr double kRangeEndTolerance = 1e-9;

const char* verb(ast::BinaryOp op) {
  switch (op) {
    case ast::BinaryOp::Add:
      return "add";
    case ast::BinaryOp::Sub:
      return "subtract";
    case ast::BinaryOp::Mul:
      return "multiply";
    case ast::BinaryOp::Div:
      return "divide";
    case ast::BinaryOp::Mod:
      return "take the remainder of";
    case ast::BinaryOp::Pow:
      return "raise";
    default:
      return "compare";
  }
}

[[noreturn]] void type_error(ast::BinaryOp op, const Value& a, const Value& b, SourceLoc loc) {
  if (op == ast::BinaryOp::Pow)
    throw LanguageError(loc,
                        fmt::format("cannot raise {} to the power of {}", with_article(a.type), with_article(b.type)));
  throw LanguageError(loc, fmt::format("cannot {} {} and {}", verb(op), with_article(a.type), with_article(b.type)));
}

double arith(ast::BinaryOp op, double x, double y, SourceLoc loc) {
  switch (op) {
    case ast::BinaryOp::Add:
      return x + y;
    case ast::BinaryOp::Sub:
      return x - y;
    case ast::BinaryOp::Mul:
      return x * y;
    case ast::BinaryOp::Div:
      if (y == 0.0) throw LanguageError(loc, "division by zero");
      return x / y;
    case ast::BinaryOp::Mod:
      if (y == 0.0) throw LanguageError(loc, "remainder of division by zero");
      return std::fmod(x, y);
    case ast::BinaryOp::Pow:
      return std::pow(x, y);
    default:
      return 0.0;
  }
}

bool is_arith(ast::BinaryOp op) {
  return op == ast::BinaryOp::Add || op == ast::BinaryOp::Sub || op == ast::BinaryOp::Mul || op == ast::BinaryOp::Div ||
         op == ast::BinaryOp::Mod || op == ast::BinaryOp::Pow;
}

bool is_triple(Type t) { return t == Type::Vector || t == Type::Color; }

}  // namespace

void check_finite(double x, SourceLoc loc, const char* what) {
  if (std::isfinite(x)) return;
  throw LanguageError(loc,
                      fmt::format("{} produced {}", what, std::isnan(x) ? "NaN (not a number)" : "an infinite value"));
}

Value binary_op(ast::BinaryOp op, const Value& a, const Value& b, SourceLoc loc) {
  using ast::BinaryOp;
  // The hot path: two numbers.
  if (a.type == Type::Number && b.type == Type::Number) {
    double x = a.v.x, y = b.v.x;
    switch (op) {
      case BinaryOp::Lt:
        return Value::boolean(x < y);
      case BinaryOp::Le:
        return Value::boolean(x <= y);
      case BinaryOp::Gt:
        return Value::boolean(x > y);
      case BinaryOp::Ge:
        return Value::boolean(x >= y);
      case BinaryOp::Eq:
        return Value::boolean(x == y);
      case BinaryOp::Ne:
        return Value::boolean(x != y);
      case BinaryOp::And:
      case BinaryOp::Or:
        break;
      default: {
        double r = arith(op, x, y, loc);
        check_finite(r, loc, "arithmetic");
        return Value::number(r);
      }
    }
  }
  if (op == BinaryOp::Eq) return Value::boolean(equal(a, b));
  if (op == BinaryOp::Ne) return Value::boolean(!equal(a, b));
  if (op == BinaryOp::Lt || op == BinaryOp::Le || op == BinaryOp::Gt || op == BinaryOp::Ge) {
    if (a.type == Type::String && b.type == Type::String) {
      int c = as_string(a).compare(as_string(b));
      bool r = op == BinaryOp::Lt ? c < 0 : op == BinaryOp::Le ? c <= 0 : op == BinaryOp::Gt ? c > 0 : c >= 0;
      return Value::boolean(r);
    }
    throw LanguageError(loc, fmt::format("cannot compare {} and {} with '{}' (only numbers and strings are ordered)",
                                         with_article(a.type), with_article(b.type), ast::to_string(op)));
  }
  if (op == BinaryOp::And || op == BinaryOp::Or)
    throw LanguageError(loc, fmt::format("'{}' needs two bools, got {} and {}", ast::to_string(op),
                                         with_article(a.type), with_article(b.type)));
  if (!is_arith(op)) type_error(op, a, b, loc);

  // Vectors and colors, component-wise (never mixed with each other); a number with one of
  // them stands for all three components, as in POV-Ray and GLSL (`v + 1`, `1 / v`).
  if (op != BinaryOp::Pow && op != BinaryOp::Mod) {
    glm::dvec3 r;
    Type t;
    if (is_triple(a.type) && a.type == b.type) {
      t = a.type;
      for (int i = 0; i < 3; ++i) r[i] = arith(op, a.v[i], b.v[i], loc);
    } else if (is_triple(a.type) && b.type == Type::Number) {
      t = a.type;
      for (int i = 0; i < 3; ++i) r[i] = arith(op, a.v[i], b.v.x, loc);
    } else if (a.type == Type::Number && is_triple(b.type)) {
      t = b.type;
      for (int i = 0; i < 3; ++i) r[i] = arith(op, a.v.x, b.v[i], loc);
    } else if (a.type == Type::String && b.type == Type::String && op == BinaryOp::Add) {
      return Value::string(as_string(a) + as_string(b));
    } else if (a.type == Type::List && b.type == Type::List && op == BinaryOp::Add) {
      std::vector<Value> items = as_list(a);
      items.insert(items.end(), as_list(b).begin(), as_list(b).end());
      return Value::list(std::move(items));
    } else {
      type_error(op, a, b, loc);
    }
    for (int i = 0; i < 3; ++i) check_finite(r[i], loc, "arithmetic");
    Value out;
    out.type = t;
    out.v = r;
    return out;
  }
  type_error(op, a, b, loc);
}

Value unary_op(ast::UnaryOp op, const Value& a, SourceLoc loc) {
  switch (op) {
    case ast::UnaryOp::Not:
      if (a.type != Type::Bool)
        throw LanguageError(loc, fmt::format("'not' needs a bool, got {}", with_article(a.type)));
      return Value::boolean(!a.truth());
    case ast::UnaryOp::Neg:
    case ast::UnaryOp::Plus:
      if (a.type == Type::Number || is_triple(a.type)) {
        Value r = a;
        if (op == ast::UnaryOp::Neg) r.v = -r.v;
        return r;
      }
      throw LanguageError(loc, fmt::format("cannot negate {}", with_article(a.type)));
  }
  return a;
}

uint64_t range_count(const Value& r) {
  double from = r.v.x, to = r.v.y, step = r.v.z;
  double span = (to - from) / step;  // how many steps fit
  double tol = kRangeEndTolerance;
  if (span < -tol) return 0;
  double n;
  if (r.inclusive) {
    n = std::floor(span + tol) + 1;
  } else {
    n = std::ceil(span - tol);
  }
  if (n <= 0) return 0;
  constexpr double kMaxCount = 9.2e18;  // beyond any iteration limit; keeps the cast defined
  return static_cast<uint64_t>(std::min(n, kMaxCount));
}

}  // namespace rts::runtime
