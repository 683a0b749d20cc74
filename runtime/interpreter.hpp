// The tree-walking interpreter behind evaluate_file(). Internal to runtime/.
//
// Bindings live in one flat stack of (symbol, value) pairs; a scope is a start index into it,
// and a macro call opens a frame whose code sees its own bindings plus the global (top-level)
// ones. Lookups compare interned symbol pointers from the top down, so the common case (a
// handful of live names) costs a few pointer comparisons and no hashing or allocation.
//
// Errors are thrown as LanguageError without notes; evaluate() adds the "in call to macro" and
// "in file included from here" notes from the context stack, which is deliberately left as it
// was at the throw (frames are popped only on normal exit).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "parser/ast.hpp"
#include "parser/diagnostics.hpp"
#include "parser/source.hpp"
#include "render/accel/probe.hpp"
#include "render/scene/resource_limits.hpp"
#include "render/builder/scene_builder.hpp"
#include "runtime/binding.hpp"
#include "runtime/budget.hpp"
#include "runtime/defines.hpp"
#include "runtime/includes.hpp"
#include "runtime/placement.hpp"
#include "runtime/evaluator.hpp"
#include "runtime/value.hpp"

namespace rts::runtime {

enum class Flow : uint8_t { Normal, Break, Continue, Return };

// One active macro call or include, for error notes.
struct Context {
  enum Kind : uint8_t { Macro, Include } kind;
  SourceLoc site;    // the call or the include statement
  ast::Symbol name;  // the macro's name (Macro)
};

class Interpreter;
struct BuiltinCall;
using BuiltinFn = Value (*)(BuiltinCall&);
struct Builtin {
  const char* name;
  int min_args, max_args;  // max_args < 0: variadic
  BuiltinFn fn;
  // select(c, a, b): eval_call evaluates the condition and then only the chosen argument;
  // `fn` is the same choice over evaluated arguments (compiled functions use that).
  bool lazy = false;
};
struct BuiltinCall {
  Interpreter& in;
  const ast::CallExpr& call;
  const Builtin& def;
  const Value* args;
  std::size_t argc;
};
const std::vector<Builtin>& builtin_table();
// `table` with the vector and interpolation builtins of builtins_math.cpp appended.
std::vector<Builtin> with_math_builtins(std::vector<Builtin> table);

class Interpreter {
  friend class FunctionCompiler;   // reads the global bindings and the builtin table

 public:
  Interpreter(SourceManager& sources, const EvalOptions& options, DiagnosticSink& warnings);

  // Runs the main file; throws LanguageError (with notes) on any error.
  void run(const SourceFile& main);
  render::SceneDesc finish() { return builder_.finish(); }
  double parse_seconds() const { return includes_.parse_seconds(); }  // of every file parsed

  // ---- services for builtins and blocks ----
  [[noreturn]] void fail(SourceLoc loc, std::string message) const;
  render::SourceRef ref(SourceLoc loc);
  Value make_texture(ast::Symbol kind, std::vector<Property> props, SourceLoc loc);
  Value transform_textures(const Value& v, const render::Mat4& t);
  // The builder id of a material / texture value, built on first use and cached in it.
  uint32_t realize_material(const Value& material);
  uint32_t realize_texture(const Value& texture);
  // A macro of one point (`macro f(p) { return ... }`) compiled once to the renderer's
  // register code (runtime/function_compiler.cpp); `use` is where it is given.
  std::shared_ptr<const render::CompiledFunction> compile_function(const Value& macro, SourceLoc use);
  // Attaches the context notes (innermost first) to an error thrown while running.
  void add_notes(Diagnostic& d) const;
  // Converts a builder SceneError into a located LanguageError.
  LanguageError from_scene_error(const render::SceneError& e) const;
  // The budgets (runtime/budget.hpp), for builtins and blocks.
  void spend(uint64_t n, SourceLoc loc, const char* what) { budget_.spend(n, loc, what); }
  void check_memory(std::size_t bytes, SourceLoc loc, const char* what) const {
    budget_.check_memory(bytes, loc, what);
  }
  std::string text_of(const Value& v, SourceLoc loc, bool quote_strings = false) {
    return budget_.text_of(v, loc, quote_strings);
  }
  void set_stack_floor(std::uintptr_t floor, std::size_t stack_bytes) { budget_.set_stack_floor(floor, stack_bytes); }
  // trace(object, origin, direction): [hit point, unit normal], or none on a miss (trace.cpp).
  Value trace_object(const Value& object, const glm::dvec3& origin, const glm::dvec3& direction, SourceLoc loc);
  uint64_t world_shapes() const { return placement_.world().shapes; }
  uint64_t world_lights() const { return placement_.world().lights; }
  bool uses_clock() const { return uses_clock_; }  // read `clock`, `frame` or `frames`
  // The global variables as text, each at most `max_bytes` (EvalOptions::describe_globals).
  std::vector<GlobalValue> describe_globals(std::size_t max_bytes) const;

  // a + b for two lists or two strings, counted against the step and memory budgets;
  // appends in place when `a` holds the only reference to its list or string.
  Value concat(Value a, const Value& b, SourceLoc loc);

