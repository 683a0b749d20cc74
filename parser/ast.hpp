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
  friend Symbol intern(std::string_view name, uint32_t hash);
  friend struct SymbolTable;
  static constexpr uint32_t kChunkBits = 12;
  static constexpr uint32_t kChunkSize = 1u << kChunkBits;
  static std::string** chunks();  // the name of id is chunks()[id >> kChunkBits][id & (kChunkSize - 1)]
  const std::string* name() const {
    std::string* chunk = std::atomic_ref<std::string*>(chunks()[id_ >> kChunkBits]).load(std::memory_order_acquire);
    return chunk + (id_ & (kChunkSize - 1));
  }
  uint32_t id_ = 0;  // 0: no symbol
};
Symbol intern(std::string_view name);
// The same, with the name's symbol_hash already computed (the parser's cache has it).
Symbol intern(std::string_view name, uint32_t hash);
uint32_t symbol_hash(std::string_view name);

struct Expr;
struct Stmt;

// A pointer to a node, held outside the nodes: on the parser's stacks, in the evaluator's
// locals, in Program. Nodes do not own each other: their memory is the program's NodeArena's.
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

// A link held inside the arena (in a node or in a node's list) to something built before it
// in the same arena: the distance back from the link to its target, 4 bytes instead of a
// pointer's 8 (issue 24: links were about a third of the arena). The parser builds bottom
// up, so a node's children, lists and strings always come before it, and the arena hands
// out addresses upward from one reserved range of at most 4 GiB: every target is below its
// link and within reach. The distance is only meaningful where the link lies, so a link is
// never copied: it is read (`get()`, `->`, converted to a NodePtr) or set to a target.
// Distance 0 is "no target" (nothing links to itself).
class RawLink {
 public:
  RawLink() = default;
  RawLink(const RawLink&) = delete;
  RawLink& operator=(const RawLink&) = delete;

  const void* raw() const { return back_ == 0 ? nullptr : target(); }
  // Where the link points, for a link known to be set (or an empty list's start: the link
  // itself). No test for "no target": reading through the tree costs one subtraction.
  const void* target() const { return reinterpret_cast<const void*>(reinterpret_cast<std::uintptr_t>(this) - back_); }
  void reset(const void* target) {
    if (target == nullptr) {
      back_ = 0;
      return;
    }
    const auto self = reinterpret_cast<std::uintptr_t>(this);
    const auto at = reinterpret_cast<std::uintptr_t>(target);
    if (at >= self || self - at > UINT32_MAX) unreachable(target);
    back_ = static_cast<uint32_t>(self - at);
  }

 private:
  [[noreturn]] void unreachable(const void* target) const;  // a builder bug: throws logic_error
  uint32_t back_ = 0;
};

template <class T>
class Link : public RawLink {
 public:
  Link() = default;
  Link(std::nullptr_t) {}
  template <class U, class = std::enable_if_t<std::is_convertible_v<U*, T*>>>
  Link(NodePtr<U> target) {
    reset(static_cast<T*>(target.get()));
  }
  template <class U, class = std::enable_if_t<std::is_convertible_v<U*, T*>>>
  Link& operator=(NodePtr<U> target) {
    reset(static_cast<T*>(target.get()));
    return *this;
  }

  T* get() const { return static_cast<T*>(const_cast<void*>(raw())); }
  T& operator*() const { return *static_cast<T*>(const_cast<void*>(target())); }
  T* operator->() const { return static_cast<T*>(const_cast<void*>(target())); }
  explicit operator bool() const { return raw() != nullptr; }
  operator NodePtr<T>() const { return NodePtr<T>(get()); }
  friend bool operator==(const Link& a, std::nullptr_t) { return a.raw() == nullptr; }
  friend bool operator!=(const Link& a, std::nullptr_t) { return a.raw() != nullptr; }
};
using ExprLink = Link<Expr>;
using StmtLink = Link<Stmt>;

// A run of elements just built in the arena, before a node takes it (NodeList).
template <class T>
struct ListPiece {
  T* first = nullptr;
  uint32_t count = 0;
};

