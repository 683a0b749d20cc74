// Reading a builtin's arguments with a located "argument N of 'name' must be ..." error:
// shared by every file of builtins (builtins.cpp, builtins_math.cpp).
#pragma once

#include <cstddef>
#include <string>

#include <fmt/format.h>

#include "runtime/interpreter.hpp"
#include "runtime/ops.hpp"

namespace rts::runtime::builtin_args {

inline SourceLoc arg_loc(const BuiltinCall& c, std::size_t i) { return c.call.args[i].value->loc; }

[[noreturn]] inline void bad_arg(const BuiltinCall& c, std::size_t i, const char* expected) {
  c.in.fail(arg_loc(c, i), fmt::format("argument {} of '{}' must be {}, got {}", i + 1, c.def.name, expected,
                                       with_article(c.args[i].type)));
}

inline double num(const BuiltinCall& c, std::size_t i) {
  if (c.args[i].type != Type::Number) bad_arg(c, i, "a number");
  return c.args[i].v.x;
}
inline glm::dvec3 vec(const BuiltinCall& c, std::size_t i) {
  if (c.args[i].type != Type::Vector) bad_arg(c, i, "a vector");
  return c.args[i].v;
}
inline const std::string& str(const BuiltinCall& c, std::size_t i) {
  if (c.args[i].type != Type::String) bad_arg(c, i, "a string");
  return as_string(c.args[i]);
}

// select(c, a, b) with a condition that is not a bool (a POV-Ray habit: its select tests A < 0).
[[noreturn]] inline void bad_select_condition(const Interpreter& in, const ast::CallExpr& call, const Value& cond) {
  in.fail(call.args[0].value->loc,
          fmt::format("the condition of 'select' must be a bool, got {} (POV-Ray's select(A, B, C) picks B "
                      "when A < 0: write select(A < 0, B, C))",
                      with_article(cond.type)));
}

}  // namespace rts::runtime::builtin_args
