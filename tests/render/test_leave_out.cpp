// Leaving out what a scene does not need: the feature analysis, the specialised paths (same
// image as the generic one, fewer rays where features are unused) and the one-pass shadow
// test through glass.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "render/shade/features.hpp"
#include "render/shade/integrator.hpp"
#include "render/renderer.hpp"
#include "render/accel/shape_release.hpp"
#include "render/accel/world.hpp"
#include "render/prepared_scene.hpp"
#include "scene_fixture.hpp"

namespace rts::render {
namespace {

using namespace test;

// A diffuse scene: a grid of matte spheres on a plane, one point light.
SceneDesc diffuse_scene() {
  SceneDesc s;
  s.settings.width = 40;
  s.settings.height = 30;
  s.has_camera = true;
  s.camera.position = Vec3(0, 4, -9);
  s.camera.look_at = Vec3(0, 0.5, 0);
  MaterialDesc matte;
  matte.color = Color(0.8, 0.5, 0.3);
  MaterialId m = add_material(s, matte);
  place(s, add_shape(s, Plane{}, add_material(s, MaterialDesc{})));
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) place(s, add_shape(s, Sphere{Vec3(i - 2, 0.4, j - 2), 0.4}, m));
  LightDesc light;
  light.position = Vec3(-4, 8, -5);
  place(s, add_light(s, light));
  return s;
}

RenderResult render_with(const SceneDesc& s, bool specialize) {
  RenderOptions o;
  o.threads = 1;
  o.specialize = specialize;
  return render(s, o);
}

bool same_pixels(const Image& a, const Image& b) { return a.rgb == b.rgb; }

bool has(const std::vector<std::string>& v, const char* name) { return std::find(v.begin(), v.end(), name) != v.end(); }

}  // namespace

TEST_CASE("analysis: a diffuse scene uses only spheres, a plane, a point light and shadows", "[leave_out]") {
  SceneDesc s = diffuse_scene();
  FlatScene flat = flatten_scene(s);
  FeatureSet f = analyze_features(s, flat, FeatureContext{1, 5, false});
  CHECK(f.has(Feature::Sphere));
  CHECK(f.has(Feature::Plane));
  CHECK(f.has(Feature::PointLight));
  CHECK(f.has(Feature::Shadows));
  for (Feature x : {Feature::Reflection, Feature::Transmission, Feature::Texture, Feature::Specular,
                    Feature::Emission, Feature::AreaLight, Feature::AreaSampling, Feature::Antialiasing,
                    Feature::DepthOfField, Feature::Mesh, Feature::TransmissiveShadows})
    CHECK_FALSE(f.has(x));
  CHECK(trace_flags::for_features(f) == 0u);
}

TEST_CASE("analysis: zero strength counts as unused, declared but unplaced as absent", "[leave_out]") {
  SceneDesc s = diffuse_scene();
  MaterialDesc zero;
  zero.reflect = Color(0.0);
  zero.transmit = Color(0.0);
  zero.roughness = 0.3;
  zero.fresnel = true;
  zero.specular = 0.0;
  place(s, add_shape(s, Box{}, add_material(s, zero)));
  LightDesc dark_area;
  dark_area.kind = LightKind::Area;
  dark_area.intensity = 0.0;
  place(s, add_light(s, dark_area));
  // Declared, never placed: a mirror sphere and a textured material.
  MaterialDesc mirror;
  mirror.reflect = Color(0.9);
  add_shape(s, Sphere{}, add_material(s, mirror));
  FeatureSet f = analyze_features(s, flatten_scene(s), FeatureContext{1, 5, false});
  CHECK(f.has(Feature::Box));
  for (Feature x : {Feature::Reflection, Feature::Transmission, Feature::Glossiness, Feature::Fresnel,
                    Feature::AreaLight, Feature::AreaSampling, Feature::Specular})
    CHECK_FALSE(f.has(x));
  CHECK(trace_flags::for_features(f) == 0u);

  // max_depth 0: reflection cannot happen, so it is not used either.
  place(s, add_shape(s, Sphere{Vec3(3, 1, 0), 0.5}, add_material(s, mirror)));
  CHECK(analyze_features(s, flatten_scene(s), FeatureContext{1, 5, false}).has(Feature::Reflection));
  CHECK_FALSE(analyze_features(s, flatten_scene(s), FeatureContext{1, 0, false}).has(Feature::Reflection));
}

