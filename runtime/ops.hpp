// Operators on values: arithmetic, comparison, unary. Each throws LanguageError at `loc`
// for operand types it does not accept ("cannot add a vector and a string"), division by zero,
// and results that are not finite numbers.
#pragma once

#include "parser/ast.hpp"
#include "runtime/value.hpp"

namespace rts::runtime {

Value binary_op(ast::BinaryOp op, const Value& a, const Value& b, SourceLoc loc);
Value unary_op(ast::UnaryOp op, const Value& a, SourceLoc loc);

// Throws at `loc` when x is NaN or infinite ("arithmetic produced an infinite value").
void check_finite(double x, SourceLoc loc, const char* what);

// How many values `from .. to step s` yields (range end excluded unless inclusive). A step of
// zero has been rejected when the range was made.
uint64_t range_count(const Value& range);
// The k-th value of a range (from + k * step: no accumulated rounding error).
inline double range_at(const Value& range, uint64_t k) { return range.v.x + static_cast<double>(k) * range.v.z; }

}  // namespace rts::runtime
