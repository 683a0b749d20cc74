// Symbol interning and operator names for the AST.
#include "parser/ast.hpp"

#include <atomic>
#include <cstdlib>
#include <mutex>
#include <new>
#include <string>
#include <unordered_map>

namespace rts::ast {
namespace {

struct StringHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
};

// One table for the life of the program: the strings (nodes of an unordered_map never move)
// and, by number, where each is. The numbered chunks are published with release stores, so
// readers (Symbol::name) need no lock; interning is guarded because evaluators may intern
// from several threads. The first-level array is calloc'd: its untouched pages cost nothing.
struct SymbolTable {
  static constexpr std::size_t kChunks = std::size_t{1} << (32 - 12);
  std::mutex mutex;
  std::unordered_map<std::string, uint32_t, StringHash, std::equal_to<>> ids;
  const std::string*** chunks = static_cast<const std::string***>(std::calloc(kChunks, sizeof(const std::string**)));
  uint32_t next = 1;  // 0 is "no symbol"
};

SymbolTable& table() {
  static SymbolTable* t = new SymbolTable;  // never destroyed: Symbols outlive static teardown
  return *t;
}

}  // namespace

const std::string*** Symbol::chunks() {
  static const std::string*** const c = table().chunks;
  return c;
}

Symbol intern(std::string_view name) {
  SymbolTable& t = table();
  std::lock_guard lock(t.mutex);
  Symbol s;
  if (auto it = t.ids.find(name); it != t.ids.end()) {
    s.id_ = it->second;
    return s;
  }
  if (t.next == 0 || !t.chunks) throw std::bad_alloc();  // 2^32 - 1 names
  const uint32_t id = t.next++;
  auto [it, inserted] = t.ids.emplace(std::string(name), id);
  const std::string**& chunk = t.chunks[id >> Symbol::kChunkBits];
  if (!chunk) {
    auto* fresh = static_cast<const std::string**>(std::calloc(Symbol::kChunkSize, sizeof(const std::string*)));
    if (!fresh) throw std::bad_alloc();
    fresh[id & (Symbol::kChunkSize - 1)] = &it->first;
    std::atomic_ref<const std::string**>(chunk).store(fresh, std::memory_order_release);
  } else {
    // A reader reaches this slot only through a Symbol made after this store (under the lock,
    // released by it), so a plain store suffices.
    chunk[id & (Symbol::kChunkSize - 1)] = &it->first;
  }
  s.id_ = id;
  return s;
}

const char* to_string(UnaryOp op) {
  switch (op) {
    case UnaryOp::Neg: return "-";
    case UnaryOp::Plus: return "+";
    case UnaryOp::Not: return "not";
  }
  return "?";
}

const char* to_string(BinaryOp op) {
  switch (op) {
    case BinaryOp::Add: return "+";
    case BinaryOp::Sub: return "-";
    case BinaryOp::Mul: return "*";
    case BinaryOp::Div: return "/";
    case BinaryOp::Mod: return "%";
    case BinaryOp::Pow: return "^";
    case BinaryOp::Eq: return "==";
    case BinaryOp::Ne: return "!=";
    case BinaryOp::Lt: return "<";
    case BinaryOp::Le: return "<=";
    case BinaryOp::Gt: return ">";
    case BinaryOp::Ge: return ">=";
    case BinaryOp::And: return "and";
    case BinaryOp::Or: return "or";
  }
  return "?";
}

const char* to_string(TransformOp op) {
  switch (op) {
    case TransformOp::Translate: return "translate";
    case TransformOp::Rotate: return "rotate";
    case TransformOp::Scale: return "scale";
    case TransformOp::Matrix: return "matrix";
  }
  return "?";
}

const char* to_string(AssignOp op) {
  switch (op) {
    case AssignOp::Set: return "=";
    case AssignOp::Add: return "+=";
    case AssignOp::Sub: return "-=";
    case AssignOp::Mul: return "*=";
    case AssignOp::Div: return "/=";
  }
  return "?";
}

}  // namespace rts::ast
