// Run-time values of the scene language. A Value is small (48 bytes) and cheap to copy:
// numbers, bools, vectors, colors, ranges and object handles live inline; strings, lists,
// materials, textures, transforms, macros and random streams are shared, immutable heap
// objects (except a random stream's state, which advances in place: it is a stream).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "parser/ast.hpp"
#include "render/scene/scene.hpp"

namespace rts::runtime {

enum class Type : uint8_t {
  None,
  Number,
  Bool,
  String,
  Vector,
  Color,
  List,
  Range,
  Material,
  Texture,
  Object,
  Transform,
  Macro,
  Builtin,
  Random,
};

// "number", "vector", ... for messages; with_article gives "a number", "an object".
const char* type_name(Type t);
std::string with_article(Type t);

struct HeapValue {
  virtual ~HeapValue() = default;
};

struct Value {
  Type type = Type::None;
  bool inclusive = false;          // Range: end included (..=)
  uint32_t id = 0;                 // Object: NodeId; Builtin: index into the builtin table
  glm::dvec3 v{0.0};               // Number/Bool: v.x; Vector/Color: x,y,z; Range: from, to, step
  std::shared_ptr<HeapValue> ref;  // String, List, Material, Texture, Macro, Random; Object: ObjectValue or null

  static Value none() { return {}; }
  Value() = default;
  // Made with each member written once, not zeroed and then partly written again: a value is
  // moved right after it is made, and a 16-byte load of v.x and v.y that spans two stores
  // cannot be forwarded from them (perf: a fifth of call_macro's samples on the instruction
  // after such a load).
  Value(Type t, glm::dvec3 x) : type(t), v(x) {}
  static Value number(double x) { return Value(Type::Number, glm::dvec3(x, 0.0, 0.0)); }
  static Value boolean(bool b) { return Value(Type::Bool, glm::dvec3(b ? 1.0 : 0.0, 0.0, 0.0)); }
  static Value vector(glm::dvec3 x) {
    Value r;
    r.type = Type::Vector;
    r.v = x;
    return r;
  }
  static Value color(glm::dvec3 c) {
    Value r;
    r.type = Type::Color;
    r.v = c;
    return r;
  }
  static Value string(std::string s);
  static Value list(std::vector<Value> items);

  double num() const { return v.x; }
  bool truth() const { return v.x != 0.0; }
  bool is(Type t) const { return type == t; }
};

struct StringValue : HeapValue {
  std::string text;
  explicit StringValue(std::string t) : text(std::move(t)) {}
};

// Lists and records may contain lists and records. Their nesting depth is kept so that it
// can be bounded (kMaxValueNesting): printing, comparing and freeing a value recurse.
inline constexpr uint32_t kMaxValueNesting = 10'000;

struct ListValue : HeapValue {
  std::vector<Value> items;
  uint32_t depth;  // 1 + the deepest item's depth
  explicit ListValue(std::vector<Value> i);
};

// A property of a material or texture record: `name = value`, where it was written.
struct Property {
  ast::Symbol name;
  Value value;
  SourceLoc loc;
};

// A material or texture value: its properties (so `with` can derive new ones), and the
// builder id it became when first used (one value → one MaterialId/TextureId).
struct RecordValue : HeapValue {
  ast::Symbol kind;  // "material", "checker", ...
  std::vector<Property> props;
  render::Mat4 transform{1.0};  // textures: accumulated transform postfixes
  SourceLoc loc;
  uint32_t built_id = render::kNoId;
  uint32_t depth = 1;  // 1 + the deepest property value's depth; see update_depth()
  void update_depth();
};

// An object's heap part: its transform and, for shapes and lights, the block that defined it
// (kind, properties, location), so that `with` can derive a new definition. The object made
// by a block or by `with` holds its block itself; a transformed copy (`s translate t`) points
// to that object instead of copying the properties. Groups have no block (kind is null).
struct ObjectValue : HeapValue {
  render::Mat4 transform{1.0};
  ast::Symbol kind = nullptr;  // "sphere", "point_light", ...; null for a group
  std::vector<Property> props;
  SourceLoc loc;
  std::shared_ptr<const ObjectValue> defined_by;  // a transformed copy: the object holding the block
  // The scene node this definition became (meshes: when first placed; kNoId until then, so an
  // unused `let m = mesh { file = "big.obj" }` never opens the file).
  mutable uint32_t built_id = render::kNoId;
  const ObjectValue& definition() const { return defined_by ? *defined_by : *this; }
};

struct TransformValue : HeapValue {
  render::Mat4 matrix;
  explicit TransformValue(const render::Mat4& m) : matrix(m) {}
};

struct MacroValue : HeapValue {
  const ast::MacroStmt* def;
  explicit MacroValue(const ast::MacroStmt* d) : def(d) {}
};

// A deterministic random stream (splitmix64): the same seed gives the same numbers on
// every platform and run.
struct RandomValue : HeapValue {
  uint64_t state;
  // random(seed, "povray"): POV-Ray 3.7's own sequence (seed(n) then rand), so an imported
  // scene's random placements are POV-Ray's; next_unit() is then in [0, 1].
  bool povray = false;
  explicit RandomValue(uint64_t seed, bool pov = false) : state(seed), povray(pov) {}
  uint64_t next_u64();
  double next_unit();  // uniform in [0, 1), 53 random bits (povray: [0, 1], 32 bits)
};

inline const std::string& as_string(const Value& v) { return static_cast<const StringValue&>(*v.ref).text; }
inline const std::vector<Value>& as_list(const Value& v) { return static_cast<const ListValue&>(*v.ref).items; }
inline RecordValue& as_record(const Value& v) { return static_cast<RecordValue&>(*v.ref); }
inline RandomValue& as_random(const Value& v) { return static_cast<RandomValue&>(*v.ref); }
inline const ast::MacroStmt* as_macro(const Value& v) { return static_cast<const MacroValue&>(*v.ref).def; }
// How deeply lists and records nest inside `v` (0 for anything else).
uint32_t nesting_depth(const Value& v);
// An object's transform (identity when it has none).
render::Mat4 object_transform(const Value& v);
// What `==` compares for objects: the node, or for a definition not built yet its block.
const void* object_identity(const Value& v);
// The object value holding the shape or light block an object was defined by (null for a
// group).
inline const ObjectValue* object_definition(const Value& v) {
  if (!v.ref) return nullptr;
  const ObjectValue& d = static_cast<const ObjectValue&>(*v.ref).definition();
  return d.kind ? &d : nullptr;
}
// A transform value's matrix.
inline const render::Mat4& as_transform(const Value& v) { return static_cast<const TransformValue&>(*v.ref).matrix; }

// Text form used by str(), format() and print(): numbers in shortest form ("3", "0.25"),
// vectors "<1, 2, 3>", colors "rgb(1, 0, 0)", lists "[1, \"a\"]" (strings quoted inside).
std::string to_text(const Value& v, bool quote_strings = false);
// The same text appended to `out`, stopping (false) once `out` holds more than `limit` bytes:
// a list that holds itself many times over (`xs = [xs, xs]` 40 times) has a small value but a
// text of 2^40 elements, so scenes convert through this with their step budget as the limit.
bool append_text(std::string& out, const Value& v, bool quote_strings, std::size_t limit);

// Structural equality (numbers, bools, strings, vectors, colors, lists, ranges); identity
// for heap objects such as materials.
bool equal(const Value& a, const Value& b);

}  // namespace rts::runtime