 private:
  // statements (interpreter.cpp)
  void run_program(const ast::Program& program, bool is_main);
  Flow exec_list(const ast::StmtList& stmts);
  Flow exec_body(const ast::Body& body);
  Flow exec(const ast::Stmt& s);
  void exec_let(const ast::LetStmt& s);
  void exec_assign(const ast::AssignStmt& s);
  Flow exec_for(const ast::ForStmt& s);
  Flow exec_while(const ast::WhileStmt& s);
  void exec_include(const ast::IncludeStmt& s);
  void count_iteration(SourceLoc loc) { budget_.count_iteration(loc); }
  void check_stack(SourceLoc loc) const { budget_.check_stack(loc, macro_depth_); }
  // `xs = xs + e` and `xs += e` on a list or string: appends in place when the variable
  // holds the only reference. Returns false when the statement is not of that form.
  bool exec_append(const ast::AssignStmt& s);

  // scopes
  void push_scope() { scopes_.push_back(bindings_.size()); }
  void pop_scope() {
    if (scopes_.back() < indexed_end_) forget_scope_index();
    bindings_.resize(scopes_.back());
    scopes_.pop_back();
  }
  void forget_scope_index() {
    scope_index_.clear();
    indexed_scope_ = kNoScope;
    indexed_end_ = 0;
  }
  void declare(ast::Symbol name, Value value, SourceLoc loc);
  Binding* lookup(ast::Symbol name);
  [[noreturn]] void undefined(ast::Symbol name, SourceLoc loc);
  std::size_t globals_end() const { return scopes_.size() > 1 ? scopes_[1] : bindings_.size(); }

  // names and expressions (expressions.cpp, ops.cpp)
  Value eval(const ast::Expr& e);
  Value eval_name(const ast::NameExpr& e);
  bool animation_constant(ast::Symbol name, Value& out);
  Value eval_binary(const ast::BinaryExpr& e);
  Value eval_unary(const ast::UnaryExpr& e);
  Value eval_call(const ast::CallExpr& e);
  Value eval_index(const ast::IndexExpr& e);
  Value eval_member(const ast::MemberExpr& e);
  Value eval_range(const ast::RangeExpr& e);
  Value call_macro(const ast::MacroStmt& m, const ast::CallExpr& call);
  double expect_number(const ast::Expr& e, const char* what);
  // Bounds how deep lists and records nest (their printing and freeing recurse).
  void check_nesting(const Value& v, SourceLoc loc) const;

  // blocks, `with`, transforms, placement (blocks.cpp)
  // keep_block: shapes and lights keep their properties in the value (for `with`); false
  // for a block statement, whose value is placed and dropped.
  Value eval_block(const ast::BlockExpr& e, bool keep_block = true);
  Value eval_with(const ast::WithExpr& e);
  // Builds a shape or light definition from its block (kind, props, loc); the object value
  // returned keeps the block, for `with`.
  Value define_object(std::shared_ptr<ObjectValue> obj);
  Value define_object(const std::string& kind, SourceLoc loc, const std::vector<Property>& props);
  // The scene node of an object value, building its definition on first placement.
  uint32_t realize_object(const Value& object);
  Value eval_transform(const ast::TransformExpr& e);
  void collect_properties(const ast::BlockBody& body, std::vector<Property>& props, bool allow_placement);
  render::ParamSet to_params(const std::string& kind, SourceLoc loc, const std::vector<Property>& props);
  render::ParamValue to_param(const Property& p, const std::string& kind);
  void place(const Value& object, SourceLoc loc);

  SourceManager& sources_;
  const EvalOptions& options_;
  DiagnosticSink& warnings_;
  Budget budget_;
  Includes includes_;
  Defines defines_;
  Placement placement_;
  render::SceneBuilder builder_;

  std::vector<Binding> bindings_;
  std::vector<std::size_t> scopes_;
  // declare()'s duplicate check in a scope of many names (10 MB of `let`s: a scan per
  // declaration made the file quadratic, minutes of evaluation): the first binding of each
  // name in bindings_[indexed_scope_, indexed_end_), caught up on the next declaration in that
  // scope, forgotten when the scope's bindings are popped. Small scopes are scanned.
  static constexpr std::size_t kNoScope = ~std::size_t{0};
  static constexpr std::size_t kScannedScopeNames = 32;
  std::unordered_map<ast::Symbol, std::size_t> scope_index_;
  std::size_t indexed_scope_ = kNoScope, indexed_end_ = 0;
  std::size_t frame_base_ = 0;  // first binding of the current macro frame (0 at top level)
  std::vector<Context> contexts_;
  // Macro arguments between their evaluation and their binding (call_macro), all calls' in one.
  std::vector<Value> arg_stack_;
  std::vector<const ast::Argument*> arg_given_;
  unsigned macro_depth_ = 0;
  unsigned loop_depth_ = 0;  // loops enclosing the current code in this frame
  bool in_macro_ = false;    // `return` allowed
  Value return_value_;

  // trace(): the World of the object traced last, rebuilt when another object is traced.
  std::unique_ptr<render::ObjectProbe> probe_;
  render::Child probe_key_;
  std::size_t probe_shapes_ = 0;  // shapes defined when it was built (ids stay valid; a guard)
  bool uses_clock_ = false;
  SourceLoc current_loc_;  // the statement running now (for out-of-memory errors)

  // Built-in functions by symbol (a binding of the same name shadows them), with a small
  // direct-mapped cache in front.
  static constexpr uint32_t kNotBuiltin = UINT32_MAX;
  static constexpr std::size_t kBuiltinCacheSize = 64;
  struct BuiltinCacheEntry {
    ast::Symbol name = nullptr;
    uint32_t id = kNotBuiltin;
  };
  uint32_t find_builtin(ast::Symbol name);
  std::unordered_map<ast::Symbol, uint32_t> builtins_;
  std::array<BuiltinCacheEntry, kBuiltinCacheSize> builtin_cache_{};
};

}  // namespace rts::runtime
