// Compiles a macro of one point into the renderer's register code (render/scene/
// compiled_function.hpp), once, when the texture (or isosurface) that holds it is built. The
// renderer then evaluates the code per sample; the AST is never walked again.
//
// What a compiled macro may contain (anything else is a located error that says so):
//  - its first parameter is the point, a vector; further parameters need defaults (numbers
//    or vectors), which are compiled like the body;
//  - `let`, assignments (=, +=, -=, *=, /=) to its own variables, `if`/`else` (both branches
//    are computed and the results selected, so either both branches `return` or neither does,
//    and a `return` inside an `if` must end the body), and `return expr` at the end;
//  - numbers, booleans, vectors, colors as vectors, + - * / % ^, comparisons, and/or/not,
//    .x .y .z (.r .g .b);
//  - global variables holding numbers, vectors, colors or bools (read once, as constants);
//  - calls of other macros (inlined, to a depth of kMaxInlineDepth), and of the builtins
//    sin cos tan asin acos atan atan2 sqrt pow exp log abs floor ceil round radians degrees
//    min max clamp mix dot cross length normalize vec rgb noise fbm turbulence cells worley.
// The noise builtins compile to the same functions the language's builtins call, so a
// compiled function and the interpreter agree exactly (tests/runtime/test_function_compiler.cpp).
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "render/geometry/function/compiled_function.hpp"
#include "runtime/interpreter.hpp"

namespace rts::runtime {

namespace {

using Op = render::CompiledFunction::Op;
using Reg = uint16_t;

// Macros calling macros are inlined; a recursive macro has no straight-line form.
constexpr int kMaxInlineDepth = 32;

// A compiled value: a number (one register) or a vector (three).
struct CV {
  bool vec = false;
  Reg r[3] = {0, 0, 0};
};

struct Local {
  ast::Symbol name;
  CV value;
};

}  // namespace

class FunctionCompiler {
 public:
  explicit FunctionCompiler(Interpreter& in) : in_(in), f_(std::make_shared<render::CompiledFunction>()) {}

  std::shared_ptr<const render::CompiledFunction> compile(const ast::MacroStmt& m) {
    if (m.params.empty())
      fail(m.loc, fmt::format("macro '{}' is used as a function of a point, so it needs a parameter (the point): "
                              "macro {}(p) {{ ... }}",
                              *m.name, *m.name));
    CV p;
    p.vec = true;
    p.r[0] = render::CompiledFunction::kX;
    p.r[1] = render::CompiledFunction::kY;
    p.r[2] = render::CompiledFunction::kZ;
    std::vector<Local> locals{{m.params[0].name, p}};
    for (std::size_t i = 1; i < m.params.size(); ++i) {
      if (!m.params[i].default_value)
        fail(m.params[i].loc, fmt::format("macro '{}' is used as a function of a point: its parameter '{}' needs a "
                                          "default value",
                                          *m.name, *m.params[i].name));
      locals.push_back({m.params[i].name, expr(*m.params[i].default_value, locals, 0)});
    }
    const CV result = inline_body(m, locals, 0);
    if (result.vec) fail(m.loc, fmt::format("macro '{}' returns a vector; a pattern function returns a number", *m.name));
    f_->set_result(result.r[0]);
    return f_;
  }

 private:
  [[noreturn]] void fail(SourceLoc loc, const std::string& message) const { in_.fail(loc, message); }

