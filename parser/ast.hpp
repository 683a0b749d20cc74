// The typed abstract syntax tree of an rts scene program. The parser builds it from the
// PEGTL grammar; the evaluator walks it; the S-expression printer (ast_printer.hpp) shows it.
// Every node carries the SourceLoc of its first character. Nodes, their child lists and
// their strings live in the program's NodeArena and are freed all at once with the Program
// (no node has a destructor or a virtual-table pointer: `kind` says what it is).
// Identifiers are interned Symbols (number comparison, no string hashing at run time).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "parser/source.hpp"

namespace rts::ast {

// An interned identifier, 4 bytes: two Symbols are equal iff they name the same string.
// The number indexes one process-wide table of the interned strings (never freed), read
// without a lock; `*symbol` is the name. Half a pointer, because names are in most nodes
// (issue 24: block items, names, arguments).
class Symbol {
 public:
  Symbol() = default;
  Symbol(std::nullptr_t) {}
  const std::string& operator*() const { return *name(); }
  const std::string* operator->() const { return name(); }
  explicit operator bool() const { return id_ != 0; }
  uint32_t id() const { return id_; }
  friend bool operator==(Symbol a, Symbol b) { return a.id_ == b.id_; }
  friend bool operator!=(Symbol a, Symbol b) { return a.id_ != b.id_; }
  friend bool operator==(Symbol a, std::nullptr_t) { return a.id_ == 0; }
  friend bool operator!=(Symbol a, std::nullptr_t) { return a.id_ != 0; }

 private:
  friend Symbol intern(std::string_view name);
  static constexpr uint32_t kChunkBits = 12;
  static constexpr uint32_t kChunkSize = 1u << kChunkBits;
  static const std::string*** chunks();  // [id >> kChunkBits][id & (kChunkSize - 1)]
  const std::string* name() const {
    const std::string** chunk =
        std::atomic_ref<const std::string**>(chunks()[id_ >> kChunkBits]).load(std::memory_order_acquire);
    return chunk[id_ & (kChunkSize - 1)];
  }
  uint32_t id_ = 0;  // 0: no symbol
};
Symbol intern(std::string_view name);

struct Expr;
struct Stmt;

// A link from a node to another node of the same program. Nodes do not own each other:
// their memory is the program's NodeArena's and goes with it, and no node has anything to
// destroy (its lists and strings live in the same arena), so a link is a bare pointer.
template <class T>
class NodePtr {
 public:
  NodePtr() = default;
  NodePtr(std::nullptr_t) {}
  explicit NodePtr(T* node) : node_(node) {}
  template <class U, class = std::enable_if_t<std::is_convertible_v<U*, T*>>>
  NodePtr(NodePtr<U> other) : node_(other.get()) {}

  T* get() const { return node_; }
  T& operator*() const { return *node_; }
  T* operator->() const { return node_; }
  explicit operator bool() const { return node_ != nullptr; }
  friend bool operator==(NodePtr a, std::nullptr_t) { return a.node_ == nullptr; }
  friend bool operator!=(NodePtr a, std::nullptr_t) { return a.node_ != nullptr; }

 private:
  T* node_ = nullptr;
};
using ExprPtr = NodePtr<Expr>;
using StmtPtr = NodePtr<Stmt>;

// A node's children, in order: a run of elements in the arena (read-only once built).
template <class T>
class NodeList {
 public:
  NodeList() = default;
  NodeList(const T* first, uint32_t count) : first_(first), count_(count) {}

  const T* begin() const { return first_; }
  const T* end() const { return first_ + count_; }
  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const T& operator[](std::size_t i) const { return first_[i]; }
  const T& at(std::size_t i) const {
    if (i >= count_) throw std::out_of_range("NodeList::at");
    return first_[i];
  }
  const T& front() const { return first_[0]; }
  const T& back() const { return first_[count_ - 1]; }

