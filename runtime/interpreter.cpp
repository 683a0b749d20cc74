// Running a scene: its files, scopes and statements (names, expressions and macro calls are
// in expressions.cpp; blocks in blocks.cpp).
#include "runtime/interpreter.hpp"

#include <fmt/format.h>

#include "render/scene/params.hpp"
#include "runtime/lint.hpp"
#include "runtime/ops.hpp"

namespace rts::runtime {

namespace {
// Growing a list or string by less than this is not worth a memory check of its own.
constexpr std::size_t kBigAllocationBytes = 1 << 20;
}  // namespace

Interpreter::Interpreter(SourceManager& sources, const EvalOptions& options, DiagnosticSink& warnings)
    : sources_(sources),
      options_(options),
      warnings_(warnings),
      budget_(options.limits),
      includes_(sources, options),
      placement_(options.limits, budget_, options.placed),
      builder_(render::BuilderLimits{options.limits.max_mesh_triangles, options.limits.max_memory}) {
  const auto& table = builtin_table();
  for (uint32_t i = 0; i < table.size(); ++i) builtins_[ast::intern(table[i].name)] = i;
}

void Interpreter::fail(SourceLoc loc, std::string message) const { throw LanguageError(loc, std::move(message)); }

render::SourceRef Interpreter::ref(SourceLoc loc) {
  const SourceFile* file = loc.file();
  if (!file) return {};
  return render::SourceRef{file->path().c_str(), loc.line(), loc.col()};
}

void Interpreter::add_notes(Diagnostic& d) const {
  // Deep recursion would print a note per level: keep the innermost and outermost ones.
  constexpr std::size_t kNotesKeptAtEachEnd = 5;
  const std::size_t n = contexts_.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Context& c = contexts_[n - 1 - k];  // innermost first
    if (n > 2 * kNotesKeptAtEachEnd + 1 && k >= kNotesKeptAtEachEnd && k < n - kNotesKeptAtEachEnd) {
      if (k == kNotesKeptAtEachEnd)
        d.notes.push_back(
            Note{c.site, fmt::format("({} more calls and includes not shown)", n - 2 * kNotesKeptAtEachEnd)});
      continue;
    }
    if (c.kind == Context::Macro)
      d.notes.push_back(Note{c.site, fmt::format("in call to macro '{}' from here", *c.name)});
    else
      d.notes.push_back(Note{c.site, "in file included from here"});
  }
}

LanguageError Interpreter::from_scene_error(const render::SceneError& e) const {
  Diagnostic d;
  d.message = e.what();
  if (const SourceFile* file = includes_.file_named(e.where.file)) d.loc = SourceLoc::at(file, e.where.line, e.where.col);
  add_notes(d);
  return LanguageError(std::move(d));
}

// ---------------------------------------------------------------------------------------
// Running files
// ---------------------------------------------------------------------------------------

void Interpreter::run(const SourceFile& main) {
  const render::ReadPolicy& policy = includes_.restrict_reads(main);
  if (options_.restrict_reads) builder_.set_read_policy(policy);
  try {
    const ast::Program& program = includes_.open_main(main);
    defines_.parse(options_.defines, includes_);
    push_scope();  // the global scope
    run_program(program, true);
  } catch (LanguageError& e) {
    add_notes(e.diag);
    throw;
  } catch (const render::SceneError& e) {
    throw from_scene_error(e);
  } catch (const std::bad_alloc&) {
    // The machine (or a ulimit) refused memory before --max-memory was reached.
    Diagnostic d;
    d.loc = current_loc_;
    d.message = "out of memory: the system refused more memory while running this statement "
                "(lower what the scene builds, or check ulimit -v)";
    add_notes(d);
    throw LanguageError(std::move(d));
  }
  if (options_.warn_unused) warn_unused(std::span<const Binding>(bindings_.data(), globals_end()), main, warnings_);
  defines_.warn_unmatched(main, warnings_);
}

void Interpreter::run_program(const ast::Program& program, bool is_main) {
  unsigned saved_loops = loop_depth_;
  bool saved_macro = in_macro_;
  loop_depth_ = 0;  // `break` in an included file cannot leave a loop of the includer
  in_macro_ = false;
  for (const ast::StmtLink& s : program.stmts()) {
    if (is_main && s->kind == ast::StmtKind::Let) {
      const auto& let = static_cast<const ast::LetStmt&>(*s);
      if (const ast::Expr* define = defines_.take(let.name)) {
        declare(let.name, eval(*define), let.name_loc);
        continue;
      }
    }
    exec(*s);
  }
  loop_depth_ = saved_loops;
  in_macro_ = saved_macro;
}

