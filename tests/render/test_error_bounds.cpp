// Every shape kind reports the rounding error bound of its hit point: a ray spawned from the
// hit, offset by that bound, never hits the same surface again (issue 16: quads reported none
// and shadowed themselves). The kinds are enumerated from ShapeGeometry, so a new kind without
// a sample here does not compile. Shadow rays must agree with closest hits for each kind too.
#include <cmath>
#include <memory>
#include <type_traits>
#include <utility>
#include <variant>

#include <catch2/catch.hpp>

#include "render/geometry/function/compiled_function.hpp"

#include "render/accel/world.hpp"
#include "render/geometry/ray.hpp"
#include "render/accel/flatten.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;

namespace {

template <class>
inline constexpr bool kNoSample = false;

// One instance of kind T in `s`, around the origin with a size of about one.
template <class T>
T sample(SceneDesc& s) {
  if constexpr (std::is_same_v<T, Sphere>) {
    return Sphere{Vec3(0.0), 1.0};
  } else if constexpr (std::is_same_v<T, Plane>) {
    return Plane{glm::normalize(Vec3(0.2, 1, -0.3)), 0.0};
  } else if constexpr (std::is_same_v<T, Triangle>) {
    return test::triangle(Vec3(-1, -1, 0.3), Vec3(1, -1, -0.2), Vec3(0, 1, 0));
  } else if constexpr (std::is_same_v<T, Box>) {
    return Box{Vec3(-1, -0.7, -0.9), Vec3(1, 0.8, 1.1)};
  } else if constexpr (std::is_same_v<T, Cylinder>) {
    return Cylinder{Vec3(0, -1, 0), Vec3(0.2, 1, 0.1), 0.8, true};
  } else if constexpr (std::is_same_v<T, Cone>) {
    return Cone{Vec3(0, -1, 0), Vec3(0.1, 1, 0), 1.0, 0.3, true};
  } else if constexpr (std::is_same_v<T, Disc>) {
    return Disc{Vec3(0.0), glm::normalize(Vec3(0.3, 1, 0.2)), 1.0, 0.2};
  } else if constexpr (std::is_same_v<T, MeshRef>) {
    auto m = std::make_shared<MeshData>();
    m->positions = {{-1, -1, 0}, {1, -1, 0.2f}, {1, 1, 0}, {-1, 1, -0.2f}};
    m->indices = {0, 1, 2, 0, 2, 3};
    s.meshes.push_back(m);
    return MeshRef{static_cast<MeshId>(s.meshes.size() - 1), false};
  } else if constexpr (std::is_same_v<T, Quad>) {
    return Quad{Vec3(-1, 0, 1), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  } else if constexpr (std::is_same_v<T, Torus>) {
    return Torus{0.8, 0.3};
  } else if constexpr (std::is_same_v<T, Superellipsoid>) {
    return Superellipsoid{0.3, 0.6};
  } else if constexpr (std::is_same_v<T, Blob>) {
    Blob g;
    g.threshold = 0.6;
    g.components = {BlobComponent{Vec3(-0.4, 0, 0), Vec3(-0.4, 0, 0), 0.9, 1.0, false},
                    BlobComponent{Vec3(0.2, -0.5, 0.1), Vec3(0.4, 0.6, -0.1), 0.5, 1.2, true},
                    BlobComponent{Vec3(0.1, 0.3, -0.3), Vec3(0.1, 0.3, -0.3), 0.3, -0.5, false}};
    return g;
  } else if constexpr (std::is_same_v<T, Isosurface>) {
    // x^2 + y^2 + z^2 + 0.3 sin(3x) < 0.64, in a box that cuts it at the top.
    auto f = std::make_shared<CompiledFunction>();
    using Op = CompiledFunction::Op;
    uint16_t xx, yy, zz, s1, s2, three, k, x3, sn, w, r;
    f->constant(3.0, three);
    f->constant(0.3, k);
    f->emit(Op::Mul, {CompiledFunction::kX, CompiledFunction::kX}, xx);
    f->emit(Op::Mul, {CompiledFunction::kY, CompiledFunction::kY}, yy);
    f->emit(Op::Mul, {CompiledFunction::kZ, CompiledFunction::kZ}, zz);
    f->emit(Op::Add, {xx, yy}, s1);
    f->emit(Op::Add, {s1, zz}, s2);
    f->emit(Op::Mul, {CompiledFunction::kX, three}, x3);
    f->emit(Op::Sin, {x3}, sn);
    f->emit(Op::Mul, {sn, k}, w);
    f->emit(Op::Add, {s2, w}, r);
    f->set_result(r);
    IsosurfaceData g;
    g.function = f;
    g.threshold = 0.64;
    g.max_gradient = 3.0;
    g.box_min = Vec3(-1.2, -1.2, -1.2);
    g.box_max = Vec3(1.2, 0.6, 1.2);
    return g;
  } else if constexpr (std::is_same_v<T, HeightField>) {
    // A 17 x 13 grid of hills and a valley, smooth, partly under water.
    std::vector<float> h;
    for (int iz = 0; iz < 13; ++iz)
      for (int ix = 0; ix < 17; ++ix)
        h.push_back(static_cast<float>(0.5 + 0.4 * std::sin(0.7 * ix) * std::cos(0.9 * iz)));
    HeightField g;
    g.data = make_height_field_data(17, 13, std::move(h), true);
    g.smooth = true;
    g.water_level = 0.2;
    return g;
  } else if constexpr (std::is_same_v<T, Sor>) {
    // A vase: a bulge, a waist, a flared lip, closed by its discs.
    SorData g;
    g.points = {Vec3(0.2, -1.2, 0), Vec3(0.6, -1, 0),  Vec3(0.9, -0.5, 0), Vec3(0.5, 0.2, 0),
                Vec3(0.4, 0.6, 0),  Vec3(0.7, 1, 0),   Vec3(0.8, 1.2, 0)};
    sor_setup(g);
    return g;
  } else if constexpr (std::is_same_v<T, Lathe>) {
    // A closed profile: a cup with a wall, a rim, a hollow inside and a foot.
    LatheData g;
    g.points = {Vec3(0, -1, 0),      Vec3(0.6, -1, 0), Vec3(0.4, -0.8, 0), Vec3(0.9, 0.9, 0),
                Vec3(0.8, 1, 0),     Vec3(0.7, 0.8, 0), Vec3(0, -0.5, 0)};
    lathe_setup(g);
    return g;
  } else if constexpr (std::is_same_v<T, Prism>) {
    // Two sub-polygons: a concave outline with a square hole (even-odd), closed by caps.
    PrismData g;
    g.points = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(0, 0.3, 0), Vec3(-1, 1, 0), Vec3(-1, -1, 0),
                Vec3(-0.4, -0.6, 0), Vec3(0.4, -0.6, 0), Vec3(0.4, -0.2, 0), Vec3(-0.4, -0.2, 0), Vec3(-0.4, -0.6, 0)};
    g.height1 = -0.5;
    g.height2 = 0.8;
    prism_setup(g);
    return g;
  } else if constexpr (std::is_same_v<T, Poly>) {
    // A tanglecube (a rounded cube with a hole through each face): 16 x^4 - 20 x^2 + 16 y^4 -
    // 20 y^2 + 16 z^4 - 20 z^2 + 11.8 = 0, about 1.05 across.
    Poly g;
    g.order = 4;
    g.terms = {PolyTerm{16, 4, 0, 0}, PolyTerm{-20, 2, 0, 0}, PolyTerm{16, 0, 4, 0}, PolyTerm{-20, 0, 2, 0},
               PolyTerm{16, 0, 0, 4}, PolyTerm{-20, 0, 0, 2}, PolyTerm{11.8, 0, 0, 0}};
    return g;
  } else {
    static_assert(kNoSample<T>, "a new shape kind needs a sample in test_error_bounds.cpp");
  }
}

// Rays from points on a sphere of `distance` around the shape's centre (a Fibonacci spiral) towards
// points near the centre; for each hit, the reverse ray spawned at the hit must miss.
struct Result {
  int hits = 0, rehits = 0, zero_error = 0;
};

Result spawn_back(const ShapeGeometry& g, SceneDesc s, double distance, double scale, const Mat4& placement) {
  test::place(s, test::add_shape(s, g), placement);
  FlatScene flat = flatten_scene(s);
  World world(s, flat);
  Result r;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double y = 1.0 - 2.0 * (i + 0.5) / n, rad = std::sqrt(1.0 - y * y), phi = 2.399963229728653 * i;
    const Vec3 dir_out(rad * std::cos(phi), y, rad * std::sin(phi));
    const Vec3 centre = Vec3(placement[3]);
    const Vec3 origin = centre + distance * dir_out;
    const Vec3 target = centre + 0.3 * scale * Vec3(std::sin(3.0 * i), std::cos(5.0 * i), std::sin(7.0 * i));
    const Ray ray{origin, glm::normalize(target - origin)};
    WorldHit hit;
    if (!world.intersect(ray, Interval::positive(), hit)) continue;
    ++r.hits;
    if (!(hit.error > 0.0)) ++r.zero_error;
    // Back towards the ray's origin (the side the ray came from): the surface is behind.
    const Vec3 back = -ray.direction;
    const Ray spawned{offset_ray_origin(hit.point, hit.normal, back, hit.error), back};
    if (world.occluded(spawned, Interval{0.0, hit.t})) ++r.rehits;
  }
  return r;
}