  Reg constant(double c, SourceLoc loc) {
    Reg r;
    if (!f_->constant(c, r)) too_big(loc);
    return r;
  }
  Reg emit(Op op, std::initializer_list<Reg> a, SourceLoc loc) {
    Reg r;
    if (!f_->emit(op, a, r)) too_big(loc);
    return r;
  }
  [[noreturn]] void too_big(SourceLoc loc) const {
    fail(loc, fmt::format("this function is too large to compile (more than {} steps once macros are inlined)",
                          render::CompiledFunction::kMaxRegisters));
  }
  static CV num(Reg r) {
    CV v;
    v.r[0] = r;
    return v;
  }
  static CV vec(Reg x, Reg y, Reg z) {
    CV v;
    v.vec = true;
    v.r[0] = x;
    v.r[1] = y;
    v.r[2] = z;
    return v;
  }
  Reg need_num(const CV& v, const ast::Expr& e, const char* what) const {
    if (v.vec) fail(e.loc, fmt::format("{} must be a number, got a vector", what));
    return v.r[0];
  }
  CV need_vec(const CV& v, const ast::Expr& e, const char* what) const {
    if (!v.vec) fail(e.loc, fmt::format("{} must be a vector, got a number", what));
    return v;
  }
  CV map1(Op op, const CV& a, SourceLoc loc) {
    if (!a.vec) return num(emit(op, {a.r[0]}, loc));
    return vec(emit(op, {a.r[0]}, loc), emit(op, {a.r[1]}, loc), emit(op, {a.r[2]}, loc));
  }
  CV map2(Op op, const CV& a, const CV& b, SourceLoc loc) {
    if (!a.vec && !b.vec) return num(emit(op, {a.r[0], b.r[0]}, loc));
    CV out;
    out.vec = true;
    for (int i = 0; i < 3; ++i) out.r[i] = emit(op, {a.r[a.vec ? i : 0], b.r[b.vec ? i : 0]}, loc);
    return out;
  }

  // ---- statements ----

  // Runs the macro's body with `locals` (its parameters); gives the returned value.
  CV inline_body(const ast::MacroStmt& m, std::vector<Local>& locals, int depth) {
    std::optional<CV> result = body(m.body.stmts, locals, depth);
    if (!result)
      fail(m.loc, fmt::format("macro '{}' must end with 'return' to be used as a function", *m.name));
    return *result;
  }

  // The statements of a body; returns the value of its `return` (which must come last).
  std::optional<CV> body(const ast::StmtList& stmts, std::vector<Local>& locals, int depth) {
    const std::size_t mark = locals.size();
    std::optional<CV> result;
    for (std::size_t i = 0; i < stmts.size(); ++i) {
      const ast::Stmt& s = *stmts[i];
      const bool last = i + 1 == stmts.size();
      if (result) fail(s.loc, "nothing may follow 'return' in a compiled function");
      switch (s.kind) {
        case ast::StmtKind::Let: {
          const auto& let = static_cast<const ast::LetStmt&>(s);
          locals.push_back({let.name, expr(*let.value, locals, depth)});
          break;
        }
        case ast::StmtKind::Assign: {
          const auto& a = static_cast<const ast::AssignStmt&>(s);
          Local* target = find_local(locals, a.name);
          if (!target)
            fail(s.loc, fmt::format("a compiled function can assign only its own variables; '{}' is not one", *a.name));
          CV v = expr(*a.value, locals, depth);
          static constexpr Op kOps[] = {Op::Add, Op::Add, Op::Sub, Op::Mul, Op::Div};
          if (a.op != ast::AssignOp::Set) v = arith(kOps[static_cast<int>(a.op)], target->value, v, s.loc, *a.value);
          if (v.vec != target->value.vec)
            fail(s.loc, fmt::format("'{}' holds a {}; it cannot become a {}", *a.name,
                                    target->value.vec ? "vector" : "number", v.vec ? "vector" : "number"));
          target->value = v;
          break;
        }
        case ast::StmtKind::If: result = if_stmt(static_cast<const ast::IfStmt&>(s), locals, depth, last); break;
        case ast::StmtKind::Return: {
          const auto& r = static_cast<const ast::ReturnStmt&>(s);
          if (!r.value) fail(s.loc, "a compiled function must return a number");
          result = expr(*r.value, locals, depth);
          break;
        }
        default:
          fail(s.loc, "a compiled function (a pattern or isosurface macro) may hold only 'let', assignments, "
                      "'if'/'else' and 'return'");
      }
    }
    // Variables declared in this body end with it; assignments to outer ones stay.
    locals.resize(mark);
    return result;
  }

