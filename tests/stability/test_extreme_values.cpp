// Group 9, extreme values: light intensity 1e300 and 1e-300, color * intensity overflowing,
// attenuation reaching zero or overflowing, colors above 1, emission 1e30. No NaN or Inf in
// any pixel or AOV, no NaN sample, and no black where light should be (issue 8 failure 3:
// the overflowing power made 0 * inf = NaN samples, rendered black).
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "stability_support.hpp"

using namespace rts::render;
using namespace rts::stability;

namespace {

SceneDesc lit_scene(const LightDesc& light, const MaterialDesc& floor_material) {
  SceneDesc s;
  s.settings.width = 32;
  s.settings.height = 24;
  s.settings.samples = 2;
  s.has_camera = true;
  s.camera.position = Vec3(0, 2, -4);
  s.camera.look_at = Vec3(0, 0, 0);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, floor_material)));
  MaterialDesc shiny = matte(Color(0.8));
  shiny.reflect = Color(0.3);
  shiny.transmit = Color(0.5);
  shiny.ior = 1.5;
  shiny.fresnel = true;
  shiny.specular = 0.5;
  place(s, add_shape(s, Sphere{Vec3(0, 0.6, 0), 0.6}, add_material(s, shiny)));
  place(s, add_light(s, light));
  return s;
}

struct Figures {
  int non_finite = 0;
  uint64_t nan_samples = 0;
  int black = 0;
  double floor_value = 0;  // the floor in front of the sphere, linear red
};

Figures measure(const SceneDesc& s, const std::string& name, const std::string& file) {
  RenderResult r = render_scene(s, 2, true);
  Figures f;
  f.non_finite = count_non_finite(r.color);
  for (const auto& [aov, img] : r.aovs) f.non_finite += count_non_finite(img);
  f.nan_samples = r.stats.rays.nan_samples;
  f.black = count_black(r.color);
  f.floor_value = r.color.at(16, 21)[0];
  std::string img = save(r.color, file);
  record("extreme", name, "NaN/Inf pixels (color and AOVs)", f.non_finite, "0", img);
  record("extreme", name, "NaN samples", static_cast<double>(f.nan_samples), "0");
  record("extreme", name, "black pixels", f.black, "0");
  return f;
}

LightDesc point(double intensity, Color color = Color(1.0), Vec3 attenuation = Vec3(1, 0, 0)) {
  LightDesc l;
  l.position = Vec3(2, 4, -3);
  l.intensity = intensity;
  l.color = color;
  l.attenuation = attenuation;
  return l;
}

}  // namespace

TEST_CASE("overflowing light power saturates instead of becoming NaN", "[extreme]") {
  struct Case {
    const char* name;
    LightDesc light;
  } cases[] = {
      {"color 1e200 * intensity 1e200", point(1e200, Color(1e200))},
      {"intensity 1e300", point(1e300)},
      {"intensity 1e300, attenuation <0, 0, 1e-10>", point(1e300, Color(1.0), Vec3(0, 0, 1e-10))},
      {"attenuation <0, 0, 1e300> (reaches zero)", point(1.0, Color(1.0), Vec3(0, 0, 1e300))},
      {"attenuation <1e-300, 0, 0> (overflows)", point(1.0, Color(1.0), Vec3(1e-300, 0, 0))},
  };
  for (const Case& c : cases) {
    std::string file = "extreme_";
    for (const char* p = c.name; *p; ++p) file += std::isalnum(static_cast<unsigned char>(*p)) ? *p : '_';
    Figures f = measure(lit_scene(c.light, matte(Color(0.7))), c.name, file);
    CAPTURE(c.name);
    CHECK(f.non_finite == 0);
    CHECK(f.nan_samples == 0);
    CHECK(f.black == 0);  // ambient at least, everywhere
    if (c.light.intensity >= 1e200) CHECK(f.floor_value >= 1.0f);  // lit: saturated, not black
  }
}

TEST_CASE("tiny intensity, colors above 1 and emission 1e30 stay finite", "[extreme]") {
  Figures tiny = measure(lit_scene(point(1e-300), matte(Color(0.7))), "intensity 1e-300", "extreme_tiny");
  CHECK(tiny.non_finite == 0);
  CHECK(tiny.nan_samples == 0);
  CHECK(tiny.black == 0);

  MaterialDesc bright = matte(Color(1e10));
  bright.reflect = Color(3.0);  // reflections amplify: saturated, never inf
  Figures above = measure(lit_scene(point(1.0), bright), "color 1e10, reflect 3", "extreme_color");
  CHECK(above.non_finite == 0);
  CHECK(above.nan_samples == 0);

  MaterialDesc glow = emissive(Color(1e30));
  Figures emit = measure(lit_scene(point(1.0), glow), "emission 1e30", "extreme_emission");
  CHECK(emit.non_finite == 0);
  CHECK(emit.nan_samples == 0);
  CHECK(emit.floor_value >= 1.0f);
}