// A node's children, in order: a run of elements in the arena, linked from the node
// (read-only once built; 8 bytes).
template <class T>
class NodeList {
 public:
  NodeList() = default;
  explicit NodeList(ListPiece<T> piece) { *this = piece; }
  NodeList& operator=(ListPiece<T> piece) {
    first_.reset(piece.first);
    count_ = piece.count;
    return *this;
  }

  const T* begin() const { return static_cast<const T*>(first_.target()); }  // empty: [link, link)
  const T* end() const { return begin() + count_; }
  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const T& operator[](std::size_t i) const { return begin()[i]; }
  const T& at(std::size_t i) const {
    if (i >= count_) throw std::out_of_range("NodeList::at");
    return begin()[i];
  }
  const T& front() const { return begin()[0]; }
  const T& back() const { return begin()[count_ - 1]; }

 private:
  RawLink first_;
  uint32_t count_ = 0;
};
using StmtList = NodeList<StmtLink>;

// Where a program's nodes live: one range of address space reserved for the program (so
// that links can be 4-byte distances, above), its pages committed as the parse reaches
// them, handed out in order and never freed one by one. Profile finding (issue 24, heaptrack
// of `rts parse` on a generated scene): a statement of ~70 bytes had become about 14 heap
// blocks, each with the allocator's header and rounding; nodes, their lists and their
// strings now all come from here, and nothing in the arena has a destructor. The range is
// sized from the text to parse (kReservePerTextByte, at most kMaxReserve, less if the
// address space is limited); a tree that outgrows it is an error. Whoever holds the nodes
// must hold the arena as long (Program, ParseState).
// Thrown when a tree outgrows its arena's range (the parser reports it where it stopped).
struct ArenaFull : std::length_error {
  using std::length_error::length_error;
};

// Address space this process may still map under `ulimit -v` (RLIMIT_AS), or SIZE_MAX when
// there is no such limit: a reserved range counts against it even untouched (NodeArena, and
// the evaluation thread's stack, runtime/evaluator.cpp, size themselves by it).
std::size_t address_space_left();

class NodeArena {
 public:
  explicit NodeArena(std::size_t text_size = 0);
  ~NodeArena();
  NodeArena(const NodeArena&) = delete;
  NodeArena& operator=(const NodeArena&) = delete;

  template <class T, class... Args>
  NodePtr<T> make(Args&&... args) {
    static_assert(std::is_trivially_destructible_v<T>, "an AST node has nothing to destroy");
    static_assert(alignof(T) <= alignof(std::max_align_t), "an AST node needs no over-alignment");
    void* at = allocate(sizeof(T), alignof(T));
    return NodePtr<T>(new (at) T(std::forward<Args>(args)...));
  }
  // A node with `tail` more bytes just after it (NumberExpr's wide form).
  template <class T, class... Args>
  NodePtr<T> make_with_tail(std::size_t tail, Args&&... args) {
    static_assert(std::is_trivially_destructible_v<T>, "an AST node has nothing to destroy");
    void* at = allocate(sizeof(T) + tail, alignof(T));
    return NodePtr<T>(new (at) T(std::forward<Args>(args)...));
  }
  // The elements T(get(x)) for each x in [first, last), one after another in the arena.
  template <class T, class It, class Get>
  ListPiece<T> list(It first, It last, Get get) {
    static_assert(std::is_trivially_destructible_v<T>, "a node's list has nothing to destroy");
    const auto count = static_cast<std::size_t>(last - first);
    if (count == 0) return {};
    T* at = static_cast<T*>(allocate(count * sizeof(T), alignof(T)));
    for (std::size_t k = 0; first != last; ++first, ++k) new (at + k) T(get(*first));
    return {at, static_cast<uint32_t>(count)};
  }
  // A copy of `text` in the arena (a view that lives as long as the arena).
  std::string_view text(std::string_view text) {
    if (text.empty()) return {};
    void* at = allocate(text.size(), 1);
    std::memcpy(at, text.data(), text.size());
    return {static_cast<const char*>(at), text.size()};
  }
  // Gives back the part of the range not committed: the arena takes nothing more (the parse
  // has ended). Under `ulimit -v` a reserved range counts even untouched.
  void release_unused();
  // Bytes of the range in use (committed pages), and the range's size.
  std::size_t committed() const { return committed_; }
  std::size_t reserved() const { return reserved_; }

