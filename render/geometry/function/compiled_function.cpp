// Straight-line register code for user functions: see compiled_function.hpp.
#include "render/geometry/function/compiled_function.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

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
    case Op::Const: case Op::Preset: return 0;
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
      "preset"};
  return names[static_cast<int>(op)];
}

double CompiledFunction::eval(const glm::dvec3& p) const {
  double r[kMaxRegisters];
  r[kX] = p.x;
  r[kY] = p.y;
  r[kZ] = p.z;
  double* out = r + 3;
  for (const Instr& in : code_) {
    const uint16_t* a = in.a;
    double v;
    switch (in.op) {
      case Op::Const: v = constants_[a[0]]; break;
      case Op::Add: v = r[a[0]] + r[a[1]]; break;
      case Op::Sub: v = r[a[0]] - r[a[1]]; break;
      case Op::Mul: v = r[a[0]] * r[a[1]]; break;
      case Op::Div: v = r[a[0]] / r[a[1]]; break;
      case Op::Mod: v = std::fmod(r[a[0]], r[a[1]]); break;
      case Op::Pow: v = std::pow(r[a[0]], r[a[1]]); break;
      case Op::Min: v = std::min(r[a[0]], r[a[1]]); break;
      case Op::Max: v = std::max(r[a[0]], r[a[1]]); break;
      case Op::Atan2: v = std::atan2(r[a[0]], r[a[1]]); break;
      case Op::Lt: v = r[a[0]] < r[a[1]]; break;
      case Op::Le: v = r[a[0]] <= r[a[1]]; break;
      case Op::Gt: v = r[a[0]] > r[a[1]]; break;
      case Op::Ge: v = r[a[0]] >= r[a[1]]; break;
      case Op::Eq: v = r[a[0]] == r[a[1]]; break;
      case Op::Ne: v = r[a[0]] != r[a[1]]; break;
      case Op::And: v = r[a[0]] != 0.0 && r[a[1]] != 0.0; break;
      case Op::Or: v = r[a[0]] != 0.0 || r[a[1]] != 0.0; break;
      case Op::Neg: v = -r[a[0]]; break;
      case Op::Not: v = r[a[0]] == 0.0; break;
      case Op::Sin: v = std::sin(r[a[0]]); break;
      case Op::Cos: v = std::cos(r[a[0]]); break;
      case Op::Tan: v = std::tan(r[a[0]]); break;
      case Op::Asin: v = std::asin(r[a[0]]); break;
      case Op::Acos: v = std::acos(r[a[0]]); break;
      case Op::Atan: v = std::atan(r[a[0]]); break;
      case Op::Sqrt: v = std::sqrt(r[a[0]]); break;
      case Op::Exp: v = std::exp(r[a[0]]); break;
      case Op::Log: v = std::log(r[a[0]]); break;
      case Op::Abs: v = std::fabs(r[a[0]]); break;
      case Op::Floor: v = std::floor(r[a[0]]); break;
      case Op::Ceil: v = std::ceil(r[a[0]]); break;
      case Op::Round: v = std::round(r[a[0]]); break;
      case Op::Select: v = r[a[0]] != 0.0 ? r[a[1]] : r[a[2]]; break;
      case Op::Clamp: v = std::min(std::max(r[a[0]], r[a[1]]), r[a[2]]); break;
      case Op::Mix: v = r[a[0]] + (r[a[1]] - r[a[0]]) * r[a[2]]; break;
      case Op::Noise: v = pattern::noise01({r[a[0]], r[a[1]], r[a[2]]}); break;
      case Op::Fbm:
        v = pattern::fbm({r[a[0]], r[a[1]], r[a[2]]}, octaves_of(r[a[3]]), r[a[4]], r[a[5]]);
        break;
      case Op::Turbulence:
        v = pattern::turbulence({r[a[0]], r[a[1]], r[a[2]]}, octaves_of(r[a[3]]), r[a[4]], r[a[5]]);
        break;
      case Op::Cells: v = pattern::cells({r[a[0]], r[a[1]], r[a[2]]}); break;
      case Op::Worley: v = pattern::worley({r[a[0]], r[a[1]], r[a[2]]}); break;
      case Op::SinCos: ::sincos(r[a[0]], &v, &r[a[1]]); break;
      case Op::CosSin: ::sincos(r[a[0]], &r[a[1]], &v); break;
      case Op::Preset: v = *out; break;
      default: v = 0.0; break;
    }
    *out++ = v;
  }
  const double result = r[result_];
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