  std::optional<CV> if_stmt(const ast::IfStmt& s, std::vector<Local>& locals, int depth, bool last) {
    const Reg cond = need_num(expr(*s.cond, locals, depth), *s.cond, "an 'if' condition");
    std::vector<Local> then_locals = locals, else_locals = locals;
    std::optional<CV> then_result = body(s.then_body.stmts, then_locals, depth);
    std::optional<CV> else_result;
    if (s.else_body) else_result = body(s.else_body->stmts, else_locals, depth);
    if (then_result.has_value() != else_result.has_value())
      fail(s.loc, "in a compiled function, an 'if' must return on both branches or on neither");
    if (then_result && !last) fail(s.loc, "in a compiled function, an 'if' that returns must end the body");
    // Merge: each variable either branch changed becomes select(cond, then, else).
    for (std::size_t i = 0; i < locals.size(); ++i) locals[i].value = select(cond, then_locals[i].value, else_locals[i].value, s.loc);
    if (!then_result) return std::nullopt;
    if (then_result->vec != else_result->vec) fail(s.loc, "the two branches of this 'if' return different types");
    return select(cond, *then_result, *else_result, s.loc);
  }

  CV select(Reg cond, const CV& a, const CV& b, SourceLoc loc) {
    CV out = a;
    for (int i = 0; i < (a.vec ? 3 : 1); ++i)
      if (a.r[i] != b.r[i]) out.r[i] = emit(Op::Select, {cond, a.r[i], b.r[i]}, loc);
    return out;
  }

  static Local* find_local(std::vector<Local>& locals, ast::Symbol name) {
    for (std::size_t i = locals.size(); i-- > 0;)
      if (locals[i].name == name) return &locals[i];
    return nullptr;
  }

  // ---- expressions ----

  CV expr(const ast::Expr& e, std::vector<Local>& locals, int depth) {
    switch (e.kind) {
      case ast::ExprKind::Number: return num(constant(static_cast<const ast::NumberExpr&>(e).value(), e.loc));
      case ast::ExprKind::Bool: return num(constant(static_cast<const ast::BoolExpr&>(e).value ? 1.0 : 0.0, e.loc));
      case ast::ExprKind::Name: return name(static_cast<const ast::NameExpr&>(e), locals);
      case ast::ExprKind::Vector: {
        const auto& v = static_cast<const ast::VectorExpr&>(e);
        if (v.components.size() != 3) fail(e.loc, "a vector has three components");
        Reg r[3];
        for (int i = 0; i < 3; ++i) r[i] = need_num(expr(*v.components[i], locals, depth), *v.components[i], "a vector component");
        return vec(r[0], r[1], r[2]);
      }
      case ast::ExprKind::Unary: {
        const auto& u = static_cast<const ast::UnaryExpr&>(e);
        CV a = expr(*u.operand, locals, depth);
        if (u.op() == ast::UnaryOp::Plus) return a;
        if (u.op() == ast::UnaryOp::Neg) return map1(Op::Neg, a, e.loc);
        return num(emit(Op::Not, {need_num(a, *u.operand, "the operand of 'not'")}, e.loc));
      }
      case ast::ExprKind::Binary: {
        const auto& b = static_cast<const ast::BinaryExpr&>(e);
        return binary(b.op(), expr(*b.lhs, locals, depth), expr(*b.rhs, locals, depth), b);
      }
      case ast::ExprKind::Member: {
        const auto& m = static_cast<const ast::MemberExpr&>(e);
        CV v = expr(*m.object, locals, depth);
        const std::string& n = *m.member;
        int i = n == "x" || n == "r" ? 0 : n == "y" || n == "g" ? 1 : n == "z" || n == "b" ? 2 : -1;
        if (!v.vec || i < 0) fail(m.member_loc, fmt::format("a compiled function can take only .x, .y and .z of a vector"));
        return num(v.r[i]);
      }
      case ast::ExprKind::Call: return call(static_cast<const ast::CallExpr&>(e), locals, depth);
      default:
        fail(e.loc, "this expression cannot be compiled into a function of a point (it may use numbers, vectors, "
                    "arithmetic, comparisons and calls)");
    }
  }