TEST_CASE("a diffuse scene casts no secondary rays and no extra shadow samples", "[leave_out]") {
  SceneDesc a = diffuse_scene();
  RenderResult ra = render_with(a, true);
  const RayCounters& c = ra.stats.rays;
  CHECK(c.reflection == 0);
  CHECK(c.refraction == 0);
  CHECK(c.camera == 40u * 30u);
  CHECK(c.shadow > 0);
  CHECK(c.shadow <= c.camera);  // one light: at most one shadow ray per camera ray

  // (c): the same with every other feature at zero strength: same rays, same image.
  SceneDesc z = diffuse_scene();
  MaterialDesc& matte = z.materials[0];
  matte.reflect = Color(0.0);
  matte.transmit = Color(0.0);
  matte.roughness = 0.5;
  matte.emission = Color(0.0);
  LightDesc area;
  area.kind = LightKind::Area;
  area.intensity = 0.0;
  area.samples = 16;
  place(z, add_light(z, area));
  LightDesc spot;
  spot.kind = LightKind::Spot;
  spot.color = Color(0.0);
  place(z, add_light(z, spot));
  RenderResult rz = render_with(z, true);
  CHECK(rz.stats.rays.shadow == c.shadow);
  CHECK(rz.stats.rays.reflection == 0);
  CHECK(rz.stats.rays.refraction == 0);
  CHECK(same_pixels(ra.color, rz.color));
  CHECK_FALSE(has(rz.stats.features_used, "area_light"));
  CHECK(has(rz.stats.features_left_out, "reflection"));

  // (b): unused declarations of every other feature change nothing.
  SceneDesc b = diffuse_scene();
  MaterialDesc glass;
  glass.transmit = Color(0.9);
  glass.ior = 1.5;
  MaterialId g = add_material(b, glass);
  add_shape(b, Sphere{}, g);
  add_shape(b, Cylinder{}, g);
  b.textures.push_back(TextureDesc{});
  MaterialDesc textured;
  textured.texture = 0;
  add_shape(b, Box{}, add_material(b, textured));
  add_light(b, area);
  RenderResult rb = render_with(b, true);
  CHECK(rb.stats.rays.shadow == c.shadow);
  CHECK(rb.stats.rays.total() == c.total());
  CHECK(same_pixels(ra.color, rb.color));
}

TEST_CASE("specialised paths give the generic path's image", "[leave_out]") {
  // Every feature at once, then subsets: glass (shadows through it), mirrors, glossy
  // reflection, a texture, an area light, a light of power 0 before it, specular highlights.
  auto scene = [](bool glass, bool glossy, bool area, bool texture) {
    SceneDesc s = diffuse_scene();
    s.settings.samples = 2;
    MaterialDesc m;
    m.specular = 0.5;
    m.reflect = Color(0.4);
    m.roughness = glossy ? 0.2 : 0.0;
    place(s, add_shape(s, Sphere{Vec3(-1, 1.2, -1), 0.6}, add_material(s, m)));
    if (glass) {
      MaterialDesc gl;
      gl.transmit = Color(0.9, 0.8, 0.7);
      gl.ior = 1.5;
      gl.fresnel = true;
      place(s, add_shape(s, Sphere{Vec3(1, 1.2, -1), 0.6}, add_material(s, gl)));
    }
    if (texture) {
      TextureDesc t;
      t.color1 = Color(0.9, 0.1, 0.1);
      s.textures.push_back(t);
      s.materials[1].texture = 0;  // the plane
    }
    LightDesc dark;
    dark.kind = LightKind::Area;
    dark.intensity = 0;
    place(s, add_light(s, dark));
    if (area) {
      LightDesc a;
      a.kind = LightKind::Area;
      a.position = Vec3(3, 6, -2);
      a.samples = 5;
      place(s, add_light(s, a));
    }
    return s;
  };
  for (int bits = 0; bits < 16; ++bits) {
    SceneDesc s = scene(bits & 1, bits & 2, bits & 4, bits & 8);
    RenderResult fast = render_with(s, true), generic = render_with(s, false);
    INFO("glass " << (bits & 1) << " glossy " << (bits & 2) << " area " << (bits & 4) << " texture " << (bits & 8));
    CHECK(fast.stats.rays.camera == generic.stats.rays.camera);
    CHECK(fast.stats.rays.reflection == generic.stats.rays.reflection);
    CHECK(fast.stats.rays.refraction == generic.stats.rays.refraction);
    CHECK(fast.stats.rays.shadow == generic.stats.rays.shadow);
    CHECK(same_pixels(fast.color, generic.color));
  }
}