  // Address space reserved per byte of text (the densest text, `a+a+a...`, needs about
  // 22 bytes of nodes per byte; typical scenes 3-5), at least kMinReserve, at most
  // kMaxReserve (the reach of a link).
  static constexpr std::size_t kReservePerTextByte = 32;
  static constexpr std::size_t kMinReserve = std::size_t{64} << 20;
  static constexpr std::size_t kMaxReserve = std::size_t{4} << 30;

 private:
  void* allocate(std::size_t size, std::size_t align) {
    std::size_t at = (used_ + align - 1) & ~(align - 1);
    if (at + size > committed_) commit(at + size);
    used_ = at + size;
    return base_ + at;
  }
  void commit(std::size_t end);  // more pages, or throws when the range is spent
  std::byte* base_ = nullptr;
  std::size_t reserved_ = 0;
  std::size_t committed_ = 0;
  std::size_t used_ = 0;
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
  uint8_t aux = 0;     // header bytes a node kind may use (NumberExpr)
  uint16_t aux16 = 0;
  SourceLoc loc;
  explicit Expr(ExprKind k, SourceLoc l) : kind(k), loc(l) {}
};

// The place of a binary or transform node's operator: `aux16` bytes after the node's own
// place, or, when it is kFarOperator or more bytes away, a SourceLoc just after the node.
inline constexpr uint16_t kFarOperator = 0xFFFF;
inline SourceLoc operator_place(const Expr& e, std::size_t node_size) {
  if (e.aux16 != kFarOperator) return e.loc.advanced(e.aux16);
  SourceLoc at;
  std::memcpy(&at, reinterpret_cast<const std::byte*>(&e) + node_size, sizeof at);
  return at;
}
// Makes a node T whose operator is at `op_loc`, keeping that place for operator_place.
template <class T, class... Args>
NodePtr<T> make_with_operator(NodeArena& arena, SourceLoc op_loc, SourceLoc loc, Args&&... args) {
  const int64_t distance = loc.bytes_to(op_loc);
  if (distance >= 0 && distance < kFarOperator) {
    NodePtr<T> n = arena.make<T>(loc, std::forward<Args>(args)...);
    n->aux16 = static_cast<uint16_t>(distance);
    return n;
  }
  NodePtr<T> n = arena.make_with_tail<T>(sizeof(SourceLoc), loc, std::forward<Args>(args)...);
  n->aux16 = kFarOperator;
  std::memcpy(reinterpret_cast<std::byte*>(n.get()) + sizeof(T), &op_loc, sizeof op_loc);
  return n;
}

// A number literal (issue 24: numbers were a third of a scene's nodes). Most literals are
// short decimals: kept as an integer and a power of ten, they give back exactly the double
// their text gives (both factors are exact doubles and one multiplication or division rounds
// once: Clinger's fast path, as fast_float takes it). Up to four digits (|m| < 2^15, `0.499`,
// `-38.2`) the integer is in the header and the literal is 8 bytes ("tiny"); up to nine it
// follows the node in 4 more bytes; any other value is kept whole in 8 more ("wide").
// `aux` says which, with the power. Made by make_number and make_short_number.
struct NumberExpr : Expr {
  static constexpr int kMaxExponent = 22;  // 10^22 is the largest exact power of ten
  static constexpr uint8_t kTiny = 0;      // aux - kTiny - kMaxExponent is the power
  static constexpr uint8_t kShort = 64;    // aux - kShort - kMaxExponent is the power
  static constexpr uint8_t kNegativeZero = 0xFE;
  static constexpr uint8_t kWide = 0xFF;
  static constexpr double kPow10[kMaxExponent + 1] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                     1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                                     1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

  double value() const {
    if (aux <= kTiny + 2 * kMaxExponent) return scaled(static_cast<int16_t>(aux16), aux - kTiny);
    if (aux <= kShort + 2 * kMaxExponent) return scaled(tail<int32_t>(), aux - kShort);
    if (aux == kNegativeZero) return -0.0;
    return tail<double>();
  }
  bool wide() const { return aux == kWide; }
  bool tiny() const { return aux <= kTiny + 2 * kMaxExponent || aux == kNegativeZero; }
  void negate();  // in place: the parser folds `-literal`

