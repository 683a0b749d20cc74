// Fog against closed forms: exponential attenuation exp(-s / distance) for constant fog, the
// integrated ground-fog profile, and the integrator's blend T·L + (1 − T)·fog_color along
// camera and reflected rays; and a scene without fog traced exactly as before.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "render/renderer.hpp"
#include "render/shade/fog.hpp"
#include "scene_fixture.hpp"
#include "tracer.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

TEST_CASE("constant fog transmits exp(-s / distance)", "[fog]") {
  Fog f{4.0, 0.0, 0.0};
  CHECK(f.transmittance(Vec3(0), Vec3(0, 0, 1), 4.0) == Approx(std::exp(-1.0)));
  CHECK(f.transmittance(Vec3(1, 2, 3), Vec3(0, 0, 1), 10.0) == Approx(std::exp(-2.5)));
  // t is in units of the direction: a direction of length 2 doubles the path.
  CHECK(f.transmittance(Vec3(0), Vec3(0, 2, 0), 3.0) == Approx(std::exp(-1.5)));
  CHECK(f.transmittance(Vec3(0), Vec3(0, 0, 1), kInf) == 0.0);
  CHECK(f.transmittance(Vec3(0), Vec3(0, 0, 1), 0.0) == 1.0);
}

TEST_CASE("ground fog: density 1 below the offset, 1/(1 + (h/altitude)^2) above (POV-Ray's)", "[fog]") {
  const double d = 2.0, off = 1.0, alt = 0.5;
  Fog f{d, off, alt};
  // Level rays: the density at their height times their length.
  CHECK(f.transmittance(Vec3(0, 0.5, 0), Vec3(1, 0, 0), 3.0) == Approx(std::exp(-3.0 / d)));
  CHECK(f.transmittance(Vec3(0, off + alt, 0), Vec3(1, 0, 0), 3.0) == Approx(std::exp(-3.0 * 0.5 / d)));
  // Straight up from the offset: the integral of 1/(1 + (h/alt)^2) from 0 to alt is
  // alt atan(1) = alt pi/4, and to infinity alt pi/2.
  const double quarter = alt * M_PI / 4;
  CHECK(f.transmittance(Vec3(0, off, 0), Vec3(0, 1, 0), alt) == Approx(std::exp(-quarter / d)));
  CHECK(f.transmittance(Vec3(0, off, 0), Vec3(0, 1, 0), kInf) == Approx(std::exp(-alt * M_PI / 2 / d)));
  // Down from the same point to 0.4 below the offset, then on into the ground for ever.
  CHECK(f.transmittance(Vec3(0, off + alt, 0), Vec3(0, -1, 0), alt + 0.4) ==
        Approx(std::exp(-(quarter + 0.4) / d)));
  CHECK(f.transmittance(Vec3(0, off + alt, 0), Vec3(0, -1, 0), kInf) == 0.0);
  // A slanted ray covers its height change over 1/sin of the length: at 30 degrees, twice.
  Vec3 up30(std::cos(M_PI / 6), 0.5, 0);
  CHECK(f.transmittance(Vec3(0, off, 0), up30, 2 * alt) == Approx(std::exp(-2 * quarter / d)));
  // Nearly level rays agree with level ones (no division blow-up).
  CHECK(f.transmittance(Vec3(0, 0.5, 0), Vec3(1, 1e-12, 0), 3.0) == Approx(std::exp(-3.0 / d)));
}

