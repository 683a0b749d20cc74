// A color map whose entries are textures (POV-Ray's pigment_map, render/shade/texture.cpp):
// each entry is evaluated at the map's own texture-space point, after the entry's transform,
// and the two entries either side of the pattern's index are blended; a plain entry is its
// colour and transmit. Exact closed forms (1e-12): nothing here is noisy.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "render/renderer.hpp"
#include "render/shade/texture.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

// gradient along `axis` with a two-entry map (lo at 0, hi at 1), transmits as given.
TextureDesc gradient(int axis, glm::dvec3 lo, glm::dvec3 hi, double lo_transmit = 0.0, double hi_transmit = 0.0) {
  TextureDesc t;
  t.kind = TextureKind::Pattern;
  t.pattern.kind = PatternKind::Gradient;
  t.pattern.axis = axis;
  t.pattern.color_map = {{0.0, lo, lo_transmit}, {1.0, hi, hi_transmit}};
  return t;
}

glm::dvec3 mix(glm::dvec3 a, glm::dvec3 b, double t) { return a + (b - a) * t; }

const glm::dvec3 kRed(1, 0, 0), kBlue(0, 0, 1), kYellow(1, 1, 0);

}  // namespace

TEST_CASE("a pigment_map entry is its texture at the map's point, blended by the pattern", "[pigment_map]") {
  SceneDesc s;
  // Entry texture: gradient y red → blue, scaled by 0.5 (two ramps per unit of y).
  TextureDesc inner = gradient(1, kRed, kBlue);
  inner.transform = scale(Vec3(0.5));
  s.textures.push_back(inner);
  // The map: gradient x, the inner texture at 0, yellow at 1, the whole moved up by 0.1.
  TextureDesc outer = gradient(0, glm::dvec3(0), kYellow);
  outer.pattern.color_map[0].texture = 0;
  outer.transform = translate(Vec3(0, 0.1, 0));
  s.textures.push_back(outer);
  const std::vector<CompiledTexture> compiled = compile_textures(s);
  REQUIRE(compiled.size() == 2);
  for (double x : {0.1, 0.35, 0.8})
    for (double y : {0.15, 0.3, 0.55}) {
      TexturePoint p;
      p.object_point = Vec3(x, y, 0.2);
      // Map space: y - 0.1; the entry's space: twice that, a ramp repeating each unit.
      const double inner_t = std::fmod(2.0 * (y - 0.1), 1.0);
      const glm::dvec3 want = mix(mix(kRed, kBlue, inner_t), kYellow, x);
      const Color got = compiled[1].eval(p);
      INFO("x " << x << " y " << y);
      CHECK(got.r == Approx(want.x).margin(1e-12));
      CHECK(got.g == Approx(want.y).margin(1e-12));
      CHECK(got.b == Approx(want.z).margin(1e-12));
    }
}

TEST_CASE("a pigment_map's transmit comes from its entries, textured or plain", "[pigment_map]") {
  SceneDesc s;
  s.textures.push_back(gradient(1, kRed, kRed, 0.0, 1.0));   // transmit = y
  TextureDesc outer = gradient(0, glm::dvec3(0), kBlue, 0.0, 0.5);
  outer.pattern.color_map[0].texture = 0;
  s.textures.push_back(outer);
  const std::vector<CompiledTexture> compiled = compile_textures(s);
  TexturePoint p;
  p.object_point = Vec3(0.25, 0.6, 0.0);
  const glm::dvec4 got = compiled[1].eval_with_transmit(p);
  CHECK(got.w == Approx(0.75 * 0.6 + 0.25 * 0.5).margin(1e-12));
  CHECK(got.x == Approx(0.75).margin(1e-12));
  CHECK(got.z == Approx(0.25).margin(1e-12));
}

TEST_CASE("an entry refers to a texture built before its map", "[pigment_map]") {
  SceneDesc s;
  TextureDesc outer = gradient(0, kRed, kBlue);
  outer.pattern.color_map[1].texture = 0;   // itself
  s.textures.push_back(outer);
  CHECK_THROWS_AS(compile_textures(s), RenderError);
}

TEST_CASE("an image used only in a pigment_map is loaded: a missing file is a located error", "[pigment_map]") {
  // The renderer opens only the images placed materials use; an entry's image must count.
  SceneDesc s;
  s.settings.width = s.settings.height = 4;
  TextureDesc image;
  image.kind = TextureKind::Image;
  image.image_path = "/nonexistent/entry.png";
  image.loc = SourceRef{"map.rts", 3, 9};
  s.textures.push_back(image);
  TextureDesc outer = gradient(0, kRed, kBlue);
  outer.pattern.color_map[1].texture = 0;
  s.textures.push_back(outer);
  MaterialDesc m;
  m.texture = 1;
  place(s, add_shape(s, Sphere{}, add_material(s, m)));
  try {
    render(s, RenderOptions{});
    FAIL("expected a RenderError");
  } catch (const RenderError& e) {
    CHECK(e.where.line == 3);
  }
}

TEST_CASE("maps of maps share their entries and nest at most kMaxColorMapNesting deep", "[pigment_map]") {
  // Each level a map of the level below, twice: copied, level 30 would hold 2^30 textures; the
  // entries point at the level below instead. Past the limit a located error stops it.
  auto chain = [](int levels) {
    SceneDesc s;
    s.textures.push_back(gradient(1, kRed, kBlue));
    for (int k = 1; k <= levels; ++k) {
      TextureDesc t = gradient(k % 2, glm::dvec3(0), glm::dvec3(0));
      t.pattern.color_map[0].texture = static_cast<TextureId>(k - 1);
      t.pattern.color_map[1].texture = static_cast<TextureId>(k - 1);
      t.loc = SourceRef{"maps.rts", static_cast<uint32_t>(k), 1};
      s.textures.push_back(t);
    }
    return s;
  };
  const SceneDesc ok = chain(kMaxColorMapNesting);
  const std::vector<CompiledTexture> compiled = compile_textures(ok);
  TexturePoint p;
  p.object_point = Vec3(0.3, 0.25, 0.0);
  // Every level blends the same texture with itself: the innermost gradient's colour at y.
  const Color c = compiled.back().eval(p);
  CHECK(c.r == Approx(0.75).margin(1e-12));
  CHECK(c.b == Approx(0.25).margin(1e-12));
  try {
    compile_textures(chain(kMaxColorMapNesting + 1));
    FAIL("expected a RenderError");
  } catch (const RenderError& e) {
    CHECK(e.where.line == kMaxColorMapNesting + 1);
    CHECK(std::string(e.what()).find("at most 32") != std::string::npos);
  }
}
