// ShapeDesc::geometry (render/scene/stored_geometry.hpp): every kind of ShapeGeometry stored,
// the large ones boxed, reads back as the same kind with the same data; copies are deep.
#include <catch2/catch.hpp>

#include <cstring>
#include <variant>

#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/scene/scene.hpp"

using namespace rts::render;

namespace {

// A kind's data with every double set from a seed, so two copies compare by bytes where the
// kind is plain data.
template <class T>
T filled(double seed) {
  T v{};
  if constexpr (std::is_trivially_copyable_v<T>) {
    double* d = reinterpret_cast<double*>(&v);
    for (std::size_t k = 0; k < sizeof(T) / sizeof(double); ++k) d[k] = seed + 0.25 * static_cast<double>(k);
  }
  return v;
}

template <class T>
bool same_bytes(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

}  // namespace

TEST_CASE("every shape kind stored in a description reads back as itself", "[scene][shapes]") {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (
        [&] {
          using T = ShapeKind<I>;
          INFO("kind " << shape_name(I));
          StoredGeometry g = filled<T>(1.5 + I);
          CHECK(g.index() == I);
          CHECK(g.template holds<T>());
          REQUIRE(shape_if<T>(g) != nullptr);
          if constexpr (std::is_trivially_copyable_v<T>) {
            CHECK(same_bytes(*shape_if<T>(g), filled<T>(1.5 + I)));
            const StoredGeometry copy = g;
            CHECK(same_bytes(shape_get<T>(copy), filled<T>(1.5 + I)));
          }
          // Another kind is not there.
          if constexpr (I != 0) CHECK(shape_if<Sphere>(g) == nullptr);
          else CHECK(shape_if<Box>(g) == nullptr);
          // visit_shape hands over the kind's own data, never the box.
          const bool right_kind = visit_shape([](const auto& v) { return std::is_same_v<std::decay_t<decltype(v)>, T>; }, g);
          CHECK(right_kind);
        }(),
        ...);
  }(std::make_index_sequence<kShapeKindCount>{});
}

TEST_CASE("a stored shape's copy is its own; a sphere's description is 64 bytes", "[scene][shapes]") {
  ShapeDesc a;
  a.geometry = Cylinder{Vec3(1, 2, 3), Vec3(4, 5, 6), 0.5, false};
  ShapeDesc b = a;
  REQUIRE(shape_if<Cylinder>(b.geometry) != nullptr);
  CHECK(shape_if<Cylinder>(b.geometry) != shape_if<Cylinder>(a.geometry));  // boxed: deep copy
  CHECK(shape_get<Cylinder>(b.geometry).radius == 0.5);
  CHECK(shape_get<Cylinder>(b.geometry).to == Vec3(4, 5, 6));
  CHECK_FALSE(shape_get<Cylinder>(b.geometry).capped);
  CHECK_THROWS_AS(shape_get<Sphere>(b.geometry), std::bad_variant_access);
  a.geometry = Sphere{Vec3(1, 2, 3), 4.0};  // a boxed kind replaced by an inline one
  CHECK(shape_get<Sphere>(a.geometry).radius == 4.0);
  CHECK(shape_if<Cylinder>(a.geometry) == nullptr);
  if (sizeof(void*) == 8) CHECK(sizeof(ShapeDesc) == 64);
}
