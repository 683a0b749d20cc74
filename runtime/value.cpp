#include "runtime/value.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace rts::runtime {

const char* type_name(Type t) {
  switch (t) {
    case Type::None:
      return "none";
    case Type::Number:
      return "number";
    case Type::Bool:
      return "bool";
    case Type::String:
      return "string";
    case Type::Vector:
      return "vector";
    case Type::Color:
      return "color";
    case Type::List:
      return "list";
    case Type::Range:
      return "range";
    case Type::Material:
      return "material";
    case Type::Texture:
      return "texture";
    case Type::Object:
      return "object";
    case Type::Transform:
      return "transform";
    case Type::Macro:
      return "macro";
    case Type::Builtin:
      return "builtin function";
    case Type::Random:
      return "random stream";
  }
  return "value";
}

std::string with_article(Type t) {
  if (t == Type::None) return "none";
  const char* n = type_name(t);
  bool vowel = n[0] == 'a' || n[0] == 'e' || n[0] == 'i' || n[0] == 'o' || n[0] == 'u';
  return fmt::format("{} {}", vowel ? "an" : "a", n);
}

Value Value::string(std::string s) {
  Value r;
  r.type = Type::String;
  r.ref = std::make_shared<StringValue>(std::move(s));
  return r;
}

ListValue::ListValue(std::vector<Value> i) : items(std::move(i)), depth(1) {
  for (const Value& v : items) depth = std::max(depth, nesting_depth(v) + 1);
}

void RecordValue::update_depth() {
  depth = 1;
  for (const Property& p : props) depth = std::max(depth, nesting_depth(p.value) + 1);
}

uint32_t nesting_depth(const Value& v) {
  switch (v.type) {
    case Type::List:
      return static_cast<const ListValue&>(*v.ref).depth;
    case Type::Material:
    case Type::Texture:
      return static_cast<const RecordValue&>(*v.ref).depth;
    default:
      return 0;
  }
}

Value Value::list(std::vector<Value> items) {
  Value r;
  r.type = Type::List;
  r.ref = std::make_shared<ListValue>(std::move(items));
  return r;
}

uint64_t RandomValue::next_u64() {
  // splitmix64 (Steele, Lea, Flood 2014): tiny, fast, and the same everywhere.
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double RandomValue::next_unit() {
  if (povray) {
    // POV-Ray 3.7's generator: a 32-bit linear congruential step (multiplier 1812433253,
    // increment 12345), the state over 2^32 - 1.
    state = static_cast<uint32_t>(static_cast<uint32_t>(state) * 1812433253u + 12345u);
    return static_cast<double>(state) / 4294967295.0;
  }
  constexpr double kTwoToMinus53 = 1.0 / 9007199254740992.0;
  return static_cast<double>(next_u64() >> 11) * kTwoToMinus53;
}

render::Mat4 object_transform(const Value& v) {
  return v.ref ? static_cast<const ObjectValue&>(*v.ref).transform : render::Mat4(1.0);
}

const void* object_identity(const Value& v) {
  // Built objects are their node; a definition not built yet is its defining block.
  if (v.id == render::kNoId && v.ref) return &static_cast<const ObjectValue&>(*v.ref).definition();
  return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(v.id) + 1);
}

namespace {
std::string num_text(double x) {
  if (x == 0.0) x = 0.0;  // no "-0"
  return fmt::format("{}", x);
}
}  // namespace

std::string to_text(const Value& v, bool quote_strings) {
  switch (v.type) {
    case Type::None:
      return "none";
    case Type::Number:
      return num_text(v.num());
    case Type::Bool:
      return v.truth() ? "true" : "false";
    case Type::String:
      return quote_strings ? fmt::format("\"{}\"", as_string(v)) : as_string(v);
    case Type::Vector:
      return fmt::format("<{}, {}, {}>", num_text(v.v.x), num_text(v.v.y), num_text(v.v.z));
    case Type::Color:
      return fmt::format("rgb({}, {}, {})", num_text(v.v.x), num_text(v.v.y), num_text(v.v.z));
    case Type::List: {
      std::string s;
      append_text(s, v, quote_strings, SIZE_MAX);
      return s;
    }
    case Type::Range:
      return fmt::format("{} {} {} step {}", num_text(v.v.x), v.inclusive ? "..=" : "..", num_text(v.v.y),
                         num_text(v.v.z));
    case Type::Material:
      return "<material>";
    case Type::Texture:
      return fmt::format("<texture {}>", *as_record(v).kind);
    case Type::Object:
      if (v.id == render::kNoId && v.ref) {  // a definition not placed (so not built) yet
        const ObjectValue& def = static_cast<const ObjectValue&>(*v.ref).definition();
        if (def.built_id != render::kNoId) return fmt::format("<object {}>", def.built_id);
        if (def.kind) return fmt::format("<object {}>", *def.kind);
      }
      return fmt::format("<object {}>", v.id);
    case Type::Transform:
      return "<transform>";
    case Type::Macro:
      return fmt::format("<macro {}>", *as_macro(v)->name);
    case Type::Builtin:
      return "<builtin>";
    case Type::Random:
      return "<random stream>";
  }
  return "?";
}

bool append_text(std::string& out, const Value& v, bool quote_strings, std::size_t limit) {
  if (v.type != Type::List) {
    out += to_text(v, quote_strings);
    return out.size() <= limit;
  }
  // Lists append in place: no temporary per level, so the cost is the text's size.
  out += '[';
  const auto& items = as_list(v);
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) out += ", ";
    if (!append_text(out, items[i], true, limit)) return false;
  }
  out += ']';
  return out.size() <= limit;
}

bool equal(const Value& a, const Value& b) {
  if (a.type != b.type) return false;
  switch (a.type) {
    case Type::None:
      return true;
    case Type::Number:
    case Type::Bool:
      return a.v.x == b.v.x;
    case Type::Vector:
    case Type::Color:
      return a.v == b.v;
    case Type::Range:
      return a.v == b.v && a.inclusive == b.inclusive;
    case Type::String:
      return as_string(a) == as_string(b);
    case Type::List: {
      const auto& x = as_list(a);
      const auto& y = as_list(b);
      if (x.size() != y.size()) return false;
      for (std::size_t i = 0; i < x.size(); ++i)
        if (!equal(x[i], y[i])) return false;
      return true;
    }
    case Type::Object:
      return object_identity(a) == object_identity(b) && object_transform(a) == object_transform(b);
    case Type::Builtin:
      return a.id == b.id;
    default:
      return a.ref == b.ref;
  }
}

}  // namespace rts::runtime