TEST_CASE("a taken scene's shapes are freed by chunks as the world's instances are made", "[leave_out]") {
  // ShapeRelease (render/accel/shape_release.hpp): a chunk goes once the loop over the placed
  // shapes has passed the last placement that reads it, unless a group or a CSG block (made
  // after the loop) reads one of its shapes. Below kReleaseMemoryMinItems nothing is freed.
  using Shapes = ChunkedVector<ShapeDesc>;
  SceneDesc s = diffuse_scene();
  const MaterialId m = s.shapes[1].material;
  const std::size_t placed = kReleaseMemoryMinItems + Shapes::kChunk;
  while (s.shapes.size() < placed) {
    const double k = static_cast<double>(s.shapes.size());
    place(s, add_shape(s, Sphere{Vec3(std::fmod(k, 300.0) * 0.1 - 15, 0.1, std::floor(k / 300.0) * 0.1), 0.04}, m));
  }
  // A CSG block whose leaves are shapes of the second chunk, one of them also placed alone.
  const NodeId pinned_leaf = static_cast<NodeId>(Shapes::kChunk + 3 + s.lights.size());
  REQUIRE(s.nodes[pinned_leaf].kind == NodeKind::Shape);
  REQUIRE(Shapes::chunk_of(s.nodes[pinned_leaf].index) == 1);
  CsgDesc cut;
  cut.op = CsgOp::Intersection;
  cut.children = {Child{pinned_leaf, Mat4(1.0), {}}, Child{add_shape(s, Box{Vec3(-20), Vec3(20)}), Mat4(1.0), {}}};
  place(s, add_csg(s, cut), translate(Vec3(0, 0.5, 0)));
  // A group placed twice (instanced: 64 shapes), its members in the last chunk.
  std::vector<Child> members;
  for (int i = 0; i < 64; ++i) members.push_back(Child{add_shape(s, Sphere{Vec3(i * 0.05, 1, 0), 0.02}, m), Mat4(1.0), {}});
  const NodeId group = add_group(s, members);
  place(s, group, translate(Vec3(-1, 0, -1)));
  place(s, group, translate(Vec3(1, 0, -1)));

  SECTION("the chunks go in order, the ones a block or a group reads stay") {
    SceneDesc taken = s;
    const FlatScene flat = flatten_scene(taken);
    REQUIRE(flat.shapes.size() == placed);  // the plane, the spheres; not the group's or the block's
    const std::size_t chunks = taken.shapes.chunk_count();
    std::vector<std::size_t> last(chunks, 0);
    for (std::size_t i = 0; i < flat.shapes.size(); ++i) last[Shapes::chunk_of(flat.shapes[i].shape)] = i;
    ShapeRelease release(&taken, flat);
    for (std::size_t i = 0; i < flat.shapes.size(); ++i) {
      release.passed(i);
      for (std::size_t k : {std::size_t{0}, std::size_t{2}})
        CHECK((taken.shapes.chunk_capacity_bytes(k) == 0) == (i >= last[k]));
    }
    CHECK(taken.shapes.chunk_capacity_bytes(1) > 0);           // the CSG block's leaf
    CHECK(taken.shapes.chunk_capacity_bytes(chunks - 1) > 0);  // the group's members
    for (std::size_t k = 2; k + 1 < chunks; ++k) CHECK(taken.shapes.chunk_capacity_bytes(k) == 0);
  }
  SECTION("nothing is freed for a borrowed scene or a small one") {
    const FlatScene flat = flatten_scene(s);
    SceneDesc copy = s;
    ShapeRelease none(nullptr, flat);
    for (std::size_t i = 0; i < flat.shapes.size(); ++i) none.passed(i);
    CHECK(copy.shapes.chunk_capacity_bytes(0) > 0);
    SceneDesc small = diffuse_scene();
    const FlatScene small_flat = flatten_scene(small);
    ShapeRelease below(&small, small_flat);
    for (std::size_t i = 0; i < small_flat.shapes.size(); ++i) below.passed(i);
    CHECK(small.shapes.chunk_capacity_bytes(0) > 0);
  }
  SECTION("the world and the image are those of the scene borrowed") {
    const PreparedScene borrowed(s, true, 0);
    const PreparedScene taken(SceneDesc(s), true, 0);
    CHECK(taken.scene().shapes.empty());
    CHECK(taken.world().instance_count() == borrowed.world().instance_count());
    CHECK(taken.world().bvh_nodes() == borrowed.world().bvh_nodes());
    RenderOptions o;
    o.threads = 1;
    CHECK(same_pixels(render(borrowed, o).color, render(taken, o).color));
  }
}

