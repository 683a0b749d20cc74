// Straight-line register code for user functions: see compiled_function.hpp.
#include "render/geometry/function/compiled_function.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>

#include <fmt/format.h>

#include "render/geometry/function/noise.hpp"

namespace rts::render {

namespace {

int octaves_of(double x) {
  if (!(x >= 1.0)) return 1;
  return x >= pattern::kMaxOctaves ? pattern::kMaxOctaves : static_cast<int>(x);
}

}  // namespace

bool CompiledFunction::constant(double c, uint16_t& reg) {
  for (std::size_t i = 0; i < constants_.size(); ++i) {
    // Bitwise equality: 0.0 and -0.0 stay distinct, so folding never changes a sign.
    if (std::memcmp(&constants_[i], &c, sizeof c) == 0) {
      reg = constant_regs_[i];
      return true;
    }
  }
  if (!emit(Op::Const, {static_cast<uint16_t>(constants_.size())}, reg)) return false;
  constants_.push_back(c);
  constant_regs_.push_back(reg);
  return true;
}

namespace {

std::string key_of(CompiledFunction::Op op, const uint16_t* a) {
  std::string k(1, static_cast<char>(op));
  k.append(reinterpret_cast<const char*>(a), CompiledFunction::kMaxOperands * sizeof(uint16_t));
  return k;
}

}  // namespace

bool CompiledFunction::is_constant(uint16_t reg, double value) const {
  if (reg < 3 || reg - 3u >= code_.size() || code_[reg - 3].op != Op::Const) return false;
  return constants_[code_[reg - 3].a[0]] == value;
}

bool CompiledFunction::emit(Op op, std::initializer_list<uint16_t> operands, uint16_t& reg) {
  Instr in{op, {}};
  int i = 0;
  for (uint16_t o : operands) in.a[i++] = o;
  if (op == Op::Pow && is_constant(in.a[1], 2.0)) in = Instr{Op::Mul, {in.a[0], in.a[0]}};
  std::string key = key_of(in.op, in.a);
  if (auto it = seen_.find(key); it != seen_.end()) {
    reg = it->second;
    return true;
  }
  if (registers() >= kMaxRegisters) return false;
  // The other half of a sin/cos pair already emitted: that instruction computes both.
  const Op partner = op == Op::Sin ? Op::Cos : op == Op::Cos ? Op::Sin : Op::Const;
  Instr pk{partner, {in.a[0]}};
  auto other = partner == Op::Const ? seen_.end() : seen_.find(key_of(pk.op, pk.a));
  if (other != seen_.end() && code_[other->second - 3].op == partner) {
    reg = static_cast<uint16_t>(registers());
    code_[other->second - 3] = Instr{partner == Op::Sin ? Op::SinCos : Op::CosSin, {in.a[0], reg}};
    in = Instr{Op::Preset, {}};
  } else {
    reg = static_cast<uint16_t>(registers());
  }
  code_.push_back(in);
  seen_.emplace(std::move(key), reg);
  return true;
}

int CompiledFunction::arity(Op op) {
  switch (op) {
    case Op::Const: case Op::Preset: case Op::End: return 0;
    case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Mod: case Op::Pow: case Op::Min:
    case Op::Max: case Op::Atan2: case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne:
    case Op::And: case Op::Or: return 2;
    case Op::Select: case Op::Clamp: case Op::Mix: case Op::Noise: case Op::Cells: case Op::Worley: return 3;
    case Op::Fbm: case Op::Turbulence: return 6;
    default: return 1;
  }
}

const char* CompiledFunction::name(Op op) {
  static const char* const names[] = {
      "const", "add",  "sub",  "mul",  "div",   "mod",   "pow",   "min",    "max",   "atan2", "lt",
      "le",    "gt",   "ge",   "eq",   "ne",    "and",   "or",    "neg",    "not",   "sin",   "cos",
      "tan",   "asin", "acos", "atan", "sqrt",  "exp",   "log",   "abs",    "floor", "ceil",  "round",
      "select", "clamp", "mix", "noise", "fbm", "turbulence", "cells", "worley", "sincos", "cossin",
      "preset", "end"};
  static_assert(std::size(names) == kOps);
  return names[static_cast<int>(op)];
}

void CompiledFunction::set_result(uint16_t reg) {
  result_ = reg;
  // The linked registers: x, y, z; the constants in constants_' order; each computed
  // instruction's in code order; then the Preset registers (their values come from the
  // SinCos/CosSin emitted before them, so placing them after every step's is free).
  const std::size_t n = code_.size();
  std::vector<uint16_t> to(3 + n);
  for (uint16_t i = 0; i < 3; ++i) to[i] = i;
  uint16_t next = static_cast<uint16_t>(3 + constants_.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Instr& in = code_[i];
    if (in.op == Op::Const) to[3 + i] = static_cast<uint16_t>(3 + in.a[0]);
    else if (in.op != Op::Preset) to[3 + i] = next++;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (code_[i].op == Op::Preset) to[3 + i] = next++;
  const void* const* targets = nullptr;
  run(glm::dvec3(0.0), &targets);
  auto go = [&](Op op) { return targets ? targets[static_cast<int>(op)] : nullptr; };
  steps_.clear();
  for (const Instr& in : code_) {
    if (in.op == Op::Const || in.op == Op::Preset) continue;
    Step step{go(in.op), in.op, {}};
    // Unused operands are 0, which stays 0; SinCos/CosSin's a1 (the partner's register) is
    // renumbered with the rest.
    for (int k = 0; k < kMaxOperands; ++k) step.a[k] = to[in.a[k]];
    steps_.push_back(step);
  }
  steps_.push_back(Step{go(Op::End), Op::End, {}});
  linked_constants_ = constants_;
  linked_constants_.resize(std::max<std::size_t>(1, (constants_.size() + kConstBlock - 1) / kConstBlock) * kConstBlock,
                           0.0);
  linked_result_ = to[reg];
}

// Direct threading where the compiler has computed goto (GCC, Clang): each step's code ends by
// jumping to the address the next step holds, with no range check and no table lookup, and
// (for most ops: GCC shares a few tails) from a jump of its own, which predicts better than one
// shared switch jump. The switch is the portable form (-DRTS_CF_THREADED=0 builds it).
#ifndef RTS_CF_THREADED
#if defined(__GNUC__)
#define RTS_CF_THREADED 1
#else
#define RTS_CF_THREADED 0
#endif
#endif

double CompiledFunction::run(const glm::dvec3& p, const void* const** targets) const {
#define A(k) r[s->a[k]]
#if RTS_CF_THREADED
  // In Op's order (checked by its size; a misplaced entry fails the folding and compiler tests).
  static const void* const kTarget[] = {
      &&L_Const, &&L_Add, &&L_Sub, &&L_Mul, &&L_Div, &&L_Mod, &&L_Pow, &&L_Min, &&L_Max, &&L_Atan2,
      &&L_Lt, &&L_Le, &&L_Gt, &&L_Ge, &&L_Eq, &&L_Ne, &&L_And, &&L_Or, &&L_Neg, &&L_Not, &&L_Sin,
      &&L_Cos, &&L_Tan, &&L_Asin, &&L_Acos, &&L_Atan, &&L_Sqrt, &&L_Exp, &&L_Log, &&L_Abs,
      &&L_Floor, &&L_Ceil, &&L_Round, &&L_Select, &&L_Clamp, &&L_Mix, &&L_Noise, &&L_Fbm,
      &&L_Turbulence, &&L_Cells, &&L_Worley, &&L_SinCos, &&L_CosSin, &&L_Preset, &&L_End};
  static_assert(std::size(kTarget) == kOps);
#endif
  if (targets) {
#if RTS_CF_THREADED
    *targets = kTarget;
#else
    *targets = nullptr;
#endif
    return 0.0;
  }
  double r[kMaxRegisters + kConstBlock];   // room for the last block's padding
  r[kX] = p.x;
  r[kY] = p.y;
  r[kZ] = p.z;
  // The first block always (linked_constants_ holds at least one), then the rest.
  const double* c = linked_constants_.data();
  std::memcpy(r + 3, c, kConstBlock * sizeof(double));
  for (std::size_t i = kConstBlock, n = linked_constants_.size(); i < n; i += kConstBlock)
    std::memcpy(r + 3 + i, c + i, kConstBlock * sizeof(double));
  double* out = r + 3 + constants_.size();
  const Step* s = steps_.data();
#if RTS_CF_THREADED
#define STEP(o) L_##o
#define NEXT \
  ++s;       \
  goto* s->go
  goto* s->go;
#else
#define STEP(o) case Op::o
#define NEXT \
  ++s;       \
  continue
  for (;;) switch (s->op) {
#endif
  STEP(Add): *out++ = A(0) + A(1); NEXT;
  STEP(Sub): *out++ = A(0) - A(1); NEXT;
  STEP(Mul): *out++ = A(0) * A(1); NEXT;
  STEP(Div): *out++ = A(0) / A(1); NEXT;
  STEP(Mod): *out++ = std::fmod(A(0), A(1)); NEXT;
  STEP(Pow): *out++ = std::pow(A(0), A(1)); NEXT;
  STEP(Min): *out++ = std::min(A(0), A(1)); NEXT;
  STEP(Max): *out++ = std::max(A(0), A(1)); NEXT;
  STEP(Atan2): *out++ = std::atan2(A(0), A(1)); NEXT;
  STEP(Lt): *out++ = A(0) < A(1); NEXT;
  STEP(Le): *out++ = A(0) <= A(1); NEXT;
  STEP(Gt): *out++ = A(0) > A(1); NEXT;
  STEP(Ge): *out++ = A(0) >= A(1); NEXT;
  STEP(Eq): *out++ = A(0) == A(1); NEXT;
  STEP(Ne): *out++ = A(0) != A(1); NEXT;
  STEP(And): *out++ = A(0) != 0.0 && A(1) != 0.0; NEXT;
  STEP(Or): *out++ = A(0) != 0.0 || A(1) != 0.0; NEXT;
  STEP(Neg): *out++ = -A(0); NEXT;
  STEP(Not): *out++ = A(0) == 0.0; NEXT;
  STEP(Sin): *out++ = std::sin(A(0)); NEXT;
  STEP(Cos): *out++ = std::cos(A(0)); NEXT;
  STEP(Tan): *out++ = std::tan(A(0)); NEXT;
  STEP(Asin): *out++ = std::asin(A(0)); NEXT;
  STEP(Acos): *out++ = std::acos(A(0)); NEXT;
  STEP(Atan): *out++ = std::atan(A(0)); NEXT;
  STEP(Sqrt): *out++ = std::sqrt(A(0)); NEXT;
  STEP(Exp): *out++ = std::exp(A(0)); NEXT;
  STEP(Log): *out++ = std::log(A(0)); NEXT;
  STEP(Abs): *out++ = std::fabs(A(0)); NEXT;
  STEP(Floor): *out++ = std::floor(A(0)); NEXT;
  STEP(Ceil): *out++ = std::ceil(A(0)); NEXT;
  STEP(Round): *out++ = std::round(A(0)); NEXT;
  STEP(Select): *out++ = A(0) != 0.0 ? A(1) : A(2); NEXT;
  STEP(Clamp): *out++ = std::min(std::max(A(0), A(1)), A(2)); NEXT;
  STEP(Mix): *out++ = A(0) + (A(1) - A(0)) * A(2); NEXT;
  STEP(Noise): *out++ = pattern::noise01({A(0), A(1), A(2)}); NEXT;
  STEP(Fbm): *out++ = pattern::fbm({A(0), A(1), A(2)}, octaves_of(A(3)), A(4), A(5)); NEXT;
  STEP(Turbulence): *out++ = pattern::turbulence({A(0), A(1), A(2)}, octaves_of(A(3)), A(4), A(5)); NEXT;
  STEP(Cells): *out++ = pattern::cells({A(0), A(1), A(2)}); NEXT;
  STEP(Worley): *out++ = pattern::worley({A(0), A(1), A(2)}); NEXT;
  STEP(SinCos): ::sincos(A(0), out++, &A(1)); NEXT;
  STEP(CosSin): ::sincos(A(0), &A(1), out++); NEXT;
  // Const and Preset are never linked; End is the last step.
  STEP(Const): STEP(Preset): STEP(End): goto done;
#if !RTS_CF_THREADED
  }
#endif
#undef NEXT
#undef STEP
#undef A
done:
  const double result = r[linked_result_];
  return std::isnan(result) ? 0.0 : result;
}

std::string CompiledFunction::listing() const {
  std::string s;
  for (std::size_t i = 0; i < code_.size(); ++i) {
    const Instr& in = code_[i];
    s += fmt::format("r{} = {}", i + 3, name(in.op));
    if (in.op == Op::Const) {
      s += fmt::format(" {}", constants_[in.a[0]]);
    } else {
      for (int k = 0; k < arity(in.op); ++k) s += fmt::format(" r{}", in.a[k]);
      if (in.op == Op::SinCos || in.op == Op::CosSin) s += fmt::format(" (and r{})", in.a[1]);
    }
    s += '\n';
  }
  s += fmt::format("return r{}\n", result_);
  return s;
}

}  // namespace rts::render