TEST_CASE("the integrator blends each ray segment with the fog colour", "[fog]") {
  // An emissive wall 5 units in front of the camera ray, constant fog of distance 2.5.
  SceneDesc s;
  s.settings.background = Color(0.1, 0.2, 0.3);
  MaterialDesc lamp = emissive(Color(1.0, 0.5, 0.25));
  place(s, add_shape(s, Plane{Vec3(0, 0, -1), -5.0}, add_material(s, lamp)));
  Ray towards{Vec3(0), Vec3(0, 0, 1)}, away{Vec3(0), Vec3(0, 0, -1)};
  const Rgb wall = Tracer(s).trace(towards);
  CHECK(wall.r == 1.0);  // without fog: the emission exactly
  CHECK(Tracer(s).trace(away).b == 0.3);

  s.settings.fog_distance = 2.5;
  s.settings.fog_color = Color(0.5, 0.6, 0.7);
  Tracer fogged(s);
  const double t = std::exp(-5.0 / 2.5);
  Rgb c = fogged.trace(towards);
  CHECK(c.r == Approx(t * 1.0 + (1 - t) * 0.5));
  CHECK(c.g == Approx(t * 0.5 + (1 - t) * 0.6));
  CHECK(c.b == Approx(t * 0.25 + (1 - t) * 0.7));
  // Rays that leave the scene travel through infinite fog: the fog colour alone.
  Rgb sky = fogged.trace(away);
  CHECK(sky.r == Approx(0.5));
  CHECK(sky.b == Approx(0.7));
}

TEST_CASE("reflected light crosses the fog of both segments", "[fog]") {
  // A black mirror at z = 2 facing the camera (at the origin looking at +z), an emissive wall
  // behind the camera at z = -3: the camera ray's segment is 2 long, the reflected one 5.
  SceneDesc s;
  MaterialDesc mirror;
  mirror.color = Color(0.0);
  mirror.ambient = 0.0;
  mirror.diffuse = 0.0;
  mirror.reflect = Color(1.0);
  place(s, add_shape(s, Plane{Vec3(0, 0, -1), -2.0}, add_material(s, mirror)));
  place(s, add_shape(s, Plane{Vec3(0, 0, 1), -3.0}, add_material(s, emissive(Color(1.0)))));
  s.settings.fog_distance = 3.5;
  s.settings.fog_color = Color(0.0);
  Rgb c = Tracer(s).trace(Ray{Vec3(0), Vec3(0, 0, 1)});
  CHECK(c.r == Approx(std::exp(-7.0 / 3.5)));
  // A grey fog: the wall's light is blended on the reflected segment, that result again on the
  // camera's segment.
  s.settings.fog_color = Color(0.5);
  c = Tracer(s).trace(Ray{Vec3(0), Vec3(0, 0, 1)});
  const double t1 = std::exp(-2.0 / 3.5), t2 = std::exp(-5.0 / 3.5);
  CHECK(c.r == Approx(t1 * (t2 * 1.0 + (1 - t2) * 0.5) + (1 - t1) * 0.5));
}