  CV name(const ast::NameExpr& e, std::vector<Local>& locals) {
    if (Local* l = find_local(locals, e.name)) return l->value;
    // Globals (as a macro sees them): read now, as constants.
    for (std::size_t i = in_.globals_end(); i-- > 0;) {
      Binding& b = in_.bindings_[i];
      if (b.name != e.name) continue;
      b.used = true;
      const Value& v = b.value;
      switch (v.type) {
        case Type::Number:
        case Type::Bool: return num(constant(v.v.x, e.loc));
        case Type::Vector:
        case Type::Color: return vec(constant(v.v.x, e.loc), constant(v.v.y, e.loc), constant(v.v.z, e.loc));
        default:
          fail(e.loc, fmt::format("'{}' is {}; a compiled function can read only numbers, vectors and colors", *e.name,
                                  with_article(v.type)));
      }
    }
    if (*e.name == "pi") return num(constant(std::numbers::pi, e.loc));
    fail(e.loc, fmt::format("'{}' is not defined (a compiled function sees its parameters, its own variables and "
                            "global ones)",
                            *e.name));
  }

  CV arith(Op op, const CV& a, const CV& b, SourceLoc loc, const ast::Expr& rhs) {
    if (a.vec && b.vec && op != Op::Add && op != Op::Sub)
      fail(rhs.loc, "vectors can be added and subtracted, and multiplied or divided by a number");
    if (!a.vec && b.vec && op != Op::Mul) fail(rhs.loc, "a number can multiply a vector, not be divided by one");
    return map2(op, a, b, loc);
  }

  CV binary(ast::BinaryOp op, const CV& a, const CV& b, const ast::BinaryExpr& e) {
    using B = ast::BinaryOp;
    switch (op) {
      case B::Add: return arith(Op::Add, a, b, e.op_loc(), *e.rhs);
      case B::Sub: return arith(Op::Sub, a, b, e.op_loc(), *e.rhs);
      case B::Mul: return arith(Op::Mul, a, b, e.op_loc(), *e.rhs);
      case B::Div: return arith(Op::Div, a, b, e.op_loc(), *e.rhs);
      case B::Eq:
      case B::Ne: {
        if (a.vec != b.vec) fail(e.op_loc(), "comparing a vector with a number");
        Reg r = emit(Op::Eq, {a.r[0], b.r[0]}, e.op_loc());
        if (a.vec)
          for (int i = 1; i < 3; ++i) r = emit(Op::And, {r, emit(Op::Eq, {a.r[i], b.r[i]}, e.op_loc())}, e.op_loc());
        return num(op == B::Eq ? r : emit(Op::Not, {r}, e.op_loc()));
      }
      default: break;
    }
    const Reg x = need_num(a, *e.lhs, fmt::format("the left side of '{}'", ast::to_string(op)).c_str());
    const Reg y = need_num(b, *e.rhs, fmt::format("the right side of '{}'", ast::to_string(op)).c_str());
    static constexpr Op kOps[] = {Op::Add, Op::Sub, Op::Mul, Op::Div, Op::Mod, Op::Pow, Op::Eq,
                                  Op::Ne,  Op::Lt,  Op::Le,  Op::Gt,  Op::Ge,  Op::And, Op::Or};
    return num(emit(kOps[static_cast<int>(op)], {x, y}, e.op_loc()));
  }

  CV call(const ast::CallExpr& c, std::vector<Local>& locals, int depth) {
    if (c.callee->kind != ast::ExprKind::Name) fail(c.loc, "a compiled function can call only named macros and builtins");
    const ast::Symbol fn = static_cast<const ast::NameExpr&>(*c.callee).name;
    for (const ast::Argument& a : c.args)
      if (a.name && !macro_named(fn)) fail(a.loc, "builtins take positional arguments only");
    if (const ast::MacroStmt* m = macro_named(fn)) return inline_macro(*m, c, locals, depth);
    std::vector<CV> args;
    for (const ast::Argument& a : c.args) args.push_back(expr(*a.value, locals, depth));
    return builtin(*fn, c, args);
  }

