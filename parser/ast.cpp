// Symbol interning, number literals and operator names for the AST.
#include "parser/ast.hpp"

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <new>
#include <string>
#include <vector>

#include <sys/mman.h>

#if defined(__SANITIZE_ADDRESS__)
#define RTS_LEAK_CHECKED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
#define RTS_LEAK_CHECKED 1
#endif
#endif
#if RTS_LEAK_CHECKED
#include <sanitizer/lsan_interface.h>
#endif

namespace rts::ast {

namespace {

// An array of null pointers that costs only the pages touched: mapped by itself, since calloc
// from a heap that keeps large blocks (runtime/evaluator.cpp's M_MMAP_THRESHOLD) zeroes all 8 MB
// (profile finding: memset 1.7% of the instructions of bench/leave_out_a.rts, a small scene).
std::string** zeroed_pointers(std::size_t count) {
  void* p = ::mmap(nullptr, count * sizeof(std::string*), PROT_READ | PROT_WRITE,
                   MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
  if (p == MAP_FAILED) {
    p = std::calloc(count, sizeof(std::string*));
  } else {
#if RTS_LEAK_CHECKED
    // LeakSanitizer scans heap blocks and globals, not pages mapped by hand: the name chunks
    // this array points to would read as leaked.
    __lsan_register_root_region(p, count * sizeof(std::string*));
#endif
  }
  if (!p) throw std::bad_alloc();
  return static_cast<std::string**>(p);
}

}  // namespace

// One table for the life of the program. Profile finding (issue 24: a 50 MB scene naming
// 1.5M variables parsed at 34 MB/s, 9x the file): an unordered_map of std::string keys plus
// each parse's own unordered_map cost about 136 bytes and two cache-missing lookups per
// distinct name. Now the names are std::strings stored by number in chunks (a name's number
// finds it without a lock: the chunks are published with release stores), and one
// open-addressing index of (hash, number) pairs finds a number by its name, under the lock
// (evaluators may intern from several threads): 48 bytes per distinct name.
struct SymbolTable {
  static constexpr std::size_t kChunks = std::size_t{1} << (32 - 12);
  std::mutex mutex;
  // chunks[id >> 12] is an array of Symbol::kChunkSize names, in zero pages of their own:
  // untouched pages cost nothing.
  std::string** chunks = zeroed_pointers(kChunks);
  uint32_t next = 1;  // 0 is "no symbol"
  // Slots of (32 bits of the hash) << 32 | number; 0 is empty. At most half full.
  std::vector<uint64_t> index = std::vector<uint64_t>(1024, 0);
  std::size_t used = 0;

  const std::string& name(uint32_t id) const { return chunks[id >> Symbol::kChunkBits][id & (Symbol::kChunkSize - 1)]; }

