// Materials chosen by pattern (MaterialDesc::choice_pattern): which choice a luminance picks,
// what camera rays see per checker cell in both integrators, and shadows through the cells of
// a chooser whose choices differ in transmission.
#include <catch2/catch.hpp>

#include "render/renderer.hpp"
#include "render/shade/shading.hpp"
#include "scene_fixture.hpp"
#include "tracer.hpp"

using namespace rts::render;
using namespace rts::render::test;


TEST_CASE("material choice: equal ranges of the luminance, the first for the darkest", "[patterns]") {
  CHECK(choice_for(0.0, 2) == 0);
  CHECK(choice_for(0.49, 2) == 0);
  CHECK(choice_for(0.5, 2) == 1);
  CHECK(choice_for(1.0, 2) == 1);
  CHECK(choice_for(7.0, 3) == 2);   // above 1: the last
  CHECK(choice_for(-1.0, 3) == 0);  // below 0, and NaN: the first
  CHECK(choice_for(std::nan(""), 3) == 0);
  CHECK(choice_for(0.34, 3) == 1);
}

TEST_CASE("material choice: each checker cell shows its own material", "[patterns]") {
  for (IntegratorKind integrator : {IntegratorKind::Whitted, IntegratorKind::Path}) {
    SceneDesc s = top_down_scene(32, 32, 4);
    s.settings.integrator = integrator;
    const MaterialId tiles = add_chooser(s, add_checker(s), {emissive(Color(1, 0, 0)), emissive(Color(0, 0, 1))});
    place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, tiles));
    RenderOptions o;
    o.samples = 4;
    RenderResult r = render(s, o);
    // One unit is 8 pixels; the view spans x, z in [-2, 2]. A pixel a cell's width from
    // another shows the other material, and each is exactly one of the two.
    for (int py = 2; py < 32; py += 8)
      for (int px = 2; px < 32; px += 8) {
        const float* a = r.color.at(px, py);
        const float* b = r.color.at(px + 8 < 32 ? px + 8 : px - 8, py);
        INFO("integrator " << static_cast<int>(integrator) << " pixel " << px << ", " << py);
        CHECK(a[1] == 0.0f);
        CHECK(((a[0] == 1.0f && a[2] == 0.0f) || (a[0] == 0.0f && a[2] == 1.0f)));
        CHECK(a[0] != b[0]);
      }
  }
}

TEST_CASE("material choice: shadows pass the cells whose choice transmits", "[patterns]") {
  SceneDesc s;
  LightDesc sun;
  sun.kind = LightKind::Directional;
  sun.direction = Vec3(0, -1, 0);
  place(s, add_light(s, sun));
  MaterialDesc floor;
  floor.color = Color(1.0);
  floor.diffuse = 1.0;
  floor.ambient = 0.0;
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, floor)));
  MaterialDesc opaque = emissive(Color(0.0)), clear = emissive(Color(0.0));
  clear.transmit = Color(1.0);
  // A plane at y = 1 whose cells are opaque where the checker is black, clear where white.
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 1.0}, add_chooser(s, add_checker(s), {opaque, clear})));
  Tracer t(std::move(s));
  CHECK(t.world->instance(1).transmissive);  // a choice transmits: shadow rays must look
  // Straight down from between the planes: the shadow ray meets y = 1 at cell (0, 1, 0), odd
  // (white: clear), or at (1, 1, 0), even (black: opaque).
  const Rgb lit = t.trace(Ray{Vec3(0.5, 0.5, 0.5), Vec3(0, -1, 0)});
  const Rgb dark = t.trace(Ray{Vec3(1.5, 0.5, 0.5), Vec3(0, -1, 0)});
  CHECK(lit.x == Approx(1.0));
  CHECK(dark.x == 0.0);
}

TEST_CASE("material choice: a choice chosen by pattern chooses again", "[patterns]") {
  SceneDesc s;
  const TextureId fine = add_checker(s);  // cells of 1
  TextureDesc coarse_desc = s.textures[fine];
  coarse_desc.scale = 2.0;
  s.textures.push_back(coarse_desc);
  const TextureId coarse = static_cast<TextureId>(s.textures.size() - 1);
  const MaterialId inner = add_chooser(s, fine, {emissive(Color(1, 0, 0)), emissive(Color(0, 0, 1))});
  // As the builder stores it: the outer chooser's choices are copies, the inner one still
  // naming its own choices.
  MaterialDesc inner_copy = s.materials[inner];
  const MaterialId outer = add_chooser(s, coarse, {inner_copy, emissive(Color(0, 1, 0))});
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, outer));
  Tracer t(std::move(s));
  auto seen = [&](double x) { return t.trace(Ray{Vec3(x, 1, 0.5), Vec3(0, -1, 0)}); };
  CHECK(seen(0.5) == Rgb(1, 0, 0));  // coarse cell 0 (black: the inner checker), fine cell 0
  CHECK(seen(1.5) == Rgb(0, 0, 1));  // coarse cell 0, fine cell 1
  CHECK(seen(2.5) == Rgb(0, 1, 0));  // coarse cell 1: white, green
}