 private:
  const T* first_ = nullptr;
  uint32_t count_ = 0;
};
using StmtList = NodeList<StmtPtr>;

// Where a program's nodes live: blocks taken from the heap and handed out in order, never
// freed one by one. Profile finding (issue 24, heaptrack of `rts parse` on a generated scene):
// a statement of ~70 bytes became about 14 heap blocks, each with the allocator's header and
// rounding (930k allocations for 5 MB of text, the peak 12.6 times the file); nodes, their
// child vectors and their virtual-table pointers were most of them. Nodes, their lists and
// their strings now all come from here, and nothing in the arena has a destructor: a
// program is freed block by block. The blocks grow from kFirstBlock to kLargestBlock, so
// that a small include costs little. Whoever holds the nodes must hold the arena as long
// (Program, ParseState).
class NodeArena {
 public:
  NodeArena() = default;
  NodeArena(const NodeArena&) = delete;
  NodeArena& operator=(const NodeArena&) = delete;

  template <class T, class... Args>
  NodePtr<T> make(Args&&... args) {
    static_assert(std::is_trivially_destructible_v<T>, "an AST node has nothing to destroy");
    static_assert(alignof(T) <= alignof(std::max_align_t), "an AST node needs no over-alignment");
    void* at = allocate(sizeof(T), alignof(T));
    return NodePtr<T>(new (at) T(std::forward<Args>(args)...));
  }
  // The list of `get(x)` for each x in [first, last), in the arena.
  template <class T, class It, class Get>
  NodeList<T> list(It first, It last, Get get) {
    static_assert(std::is_trivially_destructible_v<T>, "a node's list has nothing to destroy");
    const auto count = static_cast<std::size_t>(last - first);
    if (count == 0) return {};
    T* at = static_cast<T*>(allocate(count * sizeof(T), alignof(T)));
    for (std::size_t k = 0; first != last; ++first, ++k) new (at + k) T(get(*first));
    return NodeList<T>(at, static_cast<uint32_t>(count));
  }
  // A copy of `text` in the arena (a view that lives as long as the arena).
  std::string_view text(std::string_view text) {
    if (text.empty()) return {};
    void* at = allocate(text.size(), 1);
    std::memcpy(at, text.data(), text.size());
    return {static_cast<const char*>(at), text.size()};
  }
  // Bytes taken from the heap (the blocks' sizes).
  std::size_t reserved() const { return reserved_; }

 private:
  static constexpr std::size_t kFirstBlock = 4096;
  static constexpr std::size_t kLargestBlock = std::size_t{1} << 20;
  void* allocate(std::size_t size, std::size_t align) {
    std::size_t at = (used_ + align - 1) & ~(align - 1);
    if (blocks_.empty() || at + size > block_size_) {
      block_size_ = blocks_.empty() ? kFirstBlock : std::min(2 * block_size_, kLargestBlock);
      if (block_size_ < size) block_size_ = size;
      blocks_.push_back(std::make_unique<std::max_align_t[]>((block_size_ + sizeof(std::max_align_t) - 1) /
                                                              sizeof(std::max_align_t)));
      reserved_ += block_size_;
      at = 0;
    }
    used_ = at + size;
    return reinterpret_cast<std::byte*>(blocks_.back().get()) + at;
  }
  std::vector<std::unique_ptr<std::max_align_t[]>> blocks_;
  std::size_t block_size_ = 0;
  std::size_t used_ = 0;
  std::size_t reserved_ = 0;
};

// ---------------------------------------------------------------------------------------
// Expressions
// ---------------------------------------------------------------------------------------
enum class ExprKind : uint8_t {
  Number, String, Bool, None, Name, Vector, List, Unary, Binary, Range, Call, Index, Member,
  Block, With, Transform,
};

struct Expr {
  ExprKind kind;
  SourceLoc loc;
  explicit Expr(ExprKind k, SourceLoc l) : kind(k), loc(l) {}
};

struct NumberExpr : Expr {
  double value;
  NumberExpr(SourceLoc l, double v) : Expr(ExprKind::Number, l), value(v) {}
};
struct StringExpr : Expr {
  std::string_view value;  // escapes already decoded; the text is in the arena
  StringExpr(SourceLoc l, std::string_view v) : Expr(ExprKind::String, l), value(v) {}
};
struct BoolExpr : Expr {
  bool value;
  BoolExpr(SourceLoc l, bool v) : Expr(ExprKind::Bool, l), value(v) {}
};
struct NoneExpr : Expr {
  explicit NoneExpr(SourceLoc l) : Expr(ExprKind::None, l) {}
};
struct NameExpr : Expr {
  Symbol name;
  NameExpr(SourceLoc l, Symbol n) : Expr(ExprKind::Name, l), name(n) {}
};
// A vector's components: a list of links, or, when every component is a number literal and
// the literals lie one after another in the arena (they were parsed one after another), the
// literals themselves, with no list of links (issue 24: `<1, -2, 3>` is most of a generated
// scene's vectors; the list was 24 of their 96 bytes). Reads as a list of ExprPtr either way.
class ComponentList {
 public:
  class iterator {
   public:
    iterator(const ComponentList* list, std::size_t i) : list_(list), i_(i) {}
    ExprPtr operator*() const { return (*list_)[i_]; }
    iterator& operator++() {
      ++i_;
      return *this;
    }
    bool operator!=(const iterator& o) const { return i_ != o.i_; }
    bool operator==(const iterator& o) const { return i_ == o.i_; }