TEST_CASE("path mode: fog blends every path segment, and dims what shadow rays bring", "[fog]") {
  // The same closed forms as the Whitted integrator's, through the path tracer: an emissive
  // wall 5 units away seen through fog of distance 2.5 (no lights: nothing is random).
  auto render_centre = [](SceneDesc s) {
    s.settings.width = s.settings.height = 4;
    s.settings.integrator = IntegratorKind::Path;
    s.has_camera = true;
    s.camera.projection = Projection::Orthographic;
    s.camera.view_width = 0.1;
    s.camera.position = Vec3(0);
    s.camera.look_at = Vec3(0, 0, 1);
    RenderOptions o;
    o.threads = 1;
    const RenderResult r = render(s, o);
    return Rgb(r.color.rgb[0], r.color.rgb[1], r.color.rgb[2]);
  };
  SceneDesc s;
  place(s, add_shape(s, Plane{Vec3(0, 0, -1), -5.0}, add_material(s, emissive(Color(1.0, 0.5, 0.25)))));
  s.settings.fog_distance = 2.5;
  s.settings.fog_color = Color(0.5, 0.6, 0.7);
  const double t = std::exp(-5.0 / 2.5);
  const Rgb c = render_centre(s);
  CHECK(c.r == Approx(t * 1.0 + (1 - t) * 0.5).epsilon(1e-6));
  CHECK(c.g == Approx(t * 0.5 + (1 - t) * 0.6).epsilon(1e-6));
  CHECK(c.b == Approx(t * 0.25 + (1 - t) * 0.7).epsilon(1e-6));

  // A mirror 2 away and the wall 3 behind the camera: both segments, 7 in all.
  SceneDesc m;
  MaterialDesc mirror;
  mirror.color = Color(0.0);
  mirror.diffuse = 0.0;
  mirror.reflect = Color(1.0);
  place(m, add_shape(m, Plane{Vec3(0, 0, -1), -2.0}, add_material(m, mirror)));
  place(m, add_shape(m, Plane{Vec3(0, 0, 1), -3.0}, add_material(m, emissive(Color(1.0)))));
  m.settings.fog_distance = 3.5;
  CHECK(render_centre(m).r == Approx(std::exp(-7.0 / 3.5)).epsilon(1e-6));

  // A directional light through constant fog comes from infinitely far: nothing is left of it.
  SceneDesc lit;
  MaterialDesc white;
  white.color = Color(1.0);
  white.diffuse = 1.0;
  place(lit, add_shape(lit, Plane{Vec3(0, 0, -1), -5.0}, add_material(lit, white)));
  LightDesc sun;
  sun.kind = LightKind::Directional;
  sun.direction = Vec3(0, 0, 1);
  place(lit, add_light(lit, sun));
  CHECK(render_centre(lit).r > 0.1);
  lit.settings.fog_distance = 100.0;
  CHECK(render_centre(lit).r == 0.0);
}

TEST_CASE("turbulent fog thins each segment by POV-Ray's turbulence at its middle", "[fog]") {
  Fog f{4.0, 0.0, 0.0, Vec3(0.5, 1.0, 2.0), 0.7, 1, 0.5, 2.0};
  const Vec3 o(0.3, -1.2, 2.5), d(0, 0, 2);  // t in units of d: a segment of 2 t
  for (double t : {0.1, 1.0, 3.0, 40.0}) {
    const double s = 2 * t;
    // One octave: the noise at the segment's middle, scaled by the turbulence vector.
    const Vec3 middle = (o + 0.5 * t * d) * Vec3(0.5, 1.0, 2.0);
    const double factor = 1.0 - std::exp(-s / 4.0) * std::min(1.0, pattern::noise01(middle) * 0.7);
    INFO("t = " << t << ", factor " << factor);
    CHECK(factor >= 1.0 - std::exp(-s / 4.0));
    CHECK(factor <= 1.0);
    CHECK(f.transmittance(o, d, t) == Approx(std::exp(-s / 4.0 * factor)).epsilon(1e-12));
  }
  // A ray to infinity is not thinned; neither is any segment without turbulence or depth.
  CHECK(f.transmittance(o, d, kInf) == 0.0);
  Fog calm = f;
  calm.turb_depth = 0.0;
  CHECK(calm.transmittance(o, d, 1.0) == Approx(std::exp(-0.5)).epsilon(1e-15));
  calm = f;
  calm.turbulence = Vec3(0.0);
  CHECK(calm.transmittance(o, d, 1.0) == std::exp(-2.0 / 4.0));
  // Octaves add omega^i noise01(lambda^i p): with 3 octaves the sum is read at p, 2p and 4p.
  Fog three = f;
  three.octaves = 3;
  const Vec3 m = (o + 0.5 * d) * Vec3(0.5, 1.0, 2.0);
  const double sum = pattern::noise01(m) + 0.5 * pattern::noise01(2.0 * m) + 0.25 * pattern::noise01(4.0 * m);
  CHECK(three.thinning(o + 0.5 * d, 2.0) == Approx(1.0 - std::exp(-0.5) * std::min(1.0, sum * 0.7)).epsilon(1e-15));
}