  NumberExpr(SourceLoc l, uint8_t code, uint16_t tiny_mantissa = 0) : Expr(ExprKind::Number, l) {
    aux = code;
    aux16 = tiny_mantissa;
  }

  template <class T>
  T tail() const {
    T v;
    std::memcpy(&v, reinterpret_cast<const std::byte*>(this) + sizeof(NumberExpr), sizeof v);
    return v;
  }
  template <class T>
  void set_tail(T v) {
    std::memcpy(reinterpret_cast<std::byte*>(this) + sizeof(NumberExpr), &v, sizeof v);
  }

 private:
  // m·10^(biased_exponent - kMaxExponent)
  static double scaled(double m, int biased_exponent) {
    return biased_exponent >= kMaxExponent ? m * kPow10[biased_exponent - kMaxExponent]
                                           : m / kPow10[kMaxExponent - biased_exponent];
  }
};
// A number literal with the value `value` (short when it is a small integer).
NodePtr<NumberExpr> make_number(NodeArena& arena, SourceLoc loc, double value);
// The literal a decimal spelling (the grammar's: digits, fraction, exponent) gives, when its
// short form exists (at most 9 significant digits, a power of ten within 10^±22); null
// otherwise. Its value is then exact without a decimal-to-binary conversion.
NodePtr<NumberExpr> make_short_number(NodeArena& arena, SourceLoc loc, std::string_view spelling);
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
// the literals lie one after another in the arena at one stride (they were parsed one after
// another, all of one size), the literals themselves, with no list of links (issue 24:
// `<1, -2, 3>` is most of a generated scene's vectors). Reads as a list of ExprPtr either way.
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
  ComponentList& operator=(ListPiece<ExprLink> links) {
    first_.reset(links.first);
    count_ = links.count;
    stride_ = 0;
    return *this;
  }
  // `count` number literals `stride` bytes apart from `first` (8, 12 or 16: NumberExpr's
  // forms; the last may be longer than the stride).
  void set_literals(const NumberExpr* first, uint32_t count, uint32_t stride) {
    first_.reset(first);
    count_ = count;
    stride_ = stride / 4;
  }

  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  bool literals() const { return stride_ != 0; }
  ExprPtr operator[](std::size_t i) const;
  iterator begin() const { return {this, 0}; }
  iterator end() const { return {this, count_}; }

 private:
  RawLink first_;
  uint32_t count_ : 29 = 0;
  uint32_t stride_ : 3 = 0;  // in 4-byte units; 0: a list of links
};

// <x, y, z> (the grammar allows 2 to 4 components; the evaluator decides what it accepts)
struct VectorExpr : Expr {
  ComponentList components;
  explicit VectorExpr(SourceLoc l) : Expr(ExprKind::Vector, l) {}
};

inline ExprPtr ComponentList::operator[](std::size_t i) const {
  if (stride_ != 0) {
    const auto* at = static_cast<const std::byte*>(first_.target()) + i * (stride_ * std::size_t{4});
    return ExprPtr(const_cast<NumberExpr*>(reinterpret_cast<const NumberExpr*>(at)));
  }
  return static_cast<const ExprLink*>(first_.target())[i];
}
// [a, b, c]
struct ListExpr : Expr {
  NodeList<ExprLink> elements;
  explicit ListExpr(SourceLoc l) : Expr(ExprKind::List, l) {}
};

enum class UnaryOp : uint8_t { Neg, Plus, Not };
// The operator is in the header's spare byte and `loc` is where it is: 12 bytes.
struct UnaryExpr : Expr {
  UnaryOp op() const { return static_cast<UnaryOp>(aux); }
  ExprLink operand;
  UnaryExpr(SourceLoc l, UnaryOp o, ExprPtr e) : Expr(ExprKind::Unary, l), operand(e) {
    aux = static_cast<uint8_t>(o);
  }
};