TEST_CASE("a taken scene is prepared as a borrowed one, its graph released before the BVH", "[leave_out]") {
  // What the features, the world and the image of a scene taken by PreparedScene (render() of
  // a scene rendered once) read of its shapes is read before they are freed.
  SceneDesc s = diffuse_scene();
  MaterialDesc mirror;
  mirror.reflect = Color(0.8);
  mirror.roughness = 0.1;
  place(s, add_shape(s, Sphere{Vec3(1, 1.2, -1), 0.6}, add_material(s, mirror)));
  CsgDesc cut;
  cut.op = CsgOp::Difference;
  cut.children = {Child{add_shape(s, Box{Vec3(-1), Vec3(1)}), Mat4(1.0), {}},
                  Child{add_shape(s, Sphere{Vec3(0), 1.2}), Mat4(1.0), {}}};
  s.csgs.push_back(cut);
  s.nodes.push_back(Node{NodeKind::Csg, static_cast<uint32_t>(s.csgs.size() - 1)});
  place(s, static_cast<NodeId>(s.nodes.size() - 1), translate(Vec3(-2, 1, 1)));
  const PreparedScene borrowed(s, true, 0);
  const PreparedScene taken(SceneDesc(s), true, 0);
  CHECK(borrowed.scene().shapes.size() == s.shapes.size());
  CHECK(taken.scene().shapes.empty());
  CHECK(taken.scene().nodes.empty());
  CHECK(taken.scene().csgs.empty());
  CHECK(taken.scene().roots.empty());
  CHECK(taken.flat().shapes.empty());
  CHECK(taken.flat().lights.size() == borrowed.flat().lights.size());
  CHECK(taken.scene().materials.size() == s.materials.size());
  CHECK(taken.world().instance_count() == borrowed.world().instance_count());
  CHECK(taken.world().bvh_nodes() == borrowed.world().bvh_nodes());
  for (int depth : {0, 5}) {
    const FeatureContext ctx{2, depth, false};
    const FeatureSet expected = analyze_features(s, flatten_scene(s), ctx);
    CHECK(borrowed.features(ctx).used() == taken.features(ctx).used());
    FeatureSet from_scene = expected;
    if (borrowed.world().uses_bvh()) from_scene.add(Feature::Bvh);
    CHECK(taken.features(ctx).used() == from_scene.used());
  }
  CHECK(taken.features(FeatureContext{2, 5, false}).has(Feature::Glossiness));
  CHECK(taken.features(FeatureContext{2, 5, false}).has(Feature::Csg));
  CHECK_FALSE(taken.features(FeatureContext{2, 0, false}).has(Feature::Reflection));
  RenderOptions o;
  o.threads = 1;
  CHECK(same_pixels(render(borrowed, o).color, render(taken, o).color));
  SceneDesc once = s;
  CHECK(same_pixels(render(std::move(once), o).color, render(s, o).color));
}

