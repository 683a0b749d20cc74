// Symbol interning and operator names for the AST.
#include "parser/ast.hpp"

#include <mutex>
#include <string>
#include <unordered_set>

namespace rts::ast {
namespace {

struct StringHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view s) const noexcept { return std::hash<std::string_view>{}(s); }
};

// One table for the life of the program: Symbols are pointers to its strings (nodes of an
// unordered_set never move). Guarded because evaluators may intern from several threads.
struct SymbolTable {
  std::mutex mutex;
  std::unordered_set<std::string, StringHash, std::equal_to<>> names;
};

SymbolTable& table() {
  static SymbolTable* t = new SymbolTable;  // never destroyed: Symbols outlive static teardown
  return *t;
}

}  // namespace

Symbol intern(std::string_view name) {
  SymbolTable& t = table();
  std::lock_guard lock(t.mutex);
  auto it = t.names.find(name);
  if (it == t.names.end()) it = t.names.emplace(name).first;
  return &*it;
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
