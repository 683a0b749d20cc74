// Layered materials (MaterialDesc::layered, render/shade/layers.hpp): in Whitted mode each coat
// adds its diffuse by its cover and its gloss whole, over what the layers below send times
// what the coat lets through; in path mode one layer per hit, with the same mean.
#include <catch2/catch.hpp>

#include "render/renderer.hpp"
#include "scene_fixture.hpp"
#include "tracer.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

// The layers stored together, base first, then the layered material (as the builder stores them).
MaterialId add_layered(SceneDesc& s, const std::vector<MaterialDesc>& layers) {
  MaterialDesc m;
  m.layered = true;
  m.first_choice = static_cast<MaterialId>(s.materials.size());
  m.choice_count = static_cast<uint32_t>(layers.size());
  for (const MaterialDesc& l : layers) s.materials.push_back(l);
  m.transmit = layers.front().transmit;
  return add_material(s, m);
}

// A pattern texture whose colour map is `color` with transmit `t` everywhere.
TextureId add_uniform_map(SceneDesc& s, Color color, double t) {
  TextureDesc d;
  d.kind = TextureKind::Pattern;
  d.pattern.kind = PatternKind::Gradient;
  const glm::dvec3 c(color.r, color.g, color.b);
  d.pattern.color_map = {ColorMapEntry{0.0, c, t}, ColorMapEntry{1.0, c, t}};
  s.textures.push_back(d);
  return static_cast<TextureId>(s.textures.size() - 1);
}

Rgb straight_down(SceneDesc s) {
  Tracer t(std::move(s));
  return t.trace(Ray{Vec3(0.3, 1, 0.3), Vec3(0, -1, 0)});
}

}  // namespace

TEST_CASE("layers: a coat shows by its cover, the base through what it transmits", "[layers]") {
  SceneDesc s;
  MaterialDesc coat = emissive(Color(1, 0, 0));
  coat.transmit = Color(0.25);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_layered(s, {emissive(Color(0, 0, 1)), coat})));
  const Rgb c = straight_down(std::move(s));
  CHECK(c.x == Approx(0.75));
  CHECK(c.y == 0.0);
  CHECK(c.z == Approx(0.25));
}

TEST_CASE("layers: a colour map's transmit is the coat's, its colour the coat's colour", "[layers]") {
  auto scene = [](double t, bool layered) {
    SceneDesc s;
    LightDesc sun;
    sun.kind = LightKind::Directional;
    sun.direction = Vec3(0, -1, 0);
    place(s, add_light(s, sun));
    MaterialDesc base = emissive(Color(0, 0, 1));
    MaterialDesc coat;
    coat.ambient = 0.0;
    coat.diffuse = 1.0;
    coat.texture = add_uniform_map(s, Color(0, 1, 0), t);
    const MaterialId m = layered ? add_layered(s, {base, coat}) : add_material(s, coat);
    place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, m));
    return s;
  };
  // Opaque: the coat alone, lit as the same material placed on its own.
  const Rgb opaque = straight_down(scene(0.0, true));
  const Rgb alone = straight_down(scene(0.0, false));
  CHECK(opaque.x == 0.0);
  CHECK(opaque.y == Approx(alone.y));
  CHECK(opaque.y == Approx(1.0));
  CHECK(opaque.z == 0.0);
  // 60% clear: the coat's light by 0.4, the base's by 0.6.
  const Rgb part = straight_down(scene(0.6, true));
  CHECK(part.y == Approx(0.4));
  CHECK(part.z == Approx(0.6));
  // Fully clear: the base alone.
  const Rgb clear = straight_down(scene(1.0, true));
  CHECK(clear.y == 0.0);
  CHECK(clear.z == Approx(1.0));
}

TEST_CASE("layers: a clear coat's reflection is not weighted by its cover", "[layers]") {
  SceneDesc s;
  s.settings.background = Color(1, 0, 0);
  MaterialDesc varnish = emissive(Color(0.0));
  varnish.transmit = Color(1.0);
  varnish.reflect = Color(0.5);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_layered(s, {emissive(Color(0, 0, 1)), varnish})));
  const Rgb c = straight_down(std::move(s));
  CHECK(c.x == Approx(0.5));  // the red sky, mirrored at half weight
  CHECK(c.z == Approx(1.0));  // the base, whole below a clear coat
}

TEST_CASE("layers: a base that transmits lets light into the object; coats do not", "[layers]") {
  SceneDesc s;
  s.settings.background = Color(0, 1, 0);
  MaterialDesc clear = emissive(Color(0.0));
  clear.transmit = Color(1.0);
  MaterialDesc coat = emissive(Color(1, 0, 0));
  coat.transmit = Color(0.5);
  // A thin slab seen from above: the background below shows through the base, half of it
  // through the coat.
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_layered(s, {clear, coat})));
  Tracer t(std::move(s));
  CHECK(t.world->instance(0).transmissive);
  const Rgb c = t.trace(Ray{Vec3(0.3, 1, 0.3), Vec3(0, -1, 0)});
  CHECK(c.x == Approx(0.5));
  CHECK(c.y == Approx(0.5));
}

TEST_CASE("layers: path mode picks one layer per hit, with the Whitted sum's mean", "[layers][path]") {
  SceneDesc s = top_down_scene(32, 32, 4);
  s.settings.integrator = IntegratorKind::Path;
  MaterialDesc coat = emissive(Color(1, 0, 0));
  coat.transmit = Color(0.25);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_layered(s, {emissive(Color(0, 0, 1)), coat})));
  RenderOptions o;
  o.samples = 16;
  RenderResult r = render(s, o);
  double red = 0.0, blue = 0.0;
  for (int py = 0; py < 32; ++py)
    for (int px = 0; px < 32; ++px) {
      const float* p = r.color.at(px, py);
      // Each sample is the coat's red or the base's blue, whole.
      CHECK(p[0] + p[2] == Approx(1.0).margin(1e-5));
      red += p[0];
      blue += p[2];
    }
  // 16,384 picks of probability 0.75: the mean's standard deviation is 0.0034; 5 of them
  // (a false failure about once in 3.5 million runs for independent picks).
  CHECK(red / 1024.0 == Approx(0.75).margin(0.017));
  CHECK(blue / 1024.0 == Approx(0.25).margin(0.017));
}

TEST_CASE("layers: a material chosen by pattern may choose a layered one", "[layers]") {
  SceneDesc s;
  MaterialDesc coat = emissive(Color(1, 0, 0));
  coat.transmit = Color(0.25);
  const MaterialId layered = add_layered(s, {emissive(Color(0, 0, 1)), coat});
  // A checker of cells of side 1 choosing between them (the layered copy keeps naming its layers).
  const MaterialDesc layered_copy = s.materials[layered];
  const MaterialId chooser = add_chooser(s, add_checker(s), {layered_copy, emissive(Color(0, 1, 0))});
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, chooser));
  Tracer tr(std::move(s));
  const Rgb a = tr.trace(Ray{Vec3(0.5, 1, 0.5), Vec3(0, -1, 0)});
  const Rgb b = tr.trace(Ray{Vec3(1.5, 1, 0.5), Vec3(0, -1, 0)});
  const Rgb& layered_cell = a.y == 0.0 ? a : b;
  const Rgb& green_cell = a.y == 0.0 ? b : a;
  CHECK(layered_cell.x == Approx(0.75));
  CHECK(layered_cell.z == Approx(0.25));
  CHECK(green_cell == Rgb(0, 1, 0));
}