   private:
    const ComponentList* list_;
    std::size_t i_;
  };

  ComponentList() = default;
  explicit ComponentList(NodeList<ExprPtr> links) : first_(links.begin()), count_(static_cast<uint32_t>(links.size())) {}
  // `count` number literals at consecutive addresses from `first`.
  ComponentList(const NumberExpr* first, uint32_t count) : first_(first), count_(count), literals_(true) {}

  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  bool literals() const { return literals_; }
  ExprPtr operator[](std::size_t i) const;
  iterator begin() const { return {this, 0}; }
  iterator end() const { return {this, count_}; }

 private:
  const void* first_ = nullptr;
  uint32_t count_ = 0;
  bool literals_ = false;
};

// <x, y, z> (the grammar allows 2 to 4 components; the evaluator decides what it accepts)
struct VectorExpr : Expr {
  ComponentList components;
  explicit VectorExpr(SourceLoc l) : Expr(ExprKind::Vector, l) {}
};

inline ExprPtr ComponentList::operator[](std::size_t i) const {
  if (literals_) return ExprPtr(const_cast<NumberExpr*>(static_cast<const NumberExpr*>(first_) + i));
  return static_cast<const ExprPtr*>(first_)[i];
}
// [a, b, c]
struct ListExpr : Expr {
  NodeList<ExprPtr> elements;
  explicit ListExpr(SourceLoc l) : Expr(ExprKind::List, l) {}
};

enum class UnaryOp : uint8_t { Neg, Plus, Not };
struct UnaryExpr : Expr {
  UnaryOp op;
  ExprPtr operand;
  UnaryExpr(SourceLoc l, UnaryOp o, ExprPtr e) : Expr(ExprKind::Unary, l), op(o), operand(std::move(e)) {}
};

enum class BinaryOp : uint8_t { Add, Sub, Mul, Div, Mod, Pow, Eq, Ne, Lt, Le, Gt, Ge, And, Or };
struct BinaryExpr : Expr {
  BinaryOp op;
  ExprPtr lhs, rhs;
  SourceLoc op_loc;  // where the operator is, for "wrong type for operator" errors
  BinaryExpr(SourceLoc l, BinaryOp o, ExprPtr a, ExprPtr b, SourceLoc ol)
      : Expr(ExprKind::Binary, l), op(o), lhs(std::move(a)), rhs(std::move(b)), op_loc(ol) {}
};

// a .. b (end excluded), a ..= b (end included), optional `step s`
struct RangeExpr : Expr {
  ExprPtr from, to, step;  // step may be null
  bool inclusive;
  RangeExpr(SourceLoc l, ExprPtr f, ExprPtr t, ExprPtr s, bool inc)
      : Expr(ExprKind::Range, l), from(std::move(f)), to(std::move(t)), step(std::move(s)), inclusive(inc) {}
};

// f(a, b, name = c): positional arguments first, then named ones.
struct Argument {
  Symbol name = nullptr;  // null for a positional argument
  SourceLoc loc;          // beside the name: 16 bytes, not 24
  ExprPtr value;
};
struct CallExpr : Expr {
  ExprPtr callee;  // usually a NameExpr
  NodeList<Argument> args;
  CallExpr(SourceLoc l, ExprPtr c) : Expr(ExprKind::Call, l), callee(std::move(c)) {}
};
// xs[i]
struct IndexExpr : Expr {
  ExprPtr object, index;
  IndexExpr(SourceLoc l, ExprPtr o, ExprPtr i) : Expr(ExprKind::Index, l), object(std::move(o)), index(std::move(i)) {}
};
// v.x
struct MemberExpr : Expr {
  ExprPtr object;
  Symbol member;
  SourceLoc member_loc;
  MemberExpr(SourceLoc l, ExprPtr o, Symbol m, SourceLoc ml)
      : Expr(ExprKind::Member, l), object(std::move(o)), member(m), member_loc(ml) {}
};

// The body of a block: `name = value` properties interleaved with statements (objects,
// macro calls, loops, lets...). Properties and statements keep their source order.
class BlockItem {
 public:
  static BlockItem property_item(Symbol name, ExprPtr value, SourceLoc loc) {
    BlockItem item;
    item.property = name;
    item.node_ = value.get();
    item.loc = loc;
    return item;
  }
  static BlockItem statement_item(StmtPtr stmt, SourceLoc loc) {
    BlockItem item;
    item.node_ = stmt.get();
    item.loc = loc;
    return item;
  }
  // One link, told apart by `property` (16 bytes an item with the 4-byte symbol, not 32).
  ExprPtr value() const { return property ? ExprPtr(static_cast<Expr*>(node_)) : ExprPtr(); }
  StmtPtr stmt() const { return property ? StmtPtr() : StmtPtr(static_cast<Stmt*>(node_)); }