enum class BinaryOp : uint8_t { Add, Sub, Mul, Div, Mod, Pow, Eq, Ne, Lt, Le, Gt, Ge, And, Or };
// The operator in the header, and where it is (for "wrong type for operator" errors) as a
// distance from `loc` (operator_place): 16 bytes. Made by make_with_operator.
struct BinaryExpr : Expr {
  BinaryOp op() const { return static_cast<BinaryOp>(aux); }
  SourceLoc op_loc() const { return operator_place(*this, sizeof(BinaryExpr)); }
  ExprLink lhs, rhs;
  BinaryExpr(SourceLoc l, BinaryOp o, ExprPtr a, ExprPtr b) : Expr(ExprKind::Binary, l), lhs(a), rhs(b) {
    aux = static_cast<uint8_t>(o);
  }
};

// a .. b (end excluded), a ..= b (end included), optional `step s`
struct RangeExpr : Expr {
  ExprLink from, to, step;  // step may be null
  bool inclusive;
  RangeExpr(SourceLoc l, ExprPtr f, ExprPtr t, ExprPtr s, bool inc)
      : Expr(ExprKind::Range, l), from(f), to(t), step(s), inclusive(inc) {}
};

// f(a, b, name = c): positional arguments first, then named ones.
struct ArgumentPiece {   // on the parser's stack
  Symbol name = nullptr;  // null for a positional argument
  SourceLoc loc;
  ExprPtr value;
};
struct Argument {
  explicit Argument(const ArgumentPiece& p) : name(p.name), loc(p.loc), value(p.value) {}
  Symbol name = nullptr;  // null for a positional argument
  SourceLoc loc;
  ExprLink value;
};
struct CallExpr : Expr {
  ExprLink callee;  // usually a NameExpr
  NodeList<Argument> args;
  CallExpr(SourceLoc l, ExprPtr c) : Expr(ExprKind::Call, l), callee(c) {}
};
// xs[i]
struct IndexExpr : Expr {
  ExprLink object, index;
  IndexExpr(SourceLoc l, ExprPtr o, ExprPtr i) : Expr(ExprKind::Index, l), object(o), index(i) {}
};
// v.x
struct MemberExpr : Expr {
  ExprLink object;
  Symbol member;
  SourceLoc member_loc;
  MemberExpr(SourceLoc l, ExprPtr o, Symbol m, SourceLoc ml)
      : Expr(ExprKind::Member, l), object(o), member(m), member_loc(ml) {}
};

// The body of a block: `name = value` properties interleaved with statements (objects,
// macro calls, loops, lets...). Properties and statements keep their source order.
struct BlockItemPiece {  // on the parser's stack
  Symbol property = nullptr;
  SourceLoc loc;
  void* node = nullptr;  // the value (a property) or the statement
};
class BlockItem {
 public:
  static BlockItemPiece property_item(Symbol name, ExprPtr value, SourceLoc loc) {
    return {name, loc, value.get()};
  }
  static BlockItemPiece statement_item(StmtPtr stmt, SourceLoc loc) { return {nullptr, loc, stmt.get()}; }
  explicit BlockItem(const BlockItemPiece& p) : property(p.property), loc(p.loc) { node_.reset(p.node); }

  // One link, told apart by `property` (12 bytes an item).
  ExprPtr value() const { return property ? ExprPtr(static_cast<Expr*>(const_cast<void*>(node_.target()))) : ExprPtr(); }
  StmtPtr stmt() const { return property ? StmtPtr() : StmtPtr(static_cast<Stmt*>(const_cast<void*>(node_.target()))); }

  Symbol property = nullptr;  // `property = value`; null for a statement
  SourceLoc loc;

 private:
  RawLink node_;
};
struct BlockBodyPiece {  // on the parser's stack
  ListPiece<BlockItem> items;
  SourceLoc open_loc;
};
struct BlockBody {
  BlockBody() = default;
  BlockBody& operator=(const BlockBodyPiece& p) {
    items = p.items;
    open_loc = p.open_loc;
    return *this;
  }
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
  ExprLink base;
  BlockBody body;
  WithExpr(SourceLoc l, ExprPtr b) : Expr(ExprKind::With, l), base(b) {}
};