void Interpreter::exec_include(const ast::IncludeStmt& s) {
  Includes::Found found = includes_.find(s);
  if (includes_.is_open(found.canonical))
    fail(s.loc, fmt::format("include cycle: '{}' is already being included", s.path));
  if (includes_.is_done(found.canonical)) return;  // fully included before: once only (like #pragma once)
  contexts_.push_back(Context{Context::Include, s.loc, nullptr});
  const ast::Program& program = includes_.parse(s, found);
  includes_.enter(found.canonical);
  run_program(program, false);
  includes_.leave();
  contexts_.pop_back();
}

// ---------------------------------------------------------------------------------------
// Scopes and names
// ---------------------------------------------------------------------------------------

void Interpreter::declare(ast::Symbol name, Value value, SourceLoc loc) {
  const std::size_t scope = scopes_.back();
  std::size_t previous = kNoScope;
  if (bindings_.size() - scope < kScannedScopeNames) {
    for (std::size_t i = scope; i < bindings_.size(); ++i)
      if (bindings_[i].name == name) {
        previous = i;
        break;
      }
  } else {
    if (indexed_scope_ != scope) {
      forget_scope_index();
      indexed_scope_ = indexed_end_ = scope;
    }
    for (; indexed_end_ < bindings_.size(); ++indexed_end_)
      scope_index_.emplace(bindings_[indexed_end_].name, indexed_end_);
    if (auto it = scope_index_.find(name); it != scope_index_.end()) previous = it->second;
  }
  if (previous != kNoScope) {
    Diagnostic d;
    d.loc = loc;
    d.message = fmt::format("'{}' is already defined in this scope (assign with '{} = ...' instead)", *name, *name);
    d.notes.push_back(Note{bindings_[previous].loc, "previously defined here"});
    throw LanguageError(std::move(d));
  }
  bindings_.push_back(Binding{name, std::move(value), loc});
}

Binding* Interpreter::lookup(ast::Symbol name) {
  for (std::size_t i = bindings_.size(); i-- > frame_base_;)
    if (bindings_[i].name == name) {
      bindings_[i].used = true;
      return &bindings_[i];
    }
  if (frame_base_ > 0)
    for (std::size_t i = globals_end(); i-- > 0;)
      if (bindings_[i].name == name) {
        bindings_[i].used = true;
        return &bindings_[i];
      }
  return nullptr;
}

// ---------------------------------------------------------------------------------------
// Statements
// ---------------------------------------------------------------------------------------

Flow Interpreter::exec_list(const ast::StmtList& stmts) {
  for (const ast::StmtLink& s : stmts) {
    Flow f = exec(*s);
    if (f != Flow::Normal) return f;
  }
  return Flow::Normal;
}

Flow Interpreter::exec_body(const ast::Body& body) {
  check_stack(body.stmts.empty() ? current_loc_ : body.stmts.front()->loc);
  push_scope();
  Flow f = exec_list(body.stmts);
  pop_scope();
  return f;
}

Flow Interpreter::exec(const ast::Stmt& s) {
  current_loc_ = s.loc;
  budget_.check_time(s.loc, "statements");
  switch (s.kind) {
    case ast::StmtKind::Let:
      exec_let(static_cast<const ast::LetStmt&>(s));
      return Flow::Normal;
    case ast::StmtKind::Assign:
      exec_assign(static_cast<const ast::AssignStmt&>(s));
      return Flow::Normal;
    case ast::StmtKind::If: {
      const auto& st = static_cast<const ast::IfStmt&>(s);
      Value c = eval(*st.cond);
      if (c.type != Type::Bool)
        fail(st.cond->loc, fmt::format("'if' condition must be a bool, got {}", with_article(c.type)));
      if (c.truth()) return exec_body(st.then_body);
      if (st.else_body) return exec_body(*st.else_body);
      return Flow::Normal;
    }
    case ast::StmtKind::For:
      return exec_for(static_cast<const ast::ForStmt&>(s));
    case ast::StmtKind::While:
      return exec_while(static_cast<const ast::WhileStmt&>(s));
    case ast::StmtKind::Macro: {
      const auto& m = static_cast<const ast::MacroStmt&>(s);
      Value v;
      v.type = Type::Macro;
      v.ref = std::make_shared<MacroValue>(&m);
      declare(m.name, std::move(v), m.loc);
      return Flow::Normal;
    }
    case ast::StmtKind::Return: {
      if (!in_macro_) fail(s.loc, "'return' outside a macro");
      const auto& r = static_cast<const ast::ReturnStmt&>(s);
      return_value_ = r.value ? eval(*r.value) : Value::none();
      return Flow::Return;
    }
    case ast::StmtKind::Break:
      if (loop_depth_ == 0) fail(s.loc, "'break' outside a loop");
      return Flow::Break;
    case ast::StmtKind::Continue:
      if (loop_depth_ == 0) fail(s.loc, "'continue' outside a loop");
      return Flow::Continue;
    case ast::StmtKind::Include:
      exec_include(static_cast<const ast::IncludeStmt&>(s));
      return Flow::Normal;
    case ast::StmtKind::ExprStmt: {
      const auto& e = static_cast<const ast::ExprStmt&>(s);
      // A block statement is placed and dropped: nothing can derive from it with `with`, so
      // its properties need not be kept (one allocation less per `sphere { ... }` in a loop).
      Value v = e.expr->kind == ast::ExprKind::Block
                    ? eval_block(static_cast<const ast::BlockExpr&>(*e.expr), /*keep_block=*/false)
                    : eval(*e.expr);
      if (v.type == Type::Object) place(v, e.expr->loc);
      return Flow::Normal;
    }
  }
  return Flow::Normal;
}