  const ast::MacroStmt* macro_named(ast::Symbol fn) {
    for (std::size_t i = in_.globals_end(); i-- > 0;)
      if (in_.bindings_[i].name == fn) return in_.bindings_[i].value.type == Type::Macro ? as_macro(in_.bindings_[i].value) : nullptr;
    return nullptr;
  }

  CV inline_macro(const ast::MacroStmt& m, const ast::CallExpr& c, std::vector<Local>& locals, int depth) {
    if (depth >= kMaxInlineDepth)
      fail(c.loc, fmt::format("macros nest more than {} deep here (a recursive macro cannot be compiled into a function)",
                              kMaxInlineDepth));
    std::vector<std::optional<CV>> bound(m.params.size());
    std::size_t next = 0;
    for (const ast::Argument& a : c.args) {
      std::size_t slot = next;
      if (a.name) {
        slot = m.params.size();
        for (std::size_t i = 0; i < m.params.size(); ++i)
          if (m.params[i].name == a.name) slot = i;
        if (slot == m.params.size()) fail(a.loc, fmt::format("macro '{}' has no parameter '{}'", *m.name, *a.name));
      } else {
        ++next;
      }
      if (slot >= m.params.size()) fail(a.loc, fmt::format("too many arguments for macro '{}'", *m.name));
      bound[slot] = expr(*a.value, locals, depth);
    }
    // The callee sees its parameters and the globals, not the caller's variables.
    std::vector<Local> callee;
    for (std::size_t i = 0; i < m.params.size(); ++i) {
      if (!bound[i]) {
        if (!m.params[i].default_value)
          fail(c.loc, fmt::format("macro '{}' needs argument '{}'", *m.name, *m.params[i].name));
        bound[i] = expr(*m.params[i].default_value, callee, depth + 1);
      }
      callee.push_back({m.params[i].name, *bound[i]});
    }
    return inline_body(m, callee, depth + 1);
  }

