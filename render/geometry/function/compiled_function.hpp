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
//
// What eval runs is not the built code itself (which listing() and instructions() show) but a
// linked copy made by set_result, the builder's last call: the registers renumbered so that
// the constants come first (3 .. 3 + constants - 1, copied in per eval in a few fixed-size
// blocks instead of one Const instruction each), then each computed instruction's in order
// (step j writes the next register, so no step carries its destination), then the Preset
// registers (written by their SinCos/CosSin; Preset itself runs nothing); an End step ends the
// code instead of a loop test. Where the compiler has computed goto (GCC, Clang) each step
// holds the address of its op's code and ends by jumping to the next step's (direct
// threading: no range check, no table lookup, one indirect jump per op that predicts well); a
// switch elsewhere. Same ops on the same values in the same order: the bits are the built
// code's. An isosurface runs its function (~20 instructions in the race's) hundreds of times
// per ray, and the per-instruction dispatch was most of eval's own time (docs/performance.md).
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
    End,      // the linked code's last step (never built)
  };
  static constexpr int kOps = static_cast<int>(Op::End) + 1;
  static constexpr int kMaxOperands = 6;
  struct Instr {
    Op op;
    uint16_t a[kMaxOperands];
  };
  // Registers a function may use in all (the three inputs and one per instruction).
  static constexpr std::size_t kMaxRegisters = 2048;
  static constexpr uint16_t kX = 0, kY = 1, kZ = 2;

  // An empty function (f = x) until built; linked, like every function eval runs.
  CompiledFunction() { set_result(kX); }

  // ---- building (the compiler) ----
  // The register holding constant c (equal constants share one). Returns false when full.
  bool constant(double c, uint16_t& reg);
  // Appends an instruction and gives the register it writes (an earlier register when the
  // same value is already computed: see the folding above). Returns false when full.
  bool emit(Op op, std::initializer_list<uint16_t> operands, uint16_t& reg);
  // The register whose value eval returns. The last building call: it links the code that
  // eval runs (see above), so an emit after it would not be run.
  void set_result(uint16_t reg);
  // The number of operands `op` reads.
  static int arity(Op op);
  static const char* name(Op op);

  // ---- running (the renderer) ----
  double eval(const glm::dvec3& p) const { return run(p, nullptr); }
  std::size_t instructions() const { return code_.size(); }
  std::size_t registers() const { return 3 + code_.size(); }
  // A readable listing, one instruction a line (tests and --dump).
  std::string listing() const;

 private:
  std::vector<double> constants_;
  std::vector<uint16_t> constant_regs_;   // the register holding constants_[i]
  std::vector<Instr> code_;         // instruction i writes register 3 + i
  uint16_t result_ = kX;
  // The linked form (set_result): steps_[j] writes register 3 + constants_.size() + j, its
  // operands renumbered; the last step is End. linked_result_ is result_ renumbered.
  struct Step {
    const void* go;   // the address of op's code in run() (direct threading; unused by the switch)
    Op op;
    uint16_t a[kMaxOperands];
  };
  std::vector<Step> steps_;
  uint16_t linked_result_ = kX;
  // constants_ padded with zeros to whole blocks of kConstBlock, at least one: run() copies
  // them in blocks of a fixed size, a few moves where a memcpy of a variable size is a call (a
  // function has 1-3 constants typically). The padding lands in registers that are written
  // before they are read, or never read.
  static constexpr std::size_t kConstBlock = 4;
  std::vector<double> linked_constants_;
  // The interpreter. Given `targets`, it only stores there its table of each op's code address
  // (indexed by Op; null without computed goto) and returns: the addresses are local to run(),
  // which GCC and Clang therefore never inline or clone, so they are the same on every call.
  double run(const glm::dvec3& p, const void* const** targets) const;
  // Building only: each instruction emitted so far (its op and operands as a key) -> the
  // register holding its value, for the folding.
  std::unordered_map<std::string, uint16_t> seen_;
  bool is_constant(uint16_t reg, double value) const;
};

}  // namespace rts::render