void Interpreter::exec_let(const ast::LetStmt& s) { declare(s.name, eval(*s.value), s.name_loc); }

bool Interpreter::exec_append(const ast::AssignStmt& s) {
  const ast::Expr* rhs = nullptr;
  if (s.op == ast::AssignOp::Add) {
    rhs = s.value.get();
  } else if (s.op == ast::AssignOp::Set && s.value->kind == ast::ExprKind::Binary) {
    const auto& bin = static_cast<const ast::BinaryExpr&>(*s.value);
    if (bin.op() == ast::BinaryOp::Add && bin.lhs->kind == ast::ExprKind::Name &&
        static_cast<const ast::NameExpr&>(*bin.lhs).name == s.name)
      rhs = bin.rhs.get();
  }
  if (!rhs) return false;
  Binding* b = lookup(s.name);
  if (!b || (b->value.type != Type::List && b->value.type != Type::String)) return false;
  // The left operand is taken first, as `a + b` always does; evaluating the right one may
  // rebind the variable (a macro assigning it), in which case `old` is still the value.
  Value old = b->value;
  Value v = eval(*rhs);
  SourceLoc loc = s.op == ast::AssignOp::Add ? s.loc : static_cast<const ast::BinaryExpr&>(*s.value).op_loc();
  if (v.type != old.type) {
    Value r = binary_op(ast::BinaryOp::Add, old, v, loc);  // the usual type error
    lookup(s.name)->value = std::move(r);
    return true;
  }
  b = lookup(s.name);  // bindings may have moved while evaluating the right operand
  if (b->value.ref == old.ref) b->value = Value::none();  // `old` now holds the only reference (if no one else does)
  Value r = concat(std::move(old), v, loc);
  lookup(s.name)->value = std::move(r);
  return true;
}

Value Interpreter::concat(Value a, const Value& b, SourceLoc loc) {
  const bool unique = a.ref.use_count() == 1;
  if (a.type == Type::String) {
    const std::string& tail = as_string(b);
    const std::string& head = as_string(a);
    spend(unique ? tail.size() : head.size() + tail.size(), loc, "string bytes built");
    if (!unique || head.size() + tail.size() > head.capacity()) {
      std::size_t bytes = unique ? std::max(2 * head.capacity(), head.size() + tail.size()) : head.size() + tail.size();
      if (bytes >= kBigAllocationBytes) check_memory(bytes, loc, "this string");
    }
    if (!unique) return Value::string(head + tail);
    static_cast<StringValue&>(*a.ref).text += tail;  // b may be a itself: += copes with that
    return a;
  }
  const std::vector<Value>& head = as_list(a);
  const std::vector<Value>& tail = as_list(b);
  const std::size_t n = head.size() + tail.size();
  spend(unique ? tail.size() : n, loc, "list elements built");
  if (!unique || n > head.capacity()) {
    std::size_t count = unique ? std::max(2 * head.capacity(), n) : n;
    if (count * sizeof(Value) >= kBigAllocationBytes) check_memory(count * sizeof(Value), loc, "this list");
  }
  if (!unique) {
    std::vector<Value> items;
    items.reserve(n);
    items.insert(items.end(), head.begin(), head.end());
    items.insert(items.end(), tail.begin(), tail.end());
    Value list = Value::list(std::move(items));
    check_nesting(list, loc);
    return list;
  }
  auto& list = static_cast<ListValue&>(*a.ref);
  if (a.ref == b.ref) {  // xs + xs: inserting a range of a vector into itself is undefined
    std::vector<Value> copy = tail;
    list.items.insert(list.items.end(), copy.begin(), copy.end());
  } else {
    list.items.insert(list.items.end(), tail.begin(), tail.end());
    list.depth = std::max(list.depth, nesting_depth(b));
    check_nesting(a, loc);
  }
  return a;
}

