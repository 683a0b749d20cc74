// Names, expressions, builtin and macro calls.
#include <numbers>

#include <fmt/format.h>

#include "render/scene/params.hpp"
#include "runtime/builtin_args.hpp"
#include "runtime/interpreter.hpp"
#include "runtime/ops.hpp"
#include "runtime/povray_hints.hpp"

namespace rts::runtime {

namespace {
// Builtin calls with at most this many arguments keep them on the C++ stack.
constexpr std::size_t kInlineArgs = 8;
}  // namespace

uint32_t Interpreter::find_builtin(ast::Symbol name) {
  // Symbols are interned numbers: a direct-mapped cache on the number answers repeated
  // calls (sin, cos... in loops) without hashing.
  BuiltinCacheEntry& slot = builtin_cache_[name.id() % kBuiltinCacheSize];
  if (slot.name == name) return slot.id;
  auto it = builtins_.find(name);
  uint32_t id = it == builtins_.end() ? kNotBuiltin : it->second;
  slot = BuiltinCacheEntry{name, id};
  return id;
}

namespace {
// The built-in constant `pi`, looked up after the scene's own names.
ast::Symbol pi_symbol() {
  static const ast::Symbol pi = ast::intern("pi");
  return pi;
}
// The animation constants (EvalOptions::animation), also looked up after the scene's names, so
// a scene written before they existed (`let frame = ...`) keeps its meaning.
ast::Symbol clock_symbol() {
  static const ast::Symbol s = ast::intern("clock");
  return s;
}
ast::Symbol frame_symbol() {
  static const ast::Symbol s = ast::intern("frame");
  return s;
}
ast::Symbol frames_symbol() {
  static const ast::Symbol s = ast::intern("frames");
  return s;
}
}  // namespace

void Interpreter::undefined(ast::Symbol name, SourceLoc loc) {
  std::vector<std::string_view> candidates;
  for (std::size_t i = frame_base_; i < bindings_.size(); ++i) candidates.push_back(*bindings_[i].name);
  if (frame_base_ > 0)
    for (std::size_t i = 0; i < globals_end(); ++i) candidates.push_back(*bindings_[i].name);
  for (const Builtin& b : builtin_table()) candidates.push_back(b.name);
  candidates.push_back(*pi_symbol());
  for (ast::Symbol s : {clock_symbol(), frame_symbol(), frames_symbol()}) candidates.push_back(*s);
  std::string msg = fmt::format("undefined name '{}'", *name);
  std::string hint = render::closest_name(*name, candidates);
  if (std::string pov = povray_hint(*name); !pov.empty())
    msg += pov;
  else if (!hint.empty())
    msg += fmt::format("; did you mean '{}'?", hint);
  fail(loc, msg);
}

// ---------------------------------------------------------------------------------------
// Expressions
// ---------------------------------------------------------------------------------------

void Interpreter::check_nesting(const Value& v, SourceLoc loc) const {
  if (nesting_depth(v) > kMaxValueNesting)
    fail(loc, fmt::format("lists and materials nested more than {} deep", kMaxValueNesting));
}

double Interpreter::expect_number(const ast::Expr& e, const char* what) {
  Value v = eval(e);
  if (v.type != Type::Number) fail(e.loc, fmt::format("{} must be a number, got {}", what, with_article(v.type)));
  return v.v.x;
}

Value Interpreter::eval(const ast::Expr& e) {
  switch (e.kind) {
    case ast::ExprKind::Number:
      return Value::number(static_cast<const ast::NumberExpr&>(e).value());
    case ast::ExprKind::String:
      return Value::string(std::string(static_cast<const ast::StringExpr&>(e).value));
    case ast::ExprKind::Bool:
      return Value::boolean(static_cast<const ast::BoolExpr&>(e).value);
    case ast::ExprKind::None:
      return Value::none();
    case ast::ExprKind::Name:
      return eval_name(static_cast<const ast::NameExpr&>(e));
    case ast::ExprKind::Vector: {
      const auto& ve = static_cast<const ast::VectorExpr&>(e);
      if (ve.components.size() != 3)
        fail(e.loc, fmt::format("vectors have 3 components, this one has {}", ve.components.size()));
      glm::dvec3 r;
      for (int i = 0; i < 3; ++i) r[i] = expect_number(*ve.components[i], "a vector component");
      return Value::vector(r);
    }
    case ast::ExprKind::List: {
      const auto& le = static_cast<const ast::ListExpr&>(e);
      spend(le.elements.size(), e.loc, "list elements built");
      std::vector<Value> items;
      items.reserve(le.elements.size());
      for (const ast::ExprLink& x : le.elements) items.push_back(eval(*x));
      Value list = Value::list(std::move(items));
      check_nesting(list, e.loc);
      return list;
    }
    case ast::ExprKind::Unary:
      return eval_unary(static_cast<const ast::UnaryExpr&>(e));
    case ast::ExprKind::Binary:
      return eval_binary(static_cast<const ast::BinaryExpr&>(e));
    case ast::ExprKind::Range:
      return eval_range(static_cast<const ast::RangeExpr&>(e));
    case ast::ExprKind::Call:
      return eval_call(static_cast<const ast::CallExpr&>(e));
    case ast::ExprKind::Index:
      return eval_index(static_cast<const ast::IndexExpr&>(e));
    case ast::ExprKind::Member:
      return eval_member(static_cast<const ast::MemberExpr&>(e));
    case ast::ExprKind::Block:
      return eval_block(static_cast<const ast::BlockExpr&>(e));
    case ast::ExprKind::With:
      return eval_with(static_cast<const ast::WithExpr&>(e));
    case ast::ExprKind::Transform:
      return eval_transform(static_cast<const ast::TransformExpr&>(e));
  }
  fail(e.loc, "internal error: unknown expression kind");
}

Value Interpreter::eval_name(const ast::NameExpr& e) {
  if (Binding* b = lookup(e.name)) return b->value;
  if (e.name == pi_symbol()) return Value::number(std::numbers::pi);  // a constant a `let` may shadow
  if (Value v; animation_constant(e.name, v)) return v;
  if (uint32_t id = find_builtin(e.name); id != kNotBuiltin) {
    Value v;
    v.type = Type::Builtin;
    v.id = id;
    return v;
  }
  undefined(e.name, e.loc);
}

bool Interpreter::animation_constant(ast::Symbol name, Value& out) {
  const AnimationClock& a = options_.animation;
  if (name == clock_symbol())
    out = Value::number(a.clock);
  else if (name == frame_symbol())
    out = Value::number(static_cast<double>(a.frame));
  else if (name == frames_symbol())
    out = Value::number(static_cast<double>(a.frames));
  else
    return false;
  uses_clock_ = true;
  return true;
}

Value Interpreter::eval_unary(const ast::UnaryExpr& e) { return unary_op(e.op(), eval(*e.operand), e.loc); }

Value Interpreter::eval_binary(const ast::BinaryExpr& e) {
  if (e.op() == ast::BinaryOp::And || e.op() == ast::BinaryOp::Or) {
    Value a = eval(*e.lhs);
    if (a.type != Type::Bool)
      fail(e.lhs->loc, fmt::format("'{}' needs bools, got {}", ast::to_string(e.op()), with_article(a.type)));
    if (e.op() == ast::BinaryOp::And ? !a.truth() : a.truth()) return a;  // short-circuit
    Value b = eval(*e.rhs);
    if (b.type != Type::Bool)
      fail(e.rhs->loc, fmt::format("'{}' needs bools, got {}", ast::to_string(e.op()), with_article(b.type)));
    return b;
  }
  Value a = eval(*e.lhs);
  Value b = eval(*e.rhs);
  if (e.op() == ast::BinaryOp::Add && a.type == b.type && (a.type == Type::List || a.type == Type::String))
    return concat(std::move(a), b, e.op_loc());
  return binary_op(e.op(), a, b, e.op_loc());
}

Value Interpreter::eval_range(const ast::RangeExpr& e) {
  Value r;
  r.type = Type::Range;
  r.inclusive = e.inclusive;
  r.v.x = expect_number(*e.from, "the start of a range");
  r.v.y = expect_number(*e.to, "the end of a range");
  r.v.z = e.step ? expect_number(*e.step, "a range step") : 1.0;
  if (r.v.z == 0.0) fail(e.step->loc, "a range step must not be zero");
  return r;
}

Value Interpreter::eval_index(const ast::IndexExpr& e) {
  Value obj = eval(*e.object);
  double i = expect_number(*e.index, "an index");
  std::size_t n;
  if (obj.type == Type::List)
    n = as_list(obj).size();
  else if (obj.type == Type::Vector || obj.type == Type::Color)
    n = 3;
  else if (obj.type == Type::Range)
    n = range_count(obj);
  else
    fail(e.object->loc,
         fmt::format("cannot index {} (only lists, vectors, colors and ranges)", with_article(obj.type)));
  if (i != std::floor(i) || i < 0 || i >= static_cast<double>(n))
    fail(e.index->loc, fmt::format("index {} out of range for {} of {} element{}", to_text(Value::number(i)),
                                   with_article(obj.type), n, n == 1 ? "" : "s"));
  auto k = static_cast<std::size_t>(i);
  if (obj.type == Type::List) return as_list(obj)[k];
  if (obj.type == Type::Range) return Value::number(range_at(obj, k));
  return Value::number(obj.v[static_cast<int>(k)]);
}

Value Interpreter::eval_member(const ast::MemberExpr& e) {
  Value obj = eval(*e.object);
  const std::string& m = *e.member;
  if (obj.type == Type::Vector) {
    if (m == "x") return Value::number(obj.v.x);
    if (m == "y") return Value::number(obj.v.y);
    if (m == "z") return Value::number(obj.v.z);
    fail(e.member_loc, fmt::format("a vector has no member '{}' (it has x, y and z)", m));
  }
  if (obj.type == Type::Color) {
    if (m == "r") return Value::number(obj.v.x);
    if (m == "g") return Value::number(obj.v.y);
    if (m == "b") return Value::number(obj.v.z);
    fail(e.member_loc, fmt::format("a color has no member '{}' (it has r, g and b)", m));
  }
  if (obj.type == Type::Material || obj.type == Type::Texture) {
    const RecordValue& rec = as_record(obj);
    for (auto it = rec.props.rbegin(); it != rec.props.rend(); ++it)
      if (it->name == e.member) return it->value;
    fail(e.member_loc, fmt::format("this {} has no property '{}' set", type_name(obj.type), m));
  }
  fail(e.member_loc, fmt::format("{} has no members", with_article(obj.type)));
}

Value Interpreter::eval_call(const ast::CallExpr& e) {
  Value callee;
  if (e.callee->kind == ast::ExprKind::Name) {
    const auto& name = static_cast<const ast::NameExpr&>(*e.callee);
    if (Binding* b = lookup(name.name)) {
      // A macro is called through its definition, which the parsed program keeps alive for
      // the whole evaluation: copying the Value would cost two atomic reference-count updates
      // per call (5% of a recursive macro's time in perf).
      if (b->value.type == Type::Macro) return call_macro(*as_macro(b->value), e);
      callee = b->value;
    } else if (uint32_t id = find_builtin(name.name); id != kNotBuiltin) {
      callee.type = Type::Builtin;
      callee.id = id;
    } else {
      undefined(name.name, name.loc);
    }
  } else {
    callee = eval(*e.callee);
  }
  if (callee.type == Type::Macro) return call_macro(*as_macro(callee), e);
  if (callee.type != Type::Builtin)
    fail(e.callee->loc,
         fmt::format("cannot call {}; only macros and builtin functions can be called", with_article(callee.type)));
  const Builtin& b = builtin_table()[callee.id];
  for (const ast::Argument& a : e.args)
    if (a.name) fail(a.loc, fmt::format("builtin '{}' takes no named arguments", b.name));
  std::size_t argc = e.args.size();
  if (static_cast<int>(argc) < b.min_args || (b.max_args >= 0 && static_cast<int>(argc) > b.max_args)) {
    std::string expected = b.max_args < 0             ? fmt::format("at least {}", b.min_args)
                           : b.min_args == b.max_args ? fmt::format("{}", b.min_args)
                                                      : fmt::format("{} to {}", b.min_args, b.max_args);
    fail(e.loc, fmt::format("'{}' takes {} argument{}, got {}", b.name, expected,
                            (b.max_args == 1 && b.min_args == 1) ? "" : "s", argc));
  }
  if (b.lazy) {
    // select(c, a, b): the branch not chosen is never evaluated (it may be an error there,
    // as xs[i] past the end).
    Value cond = eval(*e.args[0].value);
    if (cond.type != Type::Bool) builtin_args::bad_select_condition(*this, e, cond);
    return eval(*e.args[cond.truth() ? 1 : 2].value);
  }
  if (argc <= kInlineArgs) {
    // Only the arguments given are constructed: an unused Value slot still costs a
    // constructor and a destructor, which shows in tight loops of sin() and cos().
    struct InlineArgs {
      alignas(Value) unsigned char bytes[kInlineArgs * sizeof(Value)];
      std::size_t count = 0;
      Value* data() { return reinterpret_cast<Value*>(bytes); }
      ~InlineArgs() {
        for (std::size_t i = 0; i < count; ++i) data()[i].~Value();
      }
    } args;
    for (std::size_t i = 0; i < argc; ++i) {
      new (args.data() + i) Value(eval(*e.args[i].value));
      ++args.count;
    }
    BuiltinCall c{*this, e, b, args.data(), argc};
    return b.fn(c);
  }
  std::vector<Value> args;
  args.reserve(argc);
  for (const ast::Argument& a : e.args) args.push_back(eval(*a.value));
  BuiltinCall c{*this, e, b, args.data(), argc};
  return b.fn(c);
}

Value Interpreter::call_macro(const ast::MacroStmt& m, const ast::CallExpr& call) {
  const auto& params = m.params;
  std::size_t positional = 0;
  while (positional < call.args.size() && !call.args[positional].name) ++positional;
  if (positional > params.size())
    fail(call.args[params.size()].loc, fmt::format("macro '{}' takes at most {} argument{}, got {}", *m.name,
                                                   params.size(), params.size() == 1 ? "" : "s", positional));
  // Arguments are evaluated in the caller's scope, then bound in the macro's frame. Their
  // values wait on a stack shared by every call (nested calls push above, and are gone again
  // before this call reads its slots back), not in two vectors per call: their malloc and free
  // were 14% of a recursive macro's time (perf).
  const std::size_t base = arg_stack_.size();
  struct StackMark {  // an error thrown on the way leaves the stack as it found it
    std::vector<Value>& stack;
    std::vector<const ast::Argument*>& given;
    std::size_t base;
    ~StackMark() {
      stack.resize(base);
      given.resize(base);
    }
  } mark{arg_stack_, arg_given_, base};
  arg_stack_.resize(base + params.size());
  arg_given_.resize(base + params.size(), nullptr);
  auto values = [&](std::size_t p) -> Value& { return arg_stack_[base + p]; };
  auto given = [&](std::size_t p) -> const ast::Argument*& { return arg_given_[base + p]; };
  for (std::size_t i = 0; i < call.args.size(); ++i) {
    const ast::Argument& a = call.args[i];
    std::size_t slot = i;
    if (a.name) {
      slot = params.size();
      for (std::size_t p = 0; p < params.size(); ++p)
        if (params[p].name == a.name) slot = p;
      if (slot == params.size()) {
        std::vector<std::string_view> names;
        for (const ast::Param& p : params) names.push_back(*p.name);
        std::string msg = fmt::format("macro '{}' has no parameter '{}'", *m.name, *a.name);
        std::string hint = render::closest_name(*a.name, names);
        if (!hint.empty()) msg += fmt::format("; did you mean '{}'?", hint);
        fail(a.loc, msg);
      }
      if (given(slot)) fail(a.loc, fmt::format("argument '{}' given twice", *a.name));
    }
    given(slot) = &a;
    Value v = eval(*a.value);  // may call macros, which grow (and regrow) the stack
    values(slot) = std::move(v);
  }
  for (std::size_t p = 0; p < params.size(); ++p)
    if (!given(p) && !params[p].default_value)
      fail(call.loc, fmt::format("missing argument '{}' in call to macro '{}'", *params[p].name, *m.name));
  if (macro_depth_ >= options_.limits.max_recursion)
    fail(call.loc, fmt::format("macro calls nested deeper than {} (raise the limit with --max-recursion)",
                               options_.limits.max_recursion));
  check_stack(call.loc);
  // A macro call is a step (a recursion that doubles, f(d-1) f(d-1), never nests deep).
  if (budget_.add_steps(1))
    budget_.check(call.loc, fmt::format("calls to macro '{}'", *m.name).c_str());

  contexts_.push_back(Context{Context::Macro, call.loc, m.name});
  const std::size_t saved_base = frame_base_;
  const unsigned saved_loops = loop_depth_;
  const bool saved_in_macro = in_macro_;
  frame_base_ = bindings_.size();
  loop_depth_ = 0;
  in_macro_ = true;
  ++macro_depth_;
  push_scope();
  for (std::size_t p = 0; p < params.size(); ++p) {
    // Defaults are evaluated in the macro's frame, so they may use earlier parameters.
    Value v = given(p) ? std::move(values(p)) : eval(*params[p].default_value);
    declare(params[p].name, std::move(v), params[p].loc);
  }
  arg_stack_.resize(base);  // bound: the body's own calls reuse the slots
  arg_given_.resize(base);
  Flow f = exec_list(m.body.stmts);
  // The result is made in place (the caller's slot): a none made aside and moved in was a
  // store-forwarding stall, 17% of this function's samples in perf on a recursive macro.
  Value result;
  if (f == Flow::Return) {
    result = std::move(return_value_);
    return_value_ = Value::none();
  }
  pop_scope();
  --macro_depth_;
  in_macro_ = saved_in_macro;
  loop_depth_ = saved_loops;
  frame_base_ = saved_base;
  contexts_.pop_back();
  return result;
}

}  // namespace rts::runtime