TEST_CASE("one shadow traversal collects glass crossings and stops at opaque hits", "[leave_out]") {
  SceneDesc s;
  MaterialDesc glass;
  glass.transmit = Color(0.5);
  MaterialId g = add_material(s, glass);
  place(s, add_shape(s, Sphere{Vec3(0, 0, 5), 1}, g));
  place(s, add_shape(s, Sphere{Vec3(0, 0, 10), 1}, g));
  for (int i = 0; i < 8; ++i) place(s, add_shape(s, Sphere{Vec3(20 + i, 20, 0), 0.1}));  // enough for a BVH
  place(s, add_shape(s, Sphere{Vec3(0, 0, 20), 1}));  // opaque, beyond both
  World w(s, flatten_scene(s));
  REQUIRE(w.uses_bvh());
  Ray ray{Vec3(0, 0, 0), Vec3(0, 0, 1)};
  ShadowCrossings out;
  CHECK_FALSE(w.shadow_crossings(ray, Interval(0, 15), out));
  CHECK(out.count == 4);  // in and out of each glass sphere
  std::vector<double> ts(out.t, out.t + out.count);
  std::sort(ts.begin(), ts.end());
  CHECK(ts[0] == Approx(4));
  CHECK(ts[1] == Approx(6));
  CHECK(ts[2] == Approx(9));
  CHECK(ts[3] == Approx(11));
  CHECK(w.shadow_crossings(ray, Interval(0, 25), out));  // the opaque sphere blocks
}

TEST_CASE("a handful of objects is traced without a BVH, with the same hits", "[leave_out]") {
  SceneDesc s;
  for (int i = 0; i < 3; ++i) place(s, add_shape(s, Sphere{Vec3(i * 3.0, 0, 5), 1}));
  World small(s, flatten_scene(s)), with_bvh(s, flatten_scene(s), /*specialize=*/false);
  CHECK_FALSE(small.uses_bvh());
  CHECK(with_bvh.uses_bvh());
  for (int i = -10; i <= 10; ++i) {
    Ray r{Vec3(0, 0, 0), Vec3(i * 0.1, 0.01 * i, 1)};
    WorldHit a, b;
    bool ha = small.intersect(r, Interval::positive(), a), hb = with_bvh.intersect(r, Interval::positive(), b);
    REQUIRE(ha == hb);
    if (ha) CHECK(a.t == b.t);
    CHECK(small.occluded(r, Interval::positive()) == with_bvh.occluded(r, Interval::positive()));
  }
}

}  // namespace rts::render

namespace rts::render {
TEST_CASE("the leave-out table: each feature turns on its integrator flags and no other", "[leave_out]") {
  auto flags_of = [](Feature f) {
    FeatureSet s;
    s.add(f);
    return trace_flags::for_features(s);
  };
  CHECK(flags_of(Feature::Reflection) == trace_flags::kSecondary);
  CHECK(flags_of(Feature::Transmission) == trace_flags::kSecondary);
  CHECK(flags_of(Feature::Texture) == trace_flags::kTexture);
  CHECK(flags_of(Feature::Specular) == trace_flags::kSpecular);
  CHECK(flags_of(Feature::AreaSampling) == trace_flags::kRandom);
  CHECK(flags_of(Feature::Glossiness) == trace_flags::kRandom);
  CHECK(flags_of(Feature::TransmissiveShadows) == trace_flags::kTransmissiveShadows);
  unsigned others = 0;
  for (std::size_t i = 0; i < kFeatureCount; ++i) {
    Feature f = static_cast<Feature>(i);
    CAPTURE(feature_name(f));
    CHECK((flags_of(f) & ~trace_flags::kAll) == 0u);
    if (f != Feature::Reflection && f != Feature::Transmission && f != Feature::Texture && f != Feature::Specular &&
        f != Feature::AreaSampling && f != Feature::Glossiness && f != Feature::TransmissiveShadows)
      others |= flags_of(f);
    CHECK(!feature_name(f).empty());
  }
  CHECK(others == 0u);
  // A glass sphere lit by a light without shadows: transmissive_shadows is void without shadows.
  SceneDesc s = diffuse_scene();
  MaterialDesc glass;
  glass.transmit = Color(0.9);
  place(s, add_shape(s, Sphere{Vec3(0, 1, 0), 0.5}, add_material(s, glass)));
  FeatureSet with_shadows = analyze_features(s, flatten_scene(s), FeatureContext{1, 5, false});
  CHECK(with_shadows.has(Feature::TransmissiveShadows));
  for (LightDesc& l : s.lights) l.shadows = false;
  FeatureSet without = analyze_features(s, flatten_scene(s), FeatureContext{1, 5, false});
  CHECK(!without.has(Feature::Shadows));
  CHECK(!without.has(Feature::TransmissiveShadows));
  CHECK(without.has(Feature::Transmission));
}
}  // namespace rts::render