void Interpreter::exec_assign(const ast::AssignStmt& s) {
  if (exec_append(s)) return;
  Value v = eval(*s.value);
  Binding* b = lookup(s.name);
  if (!b) {
    std::vector<std::string_view> candidates;
    for (std::size_t i = frame_base_; i < bindings_.size(); ++i) candidates.push_back(*bindings_[i].name);
    if (frame_base_ > 0)
      for (std::size_t i = 0; i < globals_end(); ++i) candidates.push_back(*bindings_[i].name);
    std::string msg = fmt::format("cannot assign to undefined name '{}'", *s.name);
    std::string hint = render::closest_name(*s.name, candidates);
    if (!hint.empty())
      msg += fmt::format("; did you mean '{}'?", hint);
    else
      msg += fmt::format(" (declare it with 'let {} = ...')", *s.name);
    fail(s.loc, msg);
  }
  switch (s.op) {
    case ast::AssignOp::Set:
      b->value = std::move(v);
      break;
    case ast::AssignOp::Add:
      b->value = binary_op(ast::BinaryOp::Add, b->value, v, s.loc);
      break;
    case ast::AssignOp::Sub:
      b->value = binary_op(ast::BinaryOp::Sub, b->value, v, s.loc);
      break;
    case ast::AssignOp::Mul:
      b->value = binary_op(ast::BinaryOp::Mul, b->value, v, s.loc);
      break;
    case ast::AssignOp::Div:
      b->value = binary_op(ast::BinaryOp::Div, b->value, v, s.loc);
      break;
  }
}

Flow Interpreter::exec_for(const ast::ForStmt& s) {
  Value seq = eval(*s.iterable);
  if (seq.type != Type::Range && seq.type != Type::List)
    fail(s.iterable->loc, fmt::format("'for' needs a range or a list to iterate over, got {}", with_article(seq.type)));
  push_scope();
  declare(s.var, Value::none(), s.var_loc);
  const std::size_t slot = bindings_.size() - 1;
  ++loop_depth_;
  Flow result = Flow::Normal;
  uint64_t n = seq.type == Type::Range ? range_count(seq) : as_list(seq).size();
  for (uint64_t k = 0; k < n; ++k) {
    count_iteration(s.loc);
    bindings_[slot].value = seq.type == Type::Range ? Value::number(range_at(seq, k)) : as_list(seq)[k];
    Flow f = exec_body(s.body);
    if (f == Flow::Break) break;
    if (f == Flow::Return) {
      result = f;
      break;
    }
  }
  --loop_depth_;
  pop_scope();
  return result;
}

Flow Interpreter::exec_while(const ast::WhileStmt& s) {
  ++loop_depth_;
  Flow result = Flow::Normal;
  for (;;) {
    Value c = eval(*s.cond);
    if (c.type != Type::Bool)
      fail(s.cond->loc, fmt::format("'while' condition must be a bool, got {}", with_article(c.type)));
    if (!c.truth()) break;
    count_iteration(s.loc);
    Flow f = exec_body(s.body);
    if (f == Flow::Break) break;
    if (f == Flow::Return) {
      result = f;
      break;
    }
  }
  --loop_depth_;
  return result;
}

}  // namespace rts::runtime

namespace rts::runtime {

std::vector<GlobalValue> Interpreter::describe_globals(std::size_t max_bytes) const {
  std::vector<GlobalValue> out;
  const std::size_t end = std::min(globals_end(), bindings_.size());
  for (std::size_t i = 0; i < end; ++i) {
    const Binding& b = bindings_[i];
    GlobalValue g{*b.name, b.loc, {}};
    if (!append_text(g.value, b.value, true, max_bytes)) {
      g.value.resize(std::min(g.value.size(), max_bytes));
      while (!g.value.empty() && (static_cast<unsigned char>(g.value.back()) & 0xC0) == 0x80) g.value.pop_back();
      g.value += "…";
    }
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace rts::runtime
