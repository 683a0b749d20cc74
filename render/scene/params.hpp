// Parameters of a scene block, as the runtime hands them to SceneBuilder (pbrt's
// ParameterDictionary): typed values with the location of each, lookups that mark them used,
// and a final check that reports unknown (unused) names with a "did you mean" suggestion.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "render/scene/scene.hpp"

namespace rts::render {

struct TextureRef  { TextureId id = kNoId; };
struct MaterialRef { MaterialId id = kNoId; };
// A pattern's color map: `color_map = [[0, rgb(1)], [0.5, rgb(0.2)], ...]` (value, color) pairs.
struct ColorMapParam { std::vector<ColorMapEntry> entries; };
// A function of a point, compiled once by the runtime (`pattern { function = f }`, isosurfaces).
class CompiledFunction;  // render/geometry/function/compiled_function.hpp
struct FunctionRef { std::shared_ptr<const CompiledFunction> function; };
// A list of lists each holding vectors then numbers: a blob's `spheres = [[<0, 0, 0>, 1, 1]]`.
struct RowsParam {
  struct Row { std::vector<Vec3> vectors; std::vector<double> numbers; };
  std::vector<Row> rows;
};
// A sky_sphere's layers, `layers = [gradient { ... }, bozo { ... }]`: textures, or solid colors
// (texture kNoId, the color at the same index).
struct LayersParam {
  std::vector<TextureId> textures;
  std::vector<Color> colors;
};
// A material chosen by pattern's `materials = [a, b]`: materials in order.
struct MaterialListParam {
  std::vector<MaterialId> materials;
};
// An isosurface's container, `contained_by = box { min max }` or `sphere { center radius }`
// (the runtime reads the block's own properties; the shape is not placed).
struct ContainerParam {
  bool sphere = false;
  Vec3 min{-1.0}, max{1.0};
  Vec3 center{0.0};
  double radius = 1.0;
};

// The value kinds a block property can hold. The runtime converts its own values:
// number → double, bool, string, vector → Vec3, color → Color, list of vectors → vector<Vec3>,
// list of numbers → vector<double>, a texture value → TextureRef, a material → MaterialRef,
// a list of [number, color] pairs → ColorMapParam, a macro of one point → FunctionRef, an
// unplaced box or sphere → ContainerParam, a list holding textures (and colors) → LayersParam, a
// list of materials → MaterialListParam.
using ParamValue = std::variant<double, bool, std::string, Vec3, Color, TextureRef, MaterialRef,
                                std::vector<Vec3>, std::vector<double>, ColorMapParam, FunctionRef,
                                ContainerParam, RowsParam, LayersParam, MaterialListParam>;

// "number", "vector", ... for messages.
const char* param_type_name(const ParamValue& v);

struct Param {
  std::string name;
  ParamValue value;
  SourceRef loc;          // the property's location (its name)
  bool used = false;
};

class ParamSet {
 public:
  ParamSet() = default;
  ParamSet(std::string block_kind, SourceRef block_loc)
      : kind_(std::move(block_kind)), loc_(block_loc) {}

  void add(std::string name, ParamValue value, SourceRef loc);  // a later add overrides
  void reserve(std::size_t n) { params_.reserve(n); }            // capacity for n adds
  const std::string& kind() const { return kind_; }
  SourceRef loc() const { return loc_; }
  const std::vector<Param>& params() const { return params_; }

  bool has(std::string_view name) const;
  const Param* find(std::string_view name);  // marks used

  // Typed getters: a missing name gives `def`; a value of the wrong type throws SceneError at
  // the property ("property 'radius' of sphere expects a number, got a vector").
  // Conversions: number → Color (gray); Vec3 → Color; number → bool is NOT allowed.
  double number(std::string_view name, double def);
  int integer(std::string_view name, int def);          // also checks it is a whole number
  bool boolean(std::string_view name, bool def);
  std::string string(std::string_view name, const std::string& def);
  Vec3 vec3(std::string_view name, Vec3 def);
  Color color(std::string_view name, Color def);
  // Required variants throw SceneError at the block: "sphere needs property 'radius'".
  double require_number(std::string_view name);
  Vec3 require_vec3(std::string_view name);
  std::string require_string(std::string_view name);
  // Raw access for properties that accept several types (e.g. color or texture).
  const ParamValue* value(std::string_view name);       // marks used

  // Throws SceneError at the first property never looked up: "unknown property 'raduis' for
  // sphere; did you mean 'radius'?" `valid` lists every name this kind accepts.
  void check_unused(const std::vector<std::string_view>& valid) const;

  [[noreturn]] void fail(const Param& p, const std::string& message) const;
  // A block-level error (a missing property...). When the valid names are known, an unknown
  // property is reported instead: `sphere { raduis = 1 }` is a misspelling, not a missing radius.
  [[noreturn]] void fail_block(const std::string& message) const;
  // The names this kind accepts, for fail_block (the list must outlive the ParamSet).
  void set_valid_names(const std::vector<std::string_view>* names) { valid_ = names; }

 private:
  std::string kind_;
  SourceRef loc_;
  std::vector<Param> params_;
  const std::vector<std::string_view>* valid_ = nullptr;
};

// Checks shared by the builder and the shape descriptors (render/geometry/shapes/): each
// throws SceneError at the property (or the block when it is missing), e.g. "property 'radius'
// of sphere must be > 0, got -1", and returns the value it checked.
// Unit vectors closer to parallel than this (|a x b|) span no plane, and a point closer to a
// plane than this (|d . (a x b)|) does not leave it.
inline constexpr double kMinDirectionLength = 1e-12;
SourceRef loc_of(ParamSet& ps, std::string_view name);
void require(ParamSet& ps, std::string_view name, bool ok, std::string_view what, double got);
double positive(ParamSet& ps, std::string_view name, double v);
double non_negative(ParamSet& ps, std::string_view name, double v);
Vec3 direction(ParamSet& ps, std::string_view name, Vec3 v);
// Two points that must differ (a cylinder's ends): the error names `name` and `other`.
void distinct(ParamSet& ps, std::string_view name, std::string_view other, const Vec3& difference);
void non_negative_color(ParamSet& ps, std::string_view name, const Color& c);

// The closest candidate by edit distance, or "" when none is close enough to suggest.
std::string closest_name(std::string_view word, const std::vector<std::string_view>& candidates);

}  // namespace rts::render
