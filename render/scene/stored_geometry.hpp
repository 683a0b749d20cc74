// A shape's geometry as the scene description keeps it (ShapeDesc::geometry): the kinds of
// ShapeGeometry in the same order, those larger than a sphere boxed (boxed.hpp), so that every
// description pays for 32 bytes of geometry, not for the largest kind's 80. Profile finding
// (issue 24, RSS trace of 4M spheres placed by loops): the descriptions were 112 bytes each,
// 470 MB of the 501 MB resident at the end of evaluation, the render's peak; a sphere's own
// data is 32 of them. A triangle, box, cylinder, cone, disc or quad costs a heap block more
// (its data and the allocator's 16 bytes) and is described less often by the million.
//
// Read it as the variant it stands for: index() is ShapeGeometry's, shape_if<T>() and
// shape_get<T>() give the kind's data, visit_shape() calls f with it (const T&, never the box).
// The renderer's own arrays (World) hold the plain kinds: nothing is boxed where rays are
// traced.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>
#include <variant>

#include "render/scene/boxed.hpp"

namespace rts::render {

namespace stored_detail {

// Kept inline: at most 32 bytes (every BoxedShape kind is one pointer).
template <class T>
inline constexpr bool kInline = sizeof(T) <= 32;

template <class T>
using Stored = std::conditional_t<kInline<T>, T, Boxed<T>>;

template <class V>
struct StoredVariant;
template <class... T>
struct StoredVariant<std::variant<T...>> {
  using type = std::variant<Stored<T>...>;
};

template <class T, class V>
struct IsAlternative;
template <class T, class... A>
struct IsAlternative<T, std::variant<A...>> : std::bool_constant<(std::is_same_v<T, A> || ...)> {};

template <class T>
const T& unbox(const T& v) {
  return v;
}
template <class T>
const T& unbox(const Boxed<T>& v) {
  return *v;
}

}  // namespace stored_detail

template <class Geometry>
class StoredGeometryOf {
 public:
  template <class T>
  static constexpr bool kKind = stored_detail::IsAlternative<std::decay_t<T>, Geometry>::value;

  StoredGeometryOf() = default;  // the variant's first kind, default-made, as Geometry's
  template <class T, std::enable_if_t<kKind<T>, int> = 0>
  StoredGeometryOf(T v) {  // NOLINT: a shape's geometry from its kind's data
    set(std::move(v));
  }
  StoredGeometryOf(Geometry g) {  // NOLINT: and from the variant it stands for
    std::visit([&](auto& v) { set(std::move(v)); }, g);
  }

  std::size_t index() const { return v_.index(); }
  template <class T>
  bool holds() const {
    return std::holds_alternative<stored_detail::Stored<T>>(v_);
  }
  template <class T>
  const T* get_if() const {
    const auto* p = std::get_if<stored_detail::Stored<T>>(&v_);
    if constexpr (stored_detail::kInline<T>)
      return p;
    else
      return p ? &**p : nullptr;
  }
  // f(const T&) for the kind held.
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit([&](const auto& s) -> decltype(auto) { return f(stored_detail::unbox(s)); }, v_);
  }

 private:
  template <class T>
  void set(T v) {
    if constexpr (stored_detail::kInline<T>)
      v_.template emplace<T>(std::move(v));
    else
      v_.template emplace<Boxed<T>>(Boxed<T>(std::move(v)));
  }
  typename stored_detail::StoredVariant<Geometry>::type v_;
};

// The std::get_if / std::get / std::visit of a stored geometry.
template <class T, class G>
const T* shape_if(const StoredGeometryOf<G>& g) {
  return g.template get_if<T>();
}
template <class T, class G>
const T& shape_get(const StoredGeometryOf<G>& g) {
  const T* p = g.template get_if<T>();
  if (!p) throw std::bad_variant_access();
  return *p;
}
template <class F, class G>
decltype(auto) visit_shape(F&& f, const StoredGeometryOf<G>& g) {
  return g.visit(std::forward<F>(f));
}

}  // namespace rts::render
