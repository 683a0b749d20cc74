// A function of a point, f(x, y, z) -> number, compiled ONCE from the scene language (see
// runtime/function_compiler.cpp) into straight-line register code that the renderer runs per
// sample without touching the AST: user-defined patterns (`pattern { function = f }`) use it,
// and isosurfaces (`isosurface { function = f }`) can use the same form.
//
// The form: registers of doubles; 0, 1, 2 hold x, y, z; instruction i writes register 3 + i
// (each writes a fresh one, so there is no aliasing to reason about; a constant is an
// instruction too, `Const`, shared by every use of the same value). Vectors of the language are three registers each (the compiler scalarises them), so
// the renderer only ever sees numbers. Comparisons give 0 or 1; `Select` picks without a
// branch (both sides are computed: they are pure and cheap). The noise family calls the same
// functions as the pattern textures (render/geometry/function/noise.hpp).
//
// Evaluation allocates nothing: the registers live in a fixed array on the stack
// (kMaxRegisters bounds a function's size; the compiler reports a located error past it).
// A non-finite intermediate result is allowed; eval() maps a NaN result to 0 (never a NaN
// colour or a NaN isosurface step).
//
// Building folds what gives the same bits for less work (isosurfaces evaluate f hundreds of
// times per ray, and an isosurface's time is mostly f): an instruction equal to an earlier one
// (same op, same operands: every op is pure) reuses its register; `pow(a, 2)` is `a * a`
// (glibc's pow is exact there); and a `sin` and a `cos` of the same register are one
// `sincos` call (glibc computes both with the same code as `sin` and `cos`), the first of the
// two becoming SinCos/CosSin, which also writes the second's register, and the second
// Preset, which keeps the value already written. tests/render/test_noise.cpp checks each
// against the unfolded functions bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

namespace rts::render {

class CompiledFunction {
 public:
  enum class Op : uint8_t {
    Const,    // constants_[a0]
    // two operands (a0, a1)
    Add, Sub, Mul, Div, Mod, Pow, Min, Max, Atan2, Lt, Le, Gt, Ge, Eq, Ne, And, Or,
    // one operand (a0)
    Neg, Not, Sin, Cos, Tan, Asin, Acos, Atan, Sqrt, Exp, Log, Abs, Floor, Ceil, Round,
    // three operands
    Select,   // a0 != 0 ? a1 : a2
    Clamp,    // clamp(a0, a1, a2)
    Mix,      // a0 + (a1 - a0) * a2
    // the noise family: a point (a0, a1, a2) and, for the sums, octaves a3, lambda a4, omega a5
    Noise,    // noise01 in [0, 1]
    Fbm, Turbulence, Cells, Worley,
    // folded forms (see above): a0 the argument, a1 the register that gets the other result
    SinCos, CosSin,
    Preset,   // the value is already in this instruction's register
  };
  static constexpr int kMaxOperands = 6;
  struct Instr {
    Op op;
    uint16_t a[kMaxOperands];
  };
  // Registers a function may use in all (the three inputs and one per instruction).
  static constexpr std::size_t kMaxRegisters = 2048;
  static constexpr uint16_t kX = 0, kY = 1, kZ = 2;

  CompiledFunction() = default;

  // ---- building (the compiler) ----
  // The register holding constant c (equal constants share one). Returns false when full.
  bool constant(double c, uint16_t& reg);
  // Appends an instruction and gives the register it writes (an earlier register when the
  // same value is already computed: see the folding above). Returns false when full.
  bool emit(Op op, std::initializer_list<uint16_t> operands, uint16_t& reg);
  void set_result(uint16_t reg) { result_ = reg; }
  // The number of operands `op` reads.
  static int arity(Op op);
  static const char* name(Op op);

  // ---- running (the renderer) ----
  double eval(const glm::dvec3& p) const;
  std::size_t instructions() const { return code_.size(); }
  std::size_t registers() const { return 3 + code_.size(); }
  // A readable listing, one instruction a line (tests and --dump).
  std::string listing() const;

 private:
  std::vector<double> constants_;
  std::vector<uint16_t> constant_regs_;   // the register holding constants_[i]
  std::vector<Instr> code_;         // instruction i writes register 3 + i
  uint16_t result_ = kX;
  // Building only: each instruction emitted so far (its op and operands as a key) -> the
  // register holding its value, for the folding.
  std::unordered_map<std::string, uint16_t> seen_;
  bool is_constant(uint16_t reg, double value) const;
};

}  // namespace rts::render