  Symbol property = nullptr;  // `property = value`; null for a statement
  SourceLoc loc;

 private:
  void* node_ = nullptr;
};
struct BlockBody {
  NodeList<BlockItem> items;
  SourceLoc open_loc;  // the '{'
};

// kind { ... }   e.g. sphere { center = <0,1,0> radius = 1 }, material { ... }, group { ... }
struct BlockExpr : Expr {
  Symbol kind_name;
  BlockBody body;
  BlockExpr(SourceLoc l, Symbol k) : Expr(ExprKind::Block, l), kind_name(k) {}
};
// base with { overrides }
struct WithExpr : Expr {
  ExprPtr base;
  BlockBody body;
  WithExpr(SourceLoc l, ExprPtr b) : Expr(ExprKind::With, l), base(std::move(b)) {}
};

enum class TransformOp : uint8_t { Translate, Rotate, Scale, Matrix };
// object translate <1,0,0>   (postfix, lowest precedence, left-associative)
struct TransformExpr : Expr {
  ExprPtr object;
  TransformOp op;
  ExprPtr arg;
  SourceLoc op_loc;
  TransformExpr(SourceLoc l, ExprPtr o, TransformOp t, ExprPtr a, SourceLoc ol)
      : Expr(ExprKind::Transform, l), object(std::move(o)), op(t), arg(std::move(a)), op_loc(ol) {}
};

// ---------------------------------------------------------------------------------------
// Statements
// ---------------------------------------------------------------------------------------
enum class StmtKind : uint8_t {
  Let, Assign, If, For, While, Macro, Return, Break, Continue, Include, ExprStmt,
};

struct Stmt {
  StmtKind kind;
  SourceLoc loc;
  explicit Stmt(StmtKind k, SourceLoc l) : kind(k), loc(l) {}
};

struct Body {
  StmtList stmts;
  SourceLoc open_loc;  // the '{'
};

// let name = value
struct LetStmt : Stmt {
  Symbol name;
  ExprPtr value;
  SourceLoc name_loc;
  LetStmt(SourceLoc l, Symbol n, ExprPtr v, SourceLoc nl)
      : Stmt(StmtKind::Let, l), name(n), value(std::move(v)), name_loc(nl) {}
};

// name = value, name += value, ...
enum class AssignOp : uint8_t { Set, Add, Sub, Mul, Div };
struct AssignStmt : Stmt {
  Symbol name;
  AssignOp op;
  ExprPtr value;
  AssignStmt(SourceLoc l, Symbol n, AssignOp o, ExprPtr v)
      : Stmt(StmtKind::Assign, l), name(n), op(o), value(std::move(v)) {}
};

// if c { } else if c2 { } else { }   — `else if` chains are nested IfStmts in else_body
struct IfStmt : Stmt {
  ExprPtr cond;
  Body then_body;
  const Body* else_body = nullptr;  // in the arena; null when there is no else
  IfStmt(SourceLoc l, ExprPtr c) : Stmt(StmtKind::If, l), cond(std::move(c)) {}
};

// for name in iterable { }
struct ForStmt : Stmt {
  Symbol var;
  SourceLoc var_loc;
  ExprPtr iterable;
  Body body;
  ForStmt(SourceLoc l, Symbol v, SourceLoc vl, ExprPtr it)
      : Stmt(StmtKind::For, l), var(v), var_loc(vl), iterable(std::move(it)) {}
};

struct WhileStmt : Stmt {
  ExprPtr cond;
  Body body;
  WhileStmt(SourceLoc l, ExprPtr c) : Stmt(StmtKind::While, l), cond(std::move(c)) {}
};

struct Param {
  Symbol name;
  SourceLoc loc;
  ExprPtr default_value;  // null when the parameter is required
};
// macro name(a, b = 2) { ... }
struct MacroStmt : Stmt {
  Symbol name;
  NodeList<Param> params;
  Body body;
  MacroStmt(SourceLoc l, Symbol n) : Stmt(StmtKind::Macro, l), name(n) {}
};

struct ReturnStmt : Stmt {
  ExprPtr value;  // null for a bare `return`
  ReturnStmt(SourceLoc l, ExprPtr v) : Stmt(StmtKind::Return, l), value(std::move(v)) {}
};
struct BreakStmt : Stmt {
  explicit BreakStmt(SourceLoc l) : Stmt(StmtKind::Break, l) {}
};
struct ContinueStmt : Stmt {
  explicit ContinueStmt(SourceLoc l) : Stmt(StmtKind::Continue, l) {}
};

// include "file.rts"  (resolved and parsed by the evaluator when executed)
struct IncludeStmt : Stmt {
  std::string_view path;  // in the arena
  IncludeStmt(SourceLoc l, std::string_view p) : Stmt(StmtKind::Include, l), path(p) {}
};

// An expression used as a statement: an object to place, a macro call, ...
struct ExprStmt : Stmt {
  ExprPtr expr;
  ExprStmt(SourceLoc l, ExprPtr e) : Stmt(StmtKind::ExprStmt, l), expr(std::move(e)) {}
};

// A parsed file: its nodes are in its arena, the list of its own statements beside it.
struct Program {
  const SourceFile* file = nullptr;
  std::unique_ptr<NodeArena> arena;
  std::vector<StmtPtr> top_level;  // what `stmts` lists (a vector's buffer survives a move)
  StmtList stmts;
};

// Names for printing and messages.
const char* to_string(UnaryOp op);
const char* to_string(BinaryOp op);
const char* to_string(TransformOp op);
const char* to_string(AssignOp op);

}  // namespace rts::ast

template <>
struct std::hash<rts::ast::Symbol> {
  std::size_t operator()(rts::ast::Symbol s) const noexcept { return std::hash<uint32_t>{}(s.id()); }
};
