// Statements, names, expressions, macro calls and includes.
#include "runtime/interpreter.hpp"

#include <chrono>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>

#include "parser/parser.hpp"
#include "render/scene/params.hpp"
#include "runtime/ops.hpp"
#include "runtime/povray_hints.hpp"
#include "runtime/stdlib_path.hpp"

namespace rts::runtime {

namespace fs = std::filesystem;

namespace {
// Builtin calls with at most this many arguments keep them on the C++ stack.
constexpr std::size_t kInlineArgs = 8;
// The resident size is read (a small /proc read) once per this many evaluation steps, so
// that memory growth no single check sees (many small values) is still bounded.
constexpr uint64_t kStepsPerMemoryCheck = 1 << 16;
// Growing a list or string by less than this is not worth a memory check of its own.
constexpr std::size_t kBigAllocationBytes = 1 << 20;
// Included files must be named like scenes: rts never shows excerpts of other files (a
// mistyped `include "/etc/shadow"` would otherwise print its first line in a syntax error).
bool is_scene_file_name(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  return ext == ".rts" || ext == ".inc";
}
}  // namespace

Interpreter::Interpreter(SourceManager& sources, const EvalOptions& options, DiagnosticSink& warnings)
    : sources_(sources),
      options_(options),
      warnings_(warnings),
      builder_(render::BuilderLimits{options.limits.max_mesh_triangles, options.limits.max_memory}) {
  const auto& table = builtin_table();
  for (uint32_t i = 0; i < table.size(); ++i) builtins_[ast::intern(table[i].name)] = i;
}

void Interpreter::fail(SourceLoc loc, std::string message) const { throw LanguageError(loc, std::move(message)); }

render::SourceRef Interpreter::ref(SourceLoc loc) {
  if (!loc.file) return {};
  return render::SourceRef{loc.file->path().c_str(), loc.line, loc.col};
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
  auto it = files_by_name_.find(e.where.file);
  if (it != files_by_name_.end()) d.loc = SourceLoc{it->second, e.where.line, e.where.col};
  add_notes(d);
  return LanguageError(std::move(d));
}

// ---------------------------------------------------------------------------------------
// Running files
// ---------------------------------------------------------------------------------------

void Interpreter::run(const SourceFile& main) {
  if (options_.restrict_reads) {
    std::vector<std::string> roots;
    std::string main_dir = fs::path(main.path()).parent_path().string();
    roots.push_back(main_dir.empty() ? "." : main_dir);
    roots.insert(roots.end(), options_.include_paths.begin(), options_.include_paths.end());
    if (!stdlib_dir().empty()) roots.push_back(stdlib_dir());
    roots.push_back(".");
    roots.insert(roots.end(), options_.allow_read.begin(), options_.allow_read.end());
    read_policy_ = render::ReadPolicy(roots);
    builder_.set_read_policy(read_policy_);
  }
  next_memory_check_ = options_.limits.max_memory ? kStepsPerMemoryCheck : UINT64_MAX;
  try {
    files_by_name_[main.path().c_str()] = &main;
    programs_.push_back(timed_parse(main));
    main_program_ = &programs_.back();
    std::error_code ec;
    include_chain_.push_back(fs::weakly_canonical(main.path(), ec).string());
    parsed_[include_chain_.back()] = main_program_;

    // Each define is parsed as `let name = value` from a small file of its own, so its
    // errors point into "<define name>" and show the define as a let.
    for (const Define& d : options_.defines) {
      const SourceFile* f =
          sources_.add(fmt::format("<define {}>", d.name), fmt::format("let {} = {}", d.name, d.value));
      files_by_name_[f->path().c_str()] = f;
      programs_.push_back(timed_parse(*f));
      const ast::Program& p = programs_.back();
      if (p.stmts.size() != 1 || p.stmts[0]->kind != ast::StmtKind::Let)
        fail(SourceLoc{f, 1, 1}, fmt::format("define '{}={}' is not a single value", d.name, d.value));
      defines_.push_back(DefineExpr{ast::intern(d.name), static_cast<const ast::LetStmt&>(*p.stmts[0]).value.get(),
                                    d.name + "=" + d.value});
    }

    push_scope();  // the global scope
    run_program(*main_program_, true);
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
  if (options_.warn_unused) warn_unused(main);
  for (const DefineExpr& d : defines_)
    if (!d.used)
      warnings_.warning(SourceLoc{&main, 0, 0},
                        fmt::format("define '{}' matches no top-level 'let {}' in this file", d.text, *d.name));
}

void Interpreter::run_program(const ast::Program& program, bool is_main) {
  unsigned saved_loops = loop_depth_;
  bool saved_macro = in_macro_;
  loop_depth_ = 0;  // `break` in an included file cannot leave a loop of the includer
  in_macro_ = false;
  for (const ast::StmtPtr& s : program.stmts) {
    if (is_main && s->kind == ast::StmtKind::Let) {
      const auto& let = static_cast<const ast::LetStmt&>(*s);
      // The last -D of a name wins (like repeated command-line options); it applies once.
      DefineExpr* def = nullptr;
      for (DefineExpr& d : defines_)
        if (d.name == let.name && !d.used) def = &d;
      if (def) {
        for (DefineExpr& d : defines_)
          if (d.name == let.name) d.used = true;
        declare(let.name, eval(*def->expr), let.name_loc);
        continue;
      }
    }
    exec(*s);
  }
  loop_depth_ = saved_loops;
  in_macro_ = saved_macro;
}

void Interpreter::exec_include(const ast::IncludeStmt& s) {
  fs::path including_dir = fs::path(s.loc.file->path()).parent_path();
  std::vector<fs::path> candidates;
  if (fs::path(s.path).is_absolute()) {
    candidates.emplace_back(s.path);
  } else if (!names_standard_library(s.path)) {
    candidates.push_back(including_dir / s.path);
    for (const std::string& dir : options_.include_paths) candidates.push_back(fs::path(dir) / s.path);
  }
  // Then the standard library (docs/library.md): after the scene's own files, so they win.
  for (fs::path& c : standard_library_candidates(stdlib_dir(), s.path)) candidates.push_back(std::move(c));
  std::error_code ec;
  const fs::path* found = nullptr;
  for (const fs::path& c : candidates) {
    if (fs::is_regular_file(c, ec)) {
      found = &c;
      break;
    }
    // A directory, FIFO or device of that name is named as such (reading a FIFO would block).
    if (std::string kind = render::non_regular_kind(c.string()); !kind.empty())
      fail(s.loc, fmt::format("cannot include '{}': '{}' is {}, not a scene file", s.path, c.string(), kind));
  }
  if (!found) {
    if (names_standard_library(s.path))
      fail(s.loc, fmt::format("cannot find include file '{}' in the standard library{}", s.path,
                              stdlib_dir().empty() ? " (no standard library folder was found: set RTS_STDLIB)"
                                                   : " " + stdlib_dir()));
    std::string where = "next to this file";
    if (!options_.include_paths.empty()) {
      where += " or in the -I folders";
      for (std::size_t i = 0; i < options_.include_paths.size(); ++i)
        where += (i ? ", " : " ") + options_.include_paths[i];
    }
    if (stdlib_dir().empty())
      where += " (nor a standard library: none was found; set RTS_STDLIB to its folder)";
    else if (fs::path(s.path).extension() == ".inc" && !fs::path(s.path).has_parent_path())
      where += fmt::format(" (rts's standard library has no '{}' either; docs/library.md lists its files)",
                           fs::path(s.path).stem().string());
    fail(s.loc, fmt::format("cannot find include file '{}' {}", s.path, where));
  }
  std::string canonical = fs::weakly_canonical(*found, ec).string();
  if (!read_policy_.allows(found->string())) fail(s.loc, read_policy_.refusal(s.path, found->string()));
  if (!is_scene_file_name(canonical))
    fail(s.loc, fmt::format("cannot include '{}': included files must be scene files named *.rts or *.inc{}", s.path,
                            canonical != found->lexically_normal().string()
                                ? fmt::format(" (it leads to '{}')", canonical)
                                : ""));
  contexts_.push_back(Context{Context::Include, s.loc, nullptr});
  for (const std::string& open : include_chain_)
    if (open == canonical) {
      contexts_.pop_back();  // the note for this include is the error itself
      fail(s.loc, fmt::format("include cycle: '{}' is already being included", s.path));
    }
  if (included_.count(canonical)) {  // fully included before: once only (like #pragma once)
    contexts_.pop_back();
    return;
  }
  const ast::Program* program;
  if (auto it = parsed_.find(canonical); it != parsed_.end()) {
    program = it->second;
  } else {
    const SourceFile* file;
    try {
      file = sources_.load(found->lexically_normal().string());
    } catch (const SourceError& e) {
      fail(s.loc, fmt::format("cannot read include file '{}': {}", s.path, e.message));
    }
    files_by_name_[file->path().c_str()] = file;
    programs_.push_back(timed_parse(*file));
    program = &programs_.back();
    parsed_[canonical] = program;
  }
  include_chain_.push_back(canonical);
  run_program(*program, false);
  include_chain_.pop_back();
  included_.insert(std::move(canonical));
  contexts_.pop_back();
}

const std::string& Interpreter::stdlib_dir() {
  if (!stdlib_found_) {
    stdlib_dir_ = options_.stdlib_dir.empty() ? find_standard_library() : options_.stdlib_dir;
    stdlib_found_ = true;
  }
  return stdlib_dir_;
}

// ---------------------------------------------------------------------------------------
// Scopes and names
// ---------------------------------------------------------------------------------------

ast::Program Interpreter::timed_parse(const SourceFile& file) {
  auto start = std::chrono::steady_clock::now();
  ast::Program p = parse(file);
  parse_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return p;
}

void Interpreter::declare(ast::Symbol name, Value value, SourceLoc loc) {
  for (std::size_t i = scopes_.back(); i < bindings_.size(); ++i) {
    if (bindings_[i].name == name) {
      Diagnostic d;
      d.loc = loc;
      d.message = fmt::format("'{}' is already defined in this scope (assign with '{} = ...' instead)", *name, *name);
      d.notes.push_back(Note{bindings_[i].loc, "previously defined here"});
      throw LanguageError(std::move(d));
    }
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

namespace {
// The file an unused declaration names ("file" of a mesh or image_texture), or "".
std::string declared_file(const std::vector<Property>& props) {
  for (const Property& p : props)
    if (*p.name == "file" && p.value.type == Type::String) return as_string(p.value);
  return {};
}
}  // namespace

void Interpreter::warn_unused(const SourceFile& main) {
  for (std::size_t i = 0; i < globals_end(); ++i) {
    const Binding& b = bindings_[i];
    if (b.used || b.loc.file != &main) continue;
    std::string what, file;
    bool built = false;  // shapes and lights other than meshes are built (and checked) when declared
    switch (b.value.type) {
      case Type::Material: what = "material"; break;
      case Type::Texture:
        what = "texture";
        file = declared_file(as_record(b.value).props);
        break;
      case Type::Macro: what = "macro"; break;
      case Type::Object: {
        what = "object";
        if (!b.value.ref) break;
        const ObjectValue& def = static_cast<const ObjectValue&>(*b.value.ref).definition();
        if (def.kind) what = *def.kind;
        built = def.built_id != render::kNoId;
        file = declared_file(def.props);
        break;
      }
      default: break;
    }
    if (what.empty()) continue;
    const char* why = built ? "" : b.value.type == Type::Macro ? " (so it never runs)" : " (so it is not built)";
    std::string msg = fmt::format("{} '{}' is declared but never used{}", what, *b.name, why);
    if (!file.empty()) {
      std::error_code ec;
      fs::path path(file);  // relative to the declaring file, as the builder resolves it
      if (path.is_relative()) path = fs::path(main.path()).parent_path() / path;
      if (!fs::exists(path, ec)) msg += fmt::format("; its file '{}' does not exist", file);
    }
    warnings_.warning(b.loc, msg);
  }
}

uint32_t Interpreter::find_builtin(ast::Symbol name) {
  // Symbols are interned pointers: a direct-mapped cache on the pointer answers repeated
  // calls (sin, cos... in loops) without hashing.
  BuiltinCacheEntry& slot = builtin_cache_[(reinterpret_cast<std::uintptr_t>(name) >> 4) % kBuiltinCacheSize];
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
// Statements
// ---------------------------------------------------------------------------------------

Flow Interpreter::exec_list(const ast::StmtList& stmts) {
  for (const ast::StmtPtr& s : stmts) {
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
    if (bin.op == ast::BinaryOp::Add && bin.lhs->kind == ast::ExprKind::Name &&
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
  SourceLoc loc = s.op == ast::AssignOp::Add ? s.loc : static_cast<const ast::BinaryExpr&>(*s.value).op_loc;
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

void Interpreter::count_iteration(SourceLoc loc) {
  if (++iterations_ > options_.limits.max_iterations)
    fail(loc, fmt::format("loops ran more than {} iterations in total (raise the limit with --max-iterations)",
                          options_.limits.max_iterations));
  spend(1, loc, "loop iterations");
}

void Interpreter::check_budgets(SourceLoc loc, const char* what) {
  if (steps_ > options_.limits.max_steps)
    fail(loc, fmt::format("evaluation ran more than {} steps (loop iterations, macro calls and list elements and "
                          "string bytes built); it ran away here, in {} (raise the limit with --max-steps)",
                          options_.limits.max_steps, what));
  next_memory_check_ = steps_ + kStepsPerMemoryCheck;
  check_memory(0, loc, what);
}

std::string Interpreter::text_of(const Value& v, SourceLoc loc, bool quote_strings) {
  const uint64_t left = steps_ < options_.limits.max_steps ? options_.limits.max_steps - steps_ : 0;
  // And a third of what --max-memory leaves: while a string grows it briefly holds its old
  // buffer and one twice as large.
  const std::size_t max = options_.limits.max_memory;
  std::size_t room = SIZE_MAX;
  if (max > 0) {
    const std::size_t held = render::resident_bytes();
    room = held < max ? (max - held) / 3 : 0;
  }
  const std::size_t limit = static_cast<std::size_t>(std::min<uint64_t>(left, room));
  std::string text;
  if (!append_text(text, v, quote_strings, limit)) {
    if (room < left)
      fail(loc, fmt::format("this text would need more than {} more memory, past the memory limit of {} (raise it "
                            "with --max-memory)",
                            render::size_in_words(room), render::size_in_words(max)));
    // Past the step budget: spend it all and one more, which fails with the budget's message.
    spend(left + 1, loc, "string bytes built");
  }
  spend(text.size(), loc, "string bytes built");
  return text;
}

void Interpreter::check_memory(std::size_t bytes, SourceLoc loc, const char* what) {
  const std::size_t max = options_.limits.max_memory;
  if (render::memory_fits(max, bytes)) return;
  if (bytes > 0)
    fail(loc, fmt::format("{} would need {} more memory, past the memory limit of {} (raise it with --max-memory)",
                          what, render::size_in_words(bytes), render::size_in_words(max)));
  fail(loc, fmt::format("the scene uses more than the memory limit of {} (it was building {} here; raise the limit "
                        "with --max-memory)",
                        render::size_in_words(max), what));
}

void Interpreter::stack_exhausted(SourceLoc loc) {
  fail(loc, fmt::format("evaluation nested too deeply for its {} stack at macro depth {} (the stack could not be made "
                        "larger: lower --max-recursion or the nesting of the scene)",
                        render::size_in_words(stack_bytes_), macro_depth_));
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
      return Value::number(static_cast<const ast::NumberExpr&>(e).value);
    case ast::ExprKind::String:
      return Value::string(static_cast<const ast::StringExpr&>(e).value);
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
      for (const ast::ExprPtr& x : le.elements) items.push_back(eval(*x));
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

Value Interpreter::eval_unary(const ast::UnaryExpr& e) { return unary_op(e.op, eval(*e.operand), e.loc); }

Value Interpreter::eval_binary(const ast::BinaryExpr& e) {
  if (e.op == ast::BinaryOp::And || e.op == ast::BinaryOp::Or) {
    Value a = eval(*e.lhs);
    if (a.type != Type::Bool)
      fail(e.lhs->loc, fmt::format("'{}' needs bools, got {}", ast::to_string(e.op), with_article(a.type)));
    if (e.op == ast::BinaryOp::And ? !a.truth() : a.truth()) return a;  // short-circuit
    Value b = eval(*e.rhs);
    if (b.type != Type::Bool)
      fail(e.rhs->loc, fmt::format("'{}' needs bools, got {}", ast::to_string(e.op), with_article(b.type)));
    return b;
  }
  Value a = eval(*e.lhs);
  Value b = eval(*e.rhs);
  if (e.op == ast::BinaryOp::Add && a.type == b.type && (a.type == Type::List || a.type == Type::String))
    return concat(std::move(a), b, e.op_loc);
  return binary_op(e.op, a, b, e.op_loc);
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
  // Arguments are evaluated in the caller's scope, then bound in the macro's frame.
  std::vector<Value> values(params.size());
  std::vector<const ast::Argument*> given(params.size(), nullptr);
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
      if (given[slot]) fail(a.loc, fmt::format("argument '{}' given twice", *a.name));
    }
    given[slot] = &a;
    values[slot] = eval(*a.value);
  }
  for (std::size_t p = 0; p < params.size(); ++p)
    if (!given[p] && !params[p].default_value)
      fail(call.loc, fmt::format("missing argument '{}' in call to macro '{}'", *params[p].name, *m.name));
  if (macro_depth_ >= options_.limits.max_recursion)
    fail(call.loc, fmt::format("macro calls nested deeper than {} (raise the limit with --max-recursion)",
                               options_.limits.max_recursion));
  check_stack(call.loc);
  // A macro call is a step (a recursion that doubles, f(d-1) f(d-1), never nests deep).
  if (++steps_ > options_.limits.max_steps || steps_ >= next_memory_check_)
    check_budgets(call.loc, fmt::format("calls to macro '{}'", *m.name).c_str());

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
    Value v = given[p] ? std::move(values[p]) : eval(*params[p].default_value);
    declare(params[p].name, std::move(v), params[p].loc);
  }
  Flow f = exec_list(m.body.stmts);
  Value result = f == Flow::Return ? std::move(return_value_) : Value::none();
  return_value_ = Value::none();
  pop_scope();
  --macro_depth_;
  in_macro_ = saved_in_macro;
  loop_depth_ = saved_loops;
  frame_base_ = saved_base;
  contexts_.pop_back();
  return result;
}

}  // namespace rts::runtime
