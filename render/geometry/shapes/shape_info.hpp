// What a shape kind says about itself, beside its bounds() and intersect(): its name in the
// language, its properties (with type, default and a one-line meaning), whether it encloses
// a solid and whether its hits carry texture coordinates. Each kind specialises ShapeTraits
// in its own header (render/geometry/shapes/<kind>.hpp); shape_kinds.hpp collects them in the
// order of ShapeGeometry, and the builder's tables, World's storage, feature names, memory
// accounting, `rts check`'s summary and the docs and fuzz-dictionary tests are derived from it.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace rts::render {

struct PropertyInfo {
  std::string_view name;
  std::string_view type;           // as docs/shapes.md writes it: "vector", "number > 0", "bool"...
  std::string_view default_value;  // "*required*", "none" (optional, no value) or the default
  std::string_view meaning;        // one line
};

// Closed shapes bound a solid (every ray that enters leaves again), so CSG can tell inside from
// outside; open ones (a disc, a triangle, a quad: sheets) cannot. Cylinders and cones are
// closed only with their caps; a mesh when it is watertight (mesh_closure.hpp, checked when
// it is placed in CSG).
enum class Closure : uint8_t { Closed, Open, WhenCapped, WhenWatertight };

struct ShapeInfo {
  std::string_view name;                     // the block kind, "sphere"
  std::span<const PropertyInfo> properties;  // besides `material`, which every shape takes
  Closure closure = Closure::Open;
  bool has_uv = false;                       // hits carry (u, v) texture coordinates
  bool has_tangents = false;                 // hits set dpdu and dpdv (bump and normal maps)
  bool bounded = true;                       // has bounds() (else kept out of the BVH: planes)
};

// Specialised for each alternative of ShapeGeometry, in that kind's header.
template <class Geometry>
struct ShapeTraits;

}  // namespace rts::render