  CV builtin(const std::string& fn, const ast::CallExpr& c, const std::vector<CV>& a) {
    auto arity = [&](std::size_t lo, std::size_t hi) {
      if (a.size() < lo || a.size() > hi)
        fail(c.loc, lo == hi ? fmt::format("'{}' takes {} argument{}", fn, lo, lo == 1 ? "" : "s")
                             : fmt::format("'{}' takes {} to {} arguments", fn, lo, hi));
    };
    auto n = [&](std::size_t i) { return need_num(a[i], *c.args[i].value, fmt::format("argument {} of '{}'", i + 1, fn).c_str()); };
    auto v = [&](std::size_t i) { return need_vec(a[i], *c.args[i].value, fmt::format("argument {} of '{}'", i + 1, fn).c_str()); };
    const SourceLoc loc = c.loc;
    struct Unary {
      const char* name;
      Op op;
    };
    static constexpr Unary kUnary[] = {{"sin", Op::Sin},   {"cos", Op::Cos},     {"tan", Op::Tan},   {"asin", Op::Asin},
                                       {"acos", Op::Acos}, {"atan", Op::Atan},   {"sqrt", Op::Sqrt}, {"exp", Op::Exp},
                                       {"log", Op::Log},   {"abs", Op::Abs},     {"floor", Op::Floor}, {"ceil", Op::Ceil},
                                       {"round", Op::Round}};
    for (const Unary& u : kUnary)
      if (fn == u.name) {
        arity(1, 1);
        return num(emit(u.op, {n(0)}, loc));
      }
    if (fn == "radians" || fn == "degrees") {
      arity(1, 1);
      const double k = fn == "radians" ? std::numbers::pi / 180.0 : 180.0 / std::numbers::pi;
      return num(emit(Op::Mul, {n(0), constant(k, loc)}, loc));
    }
    if (fn == "atan2" || fn == "pow") {
      arity(2, 2);
      return num(emit(fn == "pow" ? Op::Pow : Op::Atan2, {n(0), n(1)}, loc));
    }
    if (fn == "min" || fn == "max") {
      if (a.empty()) arity(1, 1);
      Reg r = n(0);
      for (std::size_t i = 1; i < a.size(); ++i) r = emit(fn == "min" ? Op::Min : Op::Max, {r, n(i)}, loc);
      return num(r);
    }
    if (fn == "clamp") {
      arity(3, 3);
      return num(emit(Op::Clamp, {n(0), n(1), n(2)}, loc));
    }
    if (fn == "mix") {
      arity(3, 3);
      if (a[0].vec != a[1].vec) fail(loc, "'mix' needs two numbers or two vectors");
      const Reg t = n(2);
      CV out = a[0];
      for (int i = 0; i < (a[0].vec ? 3 : 1); ++i) out.r[i] = emit(Op::Mix, {a[0].r[i], a[1].r[i], t}, loc);
      return out;
    }
    if (fn == "vec" || fn == "rgb") {
      if (fn == "rgb" && a.size() == 1) return a[0].vec ? a[0] : vec(n(0), n(0), n(0));
      arity(3, 3);
      return vec(n(0), n(1), n(2));
    }
    if (fn == "dot" || fn == "cross") {
      arity(2, 2);
      const CV x = v(0), y = v(1);
      if (fn == "dot") return num(dot(x, y, loc));
      auto d = [&](int i, int j) {
        return emit(Op::Sub, {emit(Op::Mul, {x.r[i], y.r[j]}, loc), emit(Op::Mul, {x.r[j], y.r[i]}, loc)}, loc);
      };
      return vec(d(1, 2), d(2, 0), d(0, 1));
    }
    if (fn == "length") {
      arity(1, 1);
      const CV x = v(0);
      return num(emit(Op::Sqrt, {dot(x, x, loc)}, loc));
    }
    if (fn == "normalize") {
      arity(1, 1);
      const CV x = v(0);
      const Reg len = emit(Op::Sqrt, {dot(x, x, loc)}, loc);
      return vec(emit(Op::Div, {x.r[0], len}, loc), emit(Op::Div, {x.r[1], len}, loc), emit(Op::Div, {x.r[2], len}, loc));
    }
    if (fn == "noise" || fn == "cells" || fn == "worley") {
      arity(1, 1);
      const CV p = v(0);
      const Op op = fn == "noise" ? Op::Noise : fn == "cells" ? Op::Cells : Op::Worley;
      return num(emit(op, {p.r[0], p.r[1], p.r[2]}, loc));
    }
    if (fn == "fbm" || fn == "turbulence") {
      arity(1, 4);
      const CV p = v(0);
      const Reg octaves = a.size() > 1 ? n(1) : constant(6.0, loc);
      const Reg lambda = a.size() > 2 ? n(2) : constant(2.0, loc);
      const Reg omega = a.size() > 3 ? n(3) : constant(0.5, loc);
      return num(emit(fn == "fbm" ? Op::Fbm : Op::Turbulence, {p.r[0], p.r[1], p.r[2], octaves, lambda, omega}, loc));
    }
    fail(c.callee->loc, fmt::format("'{}' cannot be called in a compiled function (it can call macros and the math "
                                    "and noise builtins)",
                                    fn));
  }

  Reg dot(const CV& x, const CV& y, SourceLoc loc) {
    Reg r = emit(Op::Mul, {x.r[0], y.r[0]}, loc);
    for (int i = 1; i < 3; ++i) r = emit(Op::Add, {r, emit(Op::Mul, {x.r[i], y.r[i]}, loc)}, loc);
    return r;
  }

  Interpreter& in_;
  std::shared_ptr<render::CompiledFunction> f_;
};

std::shared_ptr<const render::CompiledFunction> Interpreter::compile_function(const Value& macro, SourceLoc use) {
  // Compiled at each use (cheap: one pass over the macro), so globals are read as they are now.
  (void)use;
  return FunctionCompiler(*this).compile(*as_macro(macro));
}

}  // namespace rts::runtime