  void grow() {
    std::vector<uint64_t> bigger(index.size() * 2, 0);
    const std::size_t mask = bigger.size() - 1;
    for (uint64_t slot : index) {
      if (slot == 0) continue;
      std::size_t at = static_cast<std::size_t>(slot >> 32) & mask;
      while (bigger[at] != 0) at = (at + 1) & mask;
      bigger[at] = slot;
    }
    index.swap(bigger);
  }
};

namespace {

SymbolTable& table() {
  static SymbolTable* t = new SymbolTable;  // never destroyed: Symbols outlive static teardown
  return *t;
}

}  // namespace

std::string** Symbol::chunks() {
  static std::string** const c = table().chunks;
  return c;
}

uint32_t symbol_hash(std::string_view name) {
  // FNV-1a, 64-bit, folded: names are short, and the parser's cache hashes each occurrence.
  uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : name) h = (h ^ c) * 0x100000001b3ull;
  return static_cast<uint32_t>(h ^ (h >> 32)) | 1u;  // never 0: a slot's hash half is never empty
}

Symbol intern(std::string_view name) { return intern(name, symbol_hash(name)); }

Symbol intern(std::string_view name, uint32_t hash) {
  SymbolTable& t = table();
  std::lock_guard lock(t.mutex);
  const std::size_t mask = t.index.size() - 1;
  std::size_t at = hash & mask;
  for (; t.index[at] != 0; at = (at + 1) & mask) {
    const uint64_t slot = t.index[at];
    if (static_cast<uint32_t>(slot >> 32) == hash) {
      const auto id = static_cast<uint32_t>(slot);
      if (t.name(id) == name) {
        Symbol s;
        s.id_ = id;
        return s;
      }
    }
  }
  if (t.next == 0 || !t.chunks) throw std::bad_alloc();  // 2^32 - 1 names
  const uint32_t id = t.next++;
  std::string*& chunk = t.chunks[id >> Symbol::kChunkBits];
  if (!chunk) {
    auto* fresh = new std::string[Symbol::kChunkSize];
    fresh[id & (Symbol::kChunkSize - 1)] = std::string(name);
    std::atomic_ref<std::string*>(chunk).store(fresh, std::memory_order_release);
  } else {
    // A reader reaches this slot only through a Symbol made after this store (under the lock,
    // released by it), so a plain store suffices.
    chunk[id & (Symbol::kChunkSize - 1)] = std::string(name);
  }
  t.index[at] = (uint64_t{hash} << 32) | id;
  if (++t.used * 2 > t.index.size()) t.grow();
  Symbol s;
  s.id_ = id;
  return s;
}

namespace {

// The short form of a decimal spelling (digits, an optional fraction, an optional exponent):
// its significant digits as an integer and the power of ten; false when they do not fit.
bool short_decimal(std::string_view text, int32_t& mantissa, int& exponent) {
  constexpr int kMaxDigits = 9;  // any 9 digits fit an int32_t
  uint32_t digits = 0;
  int significant = 0;    // digits kept (leading zeros are not)
  int pending_zeros = 0;  // zeros after the last nonzero digit: kept only if one follows
  int fraction_digits = 0;
  bool fraction = false;
  std::size_t i = 0;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '.') {
      fraction = true;
      continue;
    }
    if (c < '0' || c > '9') break;
    if (fraction) ++fraction_digits;
    if (c == '0') {
      if (significant > 0) ++pending_zeros;
      continue;
    }
    for (; pending_zeros > 0; --pending_zeros) {
      digits *= 10;
      if (++significant > kMaxDigits) return false;
    }
    digits = digits * 10 + static_cast<uint32_t>(c - '0');
    if (++significant > kMaxDigits) return false;
  }
  int written_exponent = 0;
  if (i < text.size()) {  // [eE][+-]?digits (the grammar's)
    int sign = 1;
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) sign = text[i++] == '-' ? -1 : 1;
    for (; i < text.size(); ++i) {
      written_exponent = written_exponent * 10 + (text[i] - '0');
      if (written_exponent > 1000) return false;
    }
    written_exponent *= sign;
  }
  // Dropped trailing zeros each raise the power by one.
  const int scale = significant == 0 ? 0 : written_exponent - fraction_digits + pending_zeros;
  if (scale < -NumberExpr::kMaxExponent || scale > NumberExpr::kMaxExponent) return false;
  mantissa = static_cast<int32_t>(digits);
  exponent = scale;
  return true;
}

constexpr int32_t kTinyLimit = 1 << 15;  // |m| < 2^15 fits the header's 16 bits

NodePtr<NumberExpr> make_decimal(NodeArena& arena, SourceLoc loc, int32_t mantissa, int exponent) {
  const int biased = exponent + NumberExpr::kMaxExponent;
  if (mantissa > -kTinyLimit && mantissa < kTinyLimit)
    return arena.make<NumberExpr>(loc, static_cast<uint8_t>(NumberExpr::kTiny + biased),
                                  static_cast<uint16_t>(static_cast<int16_t>(mantissa)));
  auto n = arena.make_with_tail<NumberExpr>(sizeof(int32_t), loc, static_cast<uint8_t>(NumberExpr::kShort + biased));
  n->set_tail(mantissa);
  return n;
}

}  // namespace

NodePtr<NumberExpr> make_number(NodeArena& arena, SourceLoc loc, double value) {
  if (value == 0 && std::signbit(value)) return arena.make<NumberExpr>(loc, NumberExpr::kNegativeZero);
  if (std::fabs(value) < 2147483648.0 && value == std::trunc(value))
    return make_decimal(arena, loc, static_cast<int32_t>(value), 0);
  auto n = arena.make_with_tail<NumberExpr>(sizeof(double), loc, NumberExpr::kWide);
  n->set_tail(value);
  return n;
}

NodePtr<NumberExpr> make_short_number(NodeArena& arena, SourceLoc loc, std::string_view spelling) {
  int32_t mantissa = 0;
  int exponent = 0;
  if (!short_decimal(spelling, mantissa, exponent)) return nullptr;
  return make_decimal(arena, loc, mantissa, exponent);
}

void NumberExpr::negate() {
  if (aux <= kTiny + 2 * kMaxExponent) {
    if (aux16 != 0) aux16 = static_cast<uint16_t>(-static_cast<int16_t>(aux16));
    else aux = kNegativeZero;
  } else if (aux <= kShort + 2 * kMaxExponent) {
    set_tail(-tail<int32_t>());
  } else if (aux == kNegativeZero) {
    aux = kTiny + kMaxExponent;  // +0
  } else {
    set_tail(-tail<double>());
  }
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
