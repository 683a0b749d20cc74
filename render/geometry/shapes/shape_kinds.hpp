// Every shape kind, in the order of ShapeGeometry (render/scene/scene.hpp): that variant is the
// list, and each alternative's ShapeTraits (in its own header, included here) describes it.
// A variant index is a shape kind everywhere: World's PrimKind, the shape Features and the
// tables derived below follow it, checked by static_asserts.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <utility>
#include <variant>

#include "render/geometry/shapes/blob.hpp"
#include "render/geometry/shapes/box.hpp"
#include "render/geometry/shapes/cone.hpp"
#include "render/geometry/shapes/cylinder.hpp"
#include "render/geometry/shapes/disc.hpp"
#include "render/geometry/shapes/height_field.hpp"
#include "render/geometry/shapes/isosurface.hpp"
#include "render/geometry/shapes/lathe.hpp"
#include "render/geometry/shapes/mesh.hpp"
#include "render/geometry/shapes/plane.hpp"
#include "render/geometry/shapes/poly.hpp"
#include "render/geometry/shapes/prism.hpp"
#include "render/geometry/shapes/quad.hpp"
#include "render/geometry/shapes/shape_info.hpp"
#include "render/geometry/shapes/sor.hpp"
#include "render/geometry/shapes/sphere.hpp"
#include "render/geometry/shapes/superellipsoid.hpp"
#include "render/geometry/shapes/torus.hpp"
#include "render/geometry/shapes/triangle.hpp"

namespace rts::render {

inline constexpr std::size_t kShapeKindCount = std::variant_size_v<ShapeGeometry>;

template <std::size_t I>
using ShapeKind = std::variant_alternative_t<I, ShapeGeometry>;

// The variant index of geometry type T.
template <class T, std::size_t I = 0>
constexpr std::size_t shape_index() {
  static_assert(I < kShapeKindCount, "not a ShapeGeometry alternative");
  if constexpr (std::is_same_v<ShapeKind<I>, T>)
    return I;
  else
    return shape_index<T, I + 1>();
}

namespace detail {
template <std::size_t... I>
constexpr std::array<ShapeInfo, kShapeKindCount> shape_infos(std::index_sequence<I...>) {
  return {ShapeTraits<ShapeKind<I>>::kInfo...};
}
}  // namespace detail

// kShapeInfos[geometry.index()] describes that shape.
inline constexpr std::array<ShapeInfo, kShapeKindCount> kShapeInfos =
    detail::shape_infos(std::make_index_sequence<kShapeKindCount>());

inline constexpr std::string_view shape_name(std::size_t kind) { return kShapeInfos[kind].name; }
inline std::string_view shape_name(const StoredGeometry& g) { return kShapeInfos[g.index()].name; }

// The kind named `name`, or nullptr.
inline const ShapeInfo* find_shape(std::string_view name) {
  for (const ShapeInfo& s : kShapeInfos)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace rts::render