template <std::size_t... I>
void check_all_kinds(std::index_sequence<I...>) {
  (
      [] {
        using T = std::variant_alternative_t<I, ShapeGeometry>;
        for (double scale : {1.0, 1e-3, 1e4})
          for (double distance : {3.4, 40.0}) {
            for (bool moved : {false, true}) {
              SceneDesc s;
              const ShapeGeometry g = sample<T>(s);
              const Mat4 placement = moved ? glm::scale(glm::translate(Mat4(1.0), Vec3(1e3, -2e3, 5e2) * scale),
                                                        Vec3(scale))
                                           : glm::scale(Mat4(1.0), Vec3(scale));
              Result r = spawn_back(g, s, distance * scale, scale, placement);
              CAPTURE(I, scale, distance, moved, r.hits);
              CHECK(r.hits > 40);
              CHECK(r.zero_error == 0);
              CHECK(r.rehits == 0);
            }
          }
      }(),
      ...);
}

// Shadow rays take shortcuts for some kinds (a sphere's root alone, an isosurface's crossing
// without its normal): World::occluded must answer what World::intersect finds, for rays that
// end just before and just after the first hit.
template <std::size_t... I>
void check_occlusion_agrees(std::index_sequence<I...>) {
  (
      [] {
        using T = std::variant_alternative_t<I, ShapeGeometry>;
        SceneDesc s;
        const ShapeGeometry g = sample<T>(s);
        test::place(s, test::add_shape(s, g), glm::translate(Mat4(1.0), Vec3(0.3, -0.2, 0.1)));
        FlatScene flat = flatten_scene(s);
        World world(s, flat);
        int hits = 0, disagree = 0;
        for (int i = 0; i < 300; ++i) {
          const Vec3 origin = 3.0 * Vec3(std::sin(1.3 * i), std::cos(2.1 * i), std::sin(0.7 * i + 1.0));
          const Vec3 target = 0.5 * Vec3(std::sin(3.0 * i), std::cos(5.0 * i), std::sin(7.0 * i));
          const Ray ray{origin, glm::normalize(target - origin)};
          WorldHit hit;
          const bool found = world.intersect(ray, Interval::positive(), hit);
          if (world.occluded(ray, Interval::positive()) != found) ++disagree;
          if (!found) continue;
          ++hits;
          if (world.occluded(ray, Interval{0.0, 0.999 * hit.t})) ++disagree;  // ends before the hit
          if (!world.occluded(ray, Interval{0.0, 1.001 * hit.t})) ++disagree;  // ends past it
        }
        CAPTURE(I, hits);
        CHECK(hits > 30);
        CHECK(disagree == 0);
      }(),
      ...);
}

}  // namespace

TEST_CASE("shadow rays agree with closest hits for every shape kind", "[primitives][occlusion]") {
  check_occlusion_agrees(std::make_index_sequence<std::variant_size_v<ShapeGeometry>>());
}

TEST_CASE("every shape kind reports an error bound that its spawned rays clear", "[primitives][error]") {
  check_all_kinds(std::make_index_sequence<std::variant_size_v<ShapeGeometry>>());
}