enum class TransformOp : uint8_t { Translate, Rotate, Scale, Matrix };
// object translate <1,0,0>   (postfix, lowest precedence, left-associative)
// As BinaryExpr: the operator and its place in the header, 16 bytes.
struct TransformExpr : Expr {
  TransformOp op() const { return static_cast<TransformOp>(aux); }
  SourceLoc op_loc() const { return operator_place(*this, sizeof(TransformExpr)); }
  ExprLink object;
  ExprLink arg;
  TransformExpr(SourceLoc l, ExprPtr o, TransformOp t, ExprPtr a) : Expr(ExprKind::Transform, l), object(o), arg(a) {
    aux = static_cast<uint8_t>(t);
  }
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

struct BodyPiece {  // on the parser's stack
  ListPiece<StmtLink> stmts;
  SourceLoc open_loc;
};
struct Body {
  Body() = default;
  explicit Body(const BodyPiece& p) { *this = p; }
  Body& operator=(const BodyPiece& p) {
    stmts = p.stmts;
    open_loc = p.open_loc;
    return *this;
  }
  StmtList stmts;
  SourceLoc open_loc;  // the '{'
};

// let name = value
struct LetStmt : Stmt {
  Symbol name;
  ExprLink value;
  SourceLoc name_loc;
  LetStmt(SourceLoc l, Symbol n, ExprPtr v, SourceLoc nl)
      : Stmt(StmtKind::Let, l), name(n), value(v), name_loc(nl) {}
};

// name = value, name += value, ...
enum class AssignOp : uint8_t { Set, Add, Sub, Mul, Div };
struct AssignStmt : Stmt {
  Symbol name;
  AssignOp op;
  ExprLink value;
  AssignStmt(SourceLoc l, Symbol n, AssignOp o, ExprPtr v)
      : Stmt(StmtKind::Assign, l), name(n), op(o), value(v) {}
};

// if c { } else if c2 { } else { }   — `else if` chains are nested IfStmts in else_body
struct IfStmt : Stmt {
  ExprLink cond;
  Body then_body;
  Link<Body> else_body;  // null when there is no else
  IfStmt(SourceLoc l, ExprPtr c) : Stmt(StmtKind::If, l), cond(c) {}
};

// for name in iterable { }
struct ForStmt : Stmt {
  Symbol var;
  SourceLoc var_loc;
  ExprLink iterable;
  Body body;
  ForStmt(SourceLoc l, Symbol v, SourceLoc vl, ExprPtr it)
      : Stmt(StmtKind::For, l), var(v), var_loc(vl), iterable(it) {}
};

struct WhileStmt : Stmt {
  ExprLink cond;
  Body body;
  WhileStmt(SourceLoc l, ExprPtr c) : Stmt(StmtKind::While, l), cond(c) {}
};

struct ParamPiece {  // on the parser's stack
  Symbol name;
  SourceLoc loc;
  ExprPtr default_value;
};
struct Param {
  explicit Param(const ParamPiece& p) : name(p.name), loc(p.loc), default_value(p.default_value) {}
  Symbol name;
  SourceLoc loc;
  ExprLink default_value;  // null when the parameter is required
};
// macro name(a, b = 2) { ... }
struct MacroStmt : Stmt {
  Symbol name;
  NodeList<Param> params;
  Body body;
  MacroStmt(SourceLoc l, Symbol n) : Stmt(StmtKind::Macro, l), name(n) {}
};

struct ReturnStmt : Stmt {
  ExprLink value;  // null for a bare `return`
  ReturnStmt(SourceLoc l, ExprPtr v) : Stmt(StmtKind::Return, l), value(v) {}
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
  ExprLink expr;
  ExprStmt(SourceLoc l, ExprPtr e) : Stmt(StmtKind::ExprStmt, l), expr(e) {}
};

// A parsed file: its nodes are in its arena, the list of its own statements too.
struct Program {
  const SourceFile* file = nullptr;
  std::unique_ptr<NodeArena> arena;
  const StmtList* top_level = nullptr;  // in the arena; null for an empty program
  const StmtList& stmts() const {
    static const StmtList kNone;
    return top_level ? *top_level : kNone;
  }
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
