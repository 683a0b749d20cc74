// The path tracer (render/shade/path/) against closed-form answers: white furnaces, a closed
// lossless world under a uniform sky, and each light kind's documented unit; then determinism
// across thread counts and finite results on degenerate scenes.
//
// Statistical checks: every pixel of these images has the same expected value, so the image
// mean's standard error is the spread of the pixels over sqrt(pixels). A check allows 5
// standard errors (plus 1e-4 relative, as the plane seen is not quite one point): for a
// normal mean that fails by chance with probability 5.7e-7 (the
// renders are seeded, so a given build passes or fails every time).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "render/image/float_image_io.hpp"
#include "render/image/image.hpp"
#include "render/renderer.hpp"
#include "render/sample/camera.hpp"
#include "render/sample/sampler.hpp"
#include "render/shade/texture.hpp"
#include "render/accel/world.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/path/light_set.hpp"
#include "render/shade/path/sky_distribution.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

constexpr double kSigmas = 5.0;

struct Measured {
  double mean = 0, standard_error = 0;   // channel 0 (the scenes here are grey)
  RenderResult result;
};

Measured render_path(SceneDesc s, int size, int spp, int threads = 2) {
  s.settings.width = s.settings.height = size;
  s.settings.samples = spp;
  s.settings.integrator = IntegratorKind::Path;
  RenderOptions o;
  o.threads = threads;
  Measured m;
  m.result = render(s, o);
  const std::vector<float>& rgb = m.result.color.rgb;
  const double n = static_cast<double>(rgb.size() / 3);
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    sum += rgb[i];
    sum2 += static_cast<double>(rgb[i]) * rgb[i];
  }
  m.mean = sum / n;
  double var = std::max(0.0, (sum2 / n - m.mean * m.mean) * n / (n - 1));
  m.standard_error = std::sqrt(var / n);
  return m;
}

void check_within_noise(const Measured& m, double expected) {
  INFO("mean " << m.mean << " expected " << expected << " standard error " << m.standard_error);
  CHECK(m.result.stats.rays.nan_samples == 0);
  CHECK(std::abs(m.mean - expected) <= kSigmas * m.standard_error + 1e-4 * expected);
}

MaterialDesc lambert(double albedo) {
  MaterialDesc m;
  m.color = Color(albedo);
  m.diffuse = 1;
  m.ambient = 0;
  return m;
}

// An orthographic camera looking straight down at the origin through a view `width` wide.
void look_down(SceneDesc& s, double width, double height = 5) {
  s.has_camera = true;
  s.camera.projection = Projection::Orthographic;
  s.camera.view_width = width;
  s.camera.position = Vec3(0, height, 0);
  s.camera.look_at = Vec3(0, 0, 0);
  s.camera.up = Vec3(0, 0, 1);
}

}  // namespace

TEST_CASE("white furnace: inside a closed sphere of albedo a and emission e, L = e / (1 - a)", "[path]") {
  const double e = 0.5;
  for (double a : {0.5, 0.9, 0.99}) {
    SceneDesc s;
    s.has_camera = true;
    s.camera.position = Vec3(0.1, -0.2, 0.05);
    s.camera.look_at = Vec3(1, 0.3, 0.2);
    s.settings.max_depth = 10000;   // Russian roulette ends the paths, unbiased
    MaterialDesc m = lambert(a);
    m.emission = Color(e);
    place(s, add_shape(s, Sphere{Vec3(0), 1.0}, add_material(s, m)));
    Measured got = render_path(s, 16, 32);
    INFO("albedo " << a);
    check_within_noise(got, e / (1.0 - a));
  }
}

TEST_CASE("lossless surfaces under a uniform sky keep its radiance; lossy ones never add to it", "[path]") {
  auto sky_scene = [](const MaterialDesc& m) {
    SceneDesc s;
    s.settings.background = Color(1.0);
    s.settings.max_depth = 64;
    look_down(s, 0.8);
    place(s, add_shape(s, Sphere{Vec3(0), 1.0}, add_material(s, m)));
    return s;
  };
  SECTION("Lambert: a times the sky") { check_within_noise(render_path(sky_scene(lambert(0.8)), 8, 16), 0.8); }
  SECTION("a clear dielectric (Fresnel, refraction, total internal reflection) loses nothing") {
    MaterialDesc glass = lambert(0.0);
    glass.diffuse = 0;
    glass.transmit = Color(1.0);
    glass.ior = 1.5;
    check_within_noise(render_path(sky_scene(glass), 8, 16), 1.0);
  }
  SECTION("rough glass (GGX reflection and transmission) loses some light, never gains") {
    MaterialDesc frosted = lambert(0.0);
    frosted.diffuse = 0;
    frosted.transmit = Color(1.0);
    frosted.ior = 1.5;
    frosted.roughness = 0.3;
    Measured g = render_path(sky_scene(frosted), 8, 64);
    INFO("rough glass under a uniform sky: mean " << g.mean << " +- " << g.standard_error);
    CHECK(g.result.stats.rays.nan_samples == 0);
    CHECK(g.mean <= 1.0 + kSigmas * g.standard_error);
    // Single scattering: a ray refracted or reflected by a facet into the macro surface is
    // lost, at every one of the bounces inside the ball (0.855 at alpha 0.3 when written).
    CHECK(g.mean > 0.8);
  }
  SECTION("a perfect mirror, and a conductor with Fresnel of reflectance 1") {
    MaterialDesc mirror = lambert(0.0);
    mirror.diffuse = 0;
    mirror.reflect = Color(1.0);
    check_within_noise(render_path(sky_scene(mirror), 4, 4), 1.0);
    mirror.fresnel = true;
    check_within_noise(render_path(sky_scene(mirror), 4, 4), 1.0);
  }
  SECTION("microfacet lobes lose some light (single scattering: 31% at alpha 0.5), never gain") {
    MaterialDesc glossy = lambert(0.0);
    glossy.diffuse = 0;
    glossy.specular = 1.0;
    glossy.shininess = 32;
    Measured g = render_path(sky_scene(glossy), 8, 16);
    CHECK(g.mean <= 1.0 + kSigmas * g.standard_error);
    CHECK(g.mean > 0.9);
    MaterialDesc rough = lambert(0.0);
    rough.diffuse = 0;
    rough.reflect = Color(1.0);
    rough.roughness = 0.5;
    Measured r = render_path(sky_scene(rough), 8, 16);
    CHECK(r.mean <= 1.0 + kSigmas * r.standard_error);
    CHECK(r.mean > 0.6);
  }
}

TEST_CASE("a patterned Lambert sphere under a uniform sky converges to its pattern, pixel by pixel", "[path]") {
  // A convex Lambert surface under a sky of radiance 1 sees only the sky, so its radiance is
  // its albedo: a marble pattern's color map value at the point. Each pixel's expected value is
  // the pattern averaged over the pixel (an 8x8 grid of camera rays, intersected with the
  // sphere here); the residuals (image - expected) have mean 0 if path mode converges to the
  // pattern, and the check allows 5 standard errors of their mean (false-failure rate 5.7e-7
  // for a normal mean, as above). That the image follows the pattern pixel by pixel, not only
  // on average, is checked by the residuals' spread against the pattern's own.
  SceneDesc s;
  s.settings.background = Color(1.0);
  s.settings.max_depth = 8;
  look_down(s, 1.2);
  TextureDesc marble;
  marble.kind = TextureKind::Pattern;
  marble.pattern.kind = PatternKind::Marble;
  marble.pattern.wave = WaveKind::Triangle;
  marble.pattern.turbulence = Vec3(0.8);
  marble.pattern.color_map = {{0.0, {0.9, 0.9, 0.9}}, {0.7, {0.6, 0.6, 0.6}}, {1.0, {0.1, 0.1, 0.1}}};
  marble.transform = glm::scale(Mat4(1.0), Vec3(0.3));
  s.textures.push_back(marble);
  MaterialDesc m = lambert(1.0);
  m.diffuse_texture = 0;
  place(s, add_shape(s, Sphere{Vec3(0), 1.0}, add_material(s, m)));

  constexpr int kSize = 48;
  const Measured measured = render_path(s, kSize, 16);
  REQUIRE(measured.result.stats.rays.nan_samples == 0);
  const Camera camera(s.camera, kSize, kSize);
  const CompiledTexture texture(marble, nullptr);
  const std::vector<float>& rgb = measured.result.color.rgb;
  double sum = 0, sum2 = 0, e_sum = 0, e_sum2 = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      double expected = 0;
      for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
          const Ray r = camera.generate(x + (i + 0.5) / 8, y + (j + 0.5) / 8, glm::dvec2(0.5));
          // The unit sphere at the origin: |o + t d|^2 = 1, the nearer root (every ray of this
          // 1.2-wide view from above hits it).
          const double b = glm::dot(r.origin, r.direction), c = glm::dot(r.origin, r.origin) - 1.0;
          const double a = glm::dot(r.direction, r.direction);
          const double t = (-b - std::sqrt(b * b - a * c)) / a;
          TexturePoint p;
          p.object_point = r.origin + t * r.direction;
          expected += texture.eval(p).r / 64.0;
        }
      }
      const double residual = rgb[(static_cast<std::size_t>(y) * kSize + x) * 3] - expected;
      sum += residual;
      sum2 += residual * residual;
      e_sum += expected;
      e_sum2 += expected * expected;
    }
  }
  const double n = kSize * kSize;
  const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
  const double pattern_mean = e_sum / n, pattern_sd = std::sqrt(std::max(0.0, e_sum2 / n - pattern_mean * pattern_mean));
  const double residual_rms = std::sqrt(sum2 / n);
  INFO("mean residual " << mean << " standard error " << se << "; residual rms " << residual_rms
                        << ", pattern mean " << pattern_mean << " sd " << pattern_sd);
  CHECK(std::abs(mean) <= kSigmas * se + 1e-4 * pattern_mean);
  CHECK(pattern_sd > 0.1);                    // the view holds veins and background
  // and the image draws them where they are: the residuals (16 samples' noise over veins that
  // cross a pixel, 0.024 here) are a fraction of the pattern's own spread, which a surface
  // ignoring its pattern would leave whole.
  CHECK(residual_rms < 0.25 * pattern_sd);
}

TEST_CASE("a bumps-mapped Lambert plane under a sky and a sun shades each point by its tilted normal", "[path]") {
  // A Lambert plane (albedo a) with a `bumps` bump map, seen straight down, under a uniform sky
  // of radiance 1 and a directional light of irradiance E from 45 degrees. The bump tilts the
  // shading normal n_s by theta from the true normal n_g (docs/rendering.md: n_s =
  // normalize(n_g - bump_scale * grad h), h the pattern's luminance); the path integrator
  // samples the cosine lobe about n_s but the surface reflects nothing from below its true
  // plane (the part of the lobe under the horizon is lost). So a tilted facet sees the sky as a
  // tilted plane does: the cosine-weighted share of its lobe above the horizon is (1 + cos
  // theta) / 2 (the lobe projects to the unit disk; the horizon cuts out an ellipse's half of
  // axes cos theta and 1), and the sun by Lambert's law on the tilted normal:
  //   L = a (1 + n_s . n_g) / 2 + a / pi * E * max(0, n_s . l).
  // A flat plane gives the constant a + a / pi * E * cos 45. The expected image is that L
  // averaged over each pixel (8x8 points), with grad h by central differences of the pattern
  // itself, independent of the renderer's bump code; the residuals' mean must be within 5
  // standard errors of 0 (false-failure rate 5.7e-7, as above) and their RMS a fraction of the
  // bumped image's own spread, which an unbumped (or wrongly bumped) render would leave whole.
  // Measured at 48x48, 128 spp: mean residual 1.4e-4 against a standard error of 1.7e-4, RMS
  // 0.0084 against the expected image's spread 0.059; ignoring the bump gives a mean residual
  // of 0.038 and an RMS of 0.071, flipping the slope's sign an RMS of 0.11.
  const double a = 0.7, E = 1.5, bump_scale = 0.2;
  const Vec3 to_sun = glm::normalize(Vec3(0, 1, 1));
  auto scene = [&](bool bumped) {
    SceneDesc s;
    s.settings.background = Color(1.0);
    s.settings.max_depth = 8;
    look_down(s, 2.0);
    TextureDesc bumps;
    bumps.kind = TextureKind::Pattern;
    bumps.pattern.kind = PatternKind::Bumps;
    bumps.pattern.color_map = {{0.0, {0, 0, 0}}, {1.0, {1, 1, 1}}};
    bumps.transform = glm::scale(Mat4(1.0), Vec3(0.25));
    s.textures.push_back(bumps);
    MaterialDesc m = lambert(a);
    if (bumped) {
      m.bump = 0;
      m.bump_scale = bump_scale;
    }
    place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, m)));
    LightDesc sun;
    sun.kind = LightKind::Directional;
    sun.direction = -to_sun;
    sun.intensity = E;
    place(s, add_light(s, sun));
    return s;
  };
  const double flat_value = a + a / std::numbers::pi * E * to_sun.y;

  constexpr int kSize = 48;
  const SceneDesc bumped_scene = scene(true);
  const Measured flat = render_path(scene(false), kSize, 128);
  const Measured bumped = render_path(bumped_scene, kSize, 128);
  REQUIRE(bumped.result.stats.rays.nan_samples == 0);
  check_within_noise(flat, flat_value);   // the same plane unbumped: the constant

  const Camera camera(bumped_scene.camera, kSize, kSize);
  const CompiledTexture texture(bumped_scene.textures[0], nullptr);
  auto height = [&](double x, double z) {
    TexturePoint p;
    p.object_point = Vec3(x, 0, z);
    const Color c = texture.eval(p);
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
  };
  const std::vector<float>& rgb = bumped.result.color.rgb;
  double sum = 0, sum2 = 0, e_sum = 0, e_sum2 = 0, tilt_max = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      double expected = 0;
      for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
          const Ray r = camera.generate(x + (i + 0.5) / 8, y + (j + 0.5) / 8, glm::dvec2(0.5));
          const Vec3 q = r.origin + (-r.origin.y / r.direction.y) * r.direction;   // on y = 0
          const double d = 1e-5;
          const double hx = (height(q.x + d, q.z) - height(q.x - d, q.z)) / (2 * d);
          const double hz = (height(q.x, q.z + d) - height(q.x, q.z - d)) / (2 * d);
          const Vec3 ns = glm::normalize(Vec3(-bump_scale * hx, 1.0, -bump_scale * hz));
          tilt_max = std::max(tilt_max, std::acos(ns.y));
          expected += (a * (1 + ns.y) / 2 + a / std::numbers::pi * E * std::max(0.0, glm::dot(ns, to_sun))) / 64.0;
        }
      }
      const double residual = rgb[(static_cast<std::size_t>(y) * kSize + x) * 3] - expected;
      sum += residual;
      sum2 += residual * residual;
      e_sum += expected;
      e_sum2 += expected * expected;
    }
  }
  const double n = kSize * kSize;
  const double mean = sum / n, se = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
  const double expected_mean = e_sum / n, expected_sd = std::sqrt(std::max(0.0, e_sum2 / n - expected_mean * expected_mean));
  const double residual_rms = std::sqrt(sum2 / n);
  INFO("mean residual " << mean << " standard error " << se << "; residual rms " << residual_rms << ", expected mean "
                        << expected_mean << " sd " << expected_sd << "; flat " << flat.mean << " (" << flat_value
                        << "), bumped " << bumped.mean << "; largest tilt " << tilt_max << " rad");
  CHECK(std::abs(mean) <= kSigmas * se + 1e-4 * expected_mean);
  CHECK(tilt_max < 1.2);   // well above the grazing cut-off: the frame is n_s everywhere
  // The bumps matter: the expected image varies from pixel to pixel, the render follows it,
  // and it is darker than flat (the sky's lost sliver) by more than both renders' noise.
  CHECK(expected_sd > 0.03);
  CHECK(residual_rms < 0.25 * expected_sd);
  CHECK(flat.mean - bumped.mean > kSigmas * std::hypot(flat.standard_error, bumped.standard_error));
}

TEST_CASE("light units: point intensity / d^2, directional irradiance, emitters' radiance", "[path]") {
  const double a = 0.6;
  auto floor_scene = [&]() {
    SceneDesc s;
    s.settings.max_depth = 4;
    look_down(s, 0.01, 0.5);   // every pixel sees (nearly) the origin, from below the lights
    place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, lambert(a))));
    return s;
  };
  SECTION("point light: L = a / pi * I / h^2") {
    SceneDesc s = floor_scene();
    LightDesc l;
    l.position = Vec3(0, 2, 0);
    l.intensity = 8;
    place(s, add_light(s, l));
    check_within_noise(render_path(s, 4, 4), a / std::numbers::pi * 8 / 4);
  }
  SECTION("light_falloff = attenuation: POV-Ray's lights, L = a / pi * I / (c + l h + q h^2)") {
    for (double h : {2.0, 5.0}) {
      SceneDesc s = floor_scene();
      s.settings.light_falloff_attenuation = true;
      LightDesc l;
      l.position = Vec3(0, h, 0);
      l.intensity = 8;   // attenuation <1, 0, 0>, the default: no falloff at all
      place(s, add_light(s, l));
      check_within_noise(render_path(s, 4, 4), a / std::numbers::pi * 8);
      SceneDesc q = floor_scene();
      q.settings.light_falloff_attenuation = true;
      l.attenuation = Vec3(0.5, 0, 0.5);   // POV-Ray's fade_power 2, fade_distance 1
      place(q, add_light(q, l));
      check_within_noise(render_path(q, 4, 4), a / std::numbers::pi * 8 / (0.5 + 0.5 * h * h));
      SceneDesc r = floor_scene();
      r.settings.light_falloff_attenuation = true;
      LightDesc area;
      area.kind = LightKind::Area;
      area.position = Vec3(0, h, 0);
      area.u = Vec3(0.01, 0, 0);
      area.v = Vec3(0, 0, 0.01);
      area.intensity = 9;   // each point of it the whole power, as Whitted's area light
      place(r, add_light(r, area));
      check_within_noise(render_path(r, 4, 4), a / std::numbers::pi * 9);
    }
  }
  SECTION("directional light: L = a / pi * E cos") {
    SceneDesc s = floor_scene();
    LightDesc l;
    l.kind = LightKind::Directional;
    l.direction = Vec3(0, -1, -1);
    l.intensity = 3;
    place(s, add_light(s, l));
    check_within_noise(render_path(s, 4, 4), a / std::numbers::pi * 3 * std::sqrt(0.5));
  }
  SECTION("area_light: a two-sided emitter of the point light's power, 2 I / h^2 straight below") {
    SceneDesc s = floor_scene();
    LightDesc l;
    l.kind = LightKind::Area;
    l.position = Vec3(0, 3, 0);
    l.u = Vec3(0.01, 0, 0);
    l.v = Vec3(0, 0, 0.01);
    l.intensity = 9;
    place(s, add_light(s, l));
    check_within_noise(render_path(s, 4, 4), a / std::numbers::pi * 2 * 9 / 9);
  }
  SECTION("an emissive quad filling the sky: L = a Le (NEE by area, MIS with the BSDF)") {
    SceneDesc s = floor_scene();
    MaterialDesc lamp = lambert(0.0);
    lamp.diffuse = 0;
    lamp.emission = Color(2.0);
    place(s, add_shape(s, Quad{Vec3(-1e4, 1, -1e4), Vec3(2e4, 0, 0), Vec3(0, 0, 2e4)}, add_material(s, lamp)));
    check_within_noise(render_path(s, 8, 16), a * 2.0);
  }
  // A rectangle of half-sides (x, z) centred a height h above the point: its form factor is
  // four times that of an x by z rectangle above one corner (Howell's catalogue, C-11).
  auto rect_form_factor = [](double x, double z, double h) {
    double a = x / h, b = z / h, sa = std::sqrt(1 + a * a), sb = std::sqrt(1 + b * b);
    return 4.0 / (2.0 * std::numbers::pi) * (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb));
  };
  SECTION("an emissive rectangle: L = a Le F (NEE by solid angle, MIS with the BSDF)") {
    SceneDesc s = floor_scene();
    MaterialDesc lamp = lambert(0.0);
    lamp.diffuse = 0;
    lamp.emission = Color(3.0);
    place(s, add_shape(s, Quad{Vec3(-0.5, 1, -0.3), Vec3(1.0, 0, 0), Vec3(0, 0, 0.6)}, add_material(s, lamp)));
    check_within_noise(render_path(s, 8, 16), a * 3.0 * rect_form_factor(0.5, 0.3, 1.0));
  }
  SECTION("a ceiling lamp seen at grazing emission angles from the wall below it: L = a / pi * the irradiance integral") {
    // The Cornell box's back wall just under the ceiling, lit by a lamp flush with it (the
    // strip where Cycles 3.4's direct light is 0.7-16% darker: docs/path-tracing.md): each point
    // of the lamp is seen within a few degrees of its plane. Expected: the irradiance
    // integral over the lamp by the midpoint rule (400 x 400, converged far below the noise).
    const double le = 5.0;
    for (double depth : {0.01, 0.05, 0.15}) {
      CAPTURE(depth);
      SceneDesc s;
      s.has_camera = true;
      s.camera.projection = Projection::Orthographic;
      s.camera.view_width = 1e-7;  // (nearly) one point of the wall, `depth` below the ceiling
      s.camera.position = Vec3(0.1, 2 - depth, 0.5);
      s.camera.look_at = Vec3(0.1, 2 - depth, 1);
      s.camera.up = Vec3(0, 1, 0);
      place(s, add_shape(s, Quad{Vec3(-1, 0, 1), Vec3(2, 0, 0), Vec3(0, 2, 0)}, add_material(s, lambert(a))));
      MaterialDesc lamp = lambert(0.0);
      lamp.diffuse = 0;
      lamp.emission = Color(le);
      place(s, add_shape(s, Quad{Vec3(-0.25, 2, -0.2), Vec3(0.5, 0, 0), Vec3(0, 0, 0.4)}, add_material(s, lamp)));
      constexpr int kSteps = 400;
      const Vec3 p(0.1, 2 - depth, 1);
      double irradiance = 0;
      for (int i = 0; i < kSteps; ++i)
        for (int j = 0; j < kSteps; ++j) {
          const Vec3 q(-0.25 + (i + 0.5) * 0.5 / kSteps, 2, -0.2 + (j + 0.5) * 0.4 / kSteps);
          const Vec3 d = q - p;
          const double r2 = glm::dot(d, d);
          // cos at the wall (normal -z) times cos at the lamp (normal -y), over r^2.
          irradiance += (-d.z) * d.y / (r2 * r2) * (0.5 / kSteps) * (0.4 / kSteps);
        }
      check_within_noise(render_path(s, 4, 256), a / std::numbers::pi * le * irradiance);
    }
  }
  SECTION("a textured emissive rectangle: NEE reads the texture at each sampled point") {
    // A checker of radiance 1 and 5 whose cells meet under the lit point: each quarter of the
    // rectangle is a quarter of its form factor, so L = a 3 F, as for a plain Le of 3.
    SceneDesc s = floor_scene();
    TextureDesc checker;
    checker.kind = TextureKind::Checker;
    checker.color1 = Color(1.0);
    checker.color2 = Color(5.0);
    checker.scale = 10;
    s.textures.push_back(checker);
    MaterialDesc lamp = lambert(0.0);
    lamp.diffuse = 0;
    lamp.emission_texture = 0;
    place(s, add_shape(s, Quad{Vec3(-0.5, 1, -0.3), Vec3(1.0, 0, 0), Vec3(0, 0, 0.6)}, add_material(s, lamp)));
    Measured m = render_path(s, 16, 16);
    check_within_noise(m, a * 3.0 * rect_form_factor(0.5, 0.3, 1.0));
    FlatScene flat = flatten_scene(s);
    World world(s, flat);
    std::vector<CompiledTexture> textures;
    textures.emplace_back(checker, nullptr);
    path::LightSet set(world, s, {}, textures);
    CHECK(set.unsampled_emitters() == 0);   // sampled by NEE, not left to bounced rays
    CHECK(set.has_shape_emitters());
  }
  SECTION("an image mapped by uv on an emissive quad, sphere and mesh: NEE reads it at the sampled point's uv") {
    // Two texels, radiance 1 where u < 1/2 and 0.2 beyond (nearest filtering): the quad's
    // halves, and the sphere's two halves in longitude, lie symmetrically about the lit point,
    // so L = a 0.6 (the plain emitter's factor).
    const std::string path = (std::filesystem::temp_directory_path() / "rts_test_uv_emission.png").string();
    Image img(2, 1);
    img.at(0, 0)[0] = img.at(0, 0)[1] = img.at(0, 0)[2] = 1.0f;
    img.at(1, 0)[0] = img.at(1, 0)[1] = img.at(1, 0)[2] = 0.2f;
    write_png(path, img, 16, Encoding::Linear);
    TextureDesc image;
    image.kind = TextureKind::Image;
    image.image_path = path;
    image.linear = true;
    image.mapping = "uv";
    image.filter = TextureFilter::Nearest;
    for (const char* shape : {"quad", "sphere", "mesh"}) {
      INFO(shape);
      SceneDesc s = floor_scene();
      s.textures.push_back(image);
      MaterialDesc lamp = emissive(Color(0.0));
      lamp.emission_texture = 0;
      const MaterialId mat = add_material(s, lamp);
      const bool sphere = std::string(shape) == "sphere";
      if (sphere) {
        place(s, add_shape(s, Sphere{Vec3(0, 3, 0), 0.5}, mat));
      } else if (std::string(shape) == "quad") {
        place(s, add_shape(s, Quad{Vec3(-0.5, 1, -0.3), Vec3(1.0, 0, 0), Vec3(0, 0, 0.6)}, mat));
      } else {
        // The quad as two triangles whose vertices carry its uvs.
        auto mesh = std::make_shared<MeshData>();
        mesh->positions = {{-0.5f, 1, -0.3f}, {0.5f, 1, -0.3f}, {0.5f, 1, 0.3f}, {-0.5f, 1, 0.3f}};
        mesh->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        mesh->indices = {0, 1, 2, 0, 2, 3};
        s.meshes.push_back(mesh);
        place(s, add_shape(s, MeshRef{0, false}, mat));
      }
      Measured m = render_path(s, 8, 16);
      check_within_noise(m, a * 0.6 * (sphere ? (0.5 / 3) * (0.5 / 3) : rect_form_factor(0.5, 0.3, 1.0)));
      CHECK(m.standard_error < 0.05 * m.mean);   // sampled by NEE, not left to bounced rays
    }
    std::filesystem::remove(path);
  }
  SECTION("a skewed emissive quad (sampled by area) lights like the rectangle it shears") {
    SceneDesc s = floor_scene();
    MaterialDesc lamp = lambert(0.0);
    lamp.diffuse = 0;
    lamp.emission = Color(3.0);
    // Far enough that the shear barely changes the form factor: a 0.2 x 0.2 light 4 above.
    place(s, add_shape(s, Quad{Vec3(-0.1, 4, -0.1), Vec3(0.2, 0, 0), Vec3(0.02, 0, 0.2)}, add_material(s, lamp)));
    const double expected = a * 3.0 * rect_form_factor(0.1, 0.1, 4.0);
    Measured m = render_path(s, 8, 16);
    INFO("mean " << m.mean << " expected " << expected);
    CHECK(std::abs(m.mean - expected) <= kSigmas * m.standard_error + 2e-3 * expected);
  }
  SECTION("an emissive disc and annulus: L = a Le (R^2 / (R^2 + h^2) - r^2 / (r^2 + h^2))") {
    for (double inner : {0.0, 0.4}) {
      SceneDesc s = floor_scene();
      MaterialDesc lamp = lambert(0.0);
      lamp.diffuse = 0;
      lamp.emission = Color(4.0);
      place(s, add_shape(s, Disc{Vec3(0, 1.5, 0), Vec3(0, -1, 0), 0.8, inner}, add_material(s, lamp)));
      const double h2 = 1.5 * 1.5;
      Measured m = render_path(s, 8, 16);
      check_within_noise(m, a * 4.0 * (0.64 / (0.64 + h2) - inner * inner / (inner * inner + h2)));
      // Sampled by NEE: found by bounced rays alone (a fifth of them hit it) the standard
      // error would be about 6% of the mean.
      CHECK(m.standard_error < 0.02 * m.mean);
    }
  }
  SECTION("an emissive box lights the floor below it by its bottom face (NEE picks any face)") {
    SceneDesc s = floor_scene();
    MaterialDesc lamp = lambert(0.0);
    lamp.diffuse = 0;
    lamp.emission = Color(3.0);
    place(s, add_shape(s, Box{Vec3(-0.4, 1, -0.25), Vec3(0.4, 1.3, 0.25)}, add_material(s, lamp)));
    Measured m = render_path(s, 8, 16);
    check_within_noise(m, a * 3.0 * rect_form_factor(0.4, 0.25, 1.0));
    CHECK(m.standard_error < 0.02 * m.mean);   // sampled by NEE (as for the disc)
  }
  SECTION("an emissive sphere: L = a Le (r / d)^2 (NEE by solid angle)") {
    SceneDesc s = floor_scene();
    MaterialDesc lamp = lambert(0.0);
    lamp.diffuse = 0;
    lamp.emission = Color(5.0);
    place(s, add_shape(s, Sphere{Vec3(0, 3, 0), 0.5}, add_material(s, lamp)));
    check_within_noise(render_path(s, 8, 16), a * 5.0 * (0.5 / 3) * (0.5 / 3));
  }
  // A cylinder or cone of emission 4 standing on the axis above the floor's point, from h1 to
  // h2 with radii r0 and r1, placed by `xf`: directions through its bottom opening meet the
  // bottom cap; without caps they meet the inner wall, except those that leave through the top
  // opening: irradiance pi Le (r0^2 / (r0^2 + h1^2) - r1^2 / (r1^2 + h2^2)). NEE samples the
  // whole surface by area (most samples are hidden by the shape itself), so this checks its
  // density as well as its units.
  auto check_axis_lamp = [&](const ShapeGeometry& shape, double r0, double r1, double h1, double h2, bool capped,
                             const Mat4& xf = Mat4(1.0)) {
    INFO((capped ? "capped" : "open"));
    SceneDesc s = floor_scene();
    place(s, add_shape(s, shape, add_material(s, emissive(Color(4.0)))), xf);
    const double through_bottom = r0 * r0 / (r0 * r0 + h1 * h1), through_top = r1 * r1 / (r1 * r1 + h2 * h2);
    Measured m = render_path(s, 8, 16);
    check_within_noise(m, a * 4.0 * (capped ? through_bottom : through_bottom - through_top));
    CHECK(m.standard_error < 0.05 * m.mean);   // sampled by NEE, not left to bounced rays
  };
  SECTION("an emissive cylinder: a capped one lights by its bottom disc, an open tube by its inner wall") {
    const double r = 0.6, h1 = 1.0, h2 = 1.8;
    for (bool capped : {true, false})
      check_axis_lamp(Cylinder{Vec3(0, h1, 0), Vec3(0, h2, 0), r, capped}, r, r, h1, h2, capped);
    // Half the size, scaled by 2 and turned about the axis: still sampled, the same light.
    check_axis_lamp(Cylinder{Vec3(0, h1 / 2, 0), Vec3(0, h2 / 2, 0), r / 2, true}, r, r, h1, h2, true,
                    scale(Vec3(2.0)) * rotate_deg(90, Vec3(0, 1, 0)));
  }
  SECTION("an emissive cone (a frustum narrowing upwards): its bottom disc, or its inner wall") {
    const double r0 = 0.8, r1 = 0.3, h1 = 1.0, h2 = 2.0;
    for (bool capped : {true, false})
      check_axis_lamp(Cone{Vec3(0, h1, 0), Vec3(0, h2, 0), r0, r1, capped}, r0, r1, h1, h2, capped);
  }
  SECTION("an emissive triangle mesh lights like the quad it tiles") {
    SceneDesc s = floor_scene();
    MaterialDesc lamp = lambert(0.0);
    lamp.diffuse = 0;
    lamp.emission = Color(2.0);
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {{-1e4f, 1, -1e4f}, {1e4f, 1, -1e4f}, {1e4f, 1, 1e4f}, {-1e4f, 1, 1e4f}};
    mesh->indices = {0, 1, 2, 0, 2, 3};
    s.meshes.push_back(mesh);
    place(s, add_shape(s, MeshRef{0, false}, add_material(s, lamp)));
    check_within_noise(render_path(s, 8, 16), a * 2.0);
  }
}

TEST_CASE("lights are picked by power (a quarter uniformly), distant ones 1/n; the sum stays unbiased", "[path]") {
  const double a = 0.6;
  SceneDesc s;
  s.settings.max_depth = 4;
  look_down(s, 0.01, 0.5);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, lambert(a))));
  LightDesc dim, bright, sun;
  dim.position = Vec3(0, 2, 0);
  dim.intensity = 1;
  bright.position = Vec3(0, 3, 0);
  bright.intensity = 9;
  sun.kind = LightKind::Directional;
  sun.direction = Vec3(0, -1, 0);
  sun.intensity = 0.5;
  for (const LightDesc& l : {dim, bright, sun}) place(s, add_light(s, l));
  FlatScene flat = flatten_scene(s);
  World world(s, flat);
  path::LightSet set(world, s, compile_lights(flat.lights), {});
  // Local lights share 2/3 by 0.75 power + 0.25 uniform: powers 4 pi and 36 pi.
  const std::vector<double> pick = set.pick_probabilities();
  REQUIRE(pick.size() == 3);
  CHECK(pick[0] == Approx(2.0 / 3.0 * (0.75 * 0.1 + 0.25 / 2)));
  CHECK(pick[1] == Approx(2.0 / 3.0 * (0.75 * 0.9 + 0.25 / 2)));
  CHECK(pick[2] == Approx(1.0 / 3.0));
  // Whatever the probabilities, the estimate is the sum of the three lights.
  check_within_noise(render_path(s, 8, 16), a / std::numbers::pi * (1.0 / 4 + 9.0 / 9 + 0.5));
  // One light is always picked; a black one is never in the set.
  SceneDesc one;
  look_down(one, 0.01, 0.5);
  place(one, add_shape(one, Plane{Vec3(0, 1, 0), 0.0}, add_material(one, lambert(a))));
  dim.color = Color(0.0);
  place(one, add_light(one, dim));
  place(one, add_light(one, bright));
  FlatScene flat_one = flatten_scene(one);
  World world_one(one, flat_one);
  CHECK(path::LightSet(world_one, one, compile_lights(flat_one.lights), {}).pick_probabilities() ==
        std::vector<double>{1.0});
}

namespace {
// A closed box with a quad lamp, a glass sphere, a glossy sphere and a point light: every
// path feature at once.
SceneDesc cornell_like() {
  SceneDesc s;
  s.settings.max_depth = 8;
  s.has_camera = true;
  s.camera.position = Vec3(0, 1, -2.9);
  s.camera.look_at = Vec3(0, 1, 0);
  MaterialId white = add_material(s, lambert(0.7)), red = add_material(s, lambert(0.5));
  place(s, add_shape(s, Quad{Vec3(-1, 0, -3), Vec3(2, 0, 0), Vec3(0, 0, 4)}, white));
  place(s, add_shape(s, Quad{Vec3(-1, 2, -3), Vec3(2, 0, 0), Vec3(0, 0, 4)}, white));
  place(s, add_shape(s, Quad{Vec3(-1, 0, 1), Vec3(2, 0, 0), Vec3(0, 2, 0)}, white));
  place(s, add_shape(s, Quad{Vec3(-1, 0, -3), Vec3(0, 0, 4), Vec3(0, 2, 0)}, red));
  place(s, add_shape(s, Quad{Vec3(1, 0, -3), Vec3(0, 0, 4), Vec3(0, 2, 0)}, white));
  place(s, add_shape(s, Quad{Vec3(-1, 0, -3), Vec3(2, 0, 0), Vec3(0, 2, 0)}, white));
  MaterialDesc lamp = lambert(0.5);
  lamp.emission = Color(8.0);
  place(s, add_shape(s, Quad{Vec3(-0.2, 1.99, -0.2), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4)}, add_material(s, lamp)));
  MaterialDesc glass = lambert(0.0);
  glass.diffuse = 0;
  glass.transmit = Color(0.9);
  glass.ior = 1.5;
  place(s, add_shape(s, Sphere{Vec3(-0.4, 0.4, 0), 0.4}, add_material(s, glass)));
  MaterialDesc metal = lambert(0.2);
  metal.reflect = Color(0.7);
  metal.roughness = 0.2;
  metal.specular = 0.1;
  place(s, add_shape(s, Sphere{Vec3(0.45, 0.35, 0.2), 0.35}, add_material(s, metal)));
  LightDesc l;
  l.position = Vec3(0.5, 1.5, -1);
  l.intensity = 0.5;
  place(s, add_light(s, l));
  return s;
}
}  // namespace

TEST_CASE("path images are the same whatever the thread count", "[path]") {
  Measured one = render_path(cornell_like(), 16, 8, 1);
  Measured two = render_path(cornell_like(), 16, 8, 2);
  Measured three = render_path(cornell_like(), 16, 8, 3);
  CHECK(one.result.color.rgb == two.result.color.rgb);
  CHECK(one.result.color.rgb == three.result.color.rgb);
  CHECK(one.mean > 0.01);   // the room is lit
  CHECK(one.result.stats.integrator == "path");
}

TEST_CASE("path mode stays finite: grazing views, albedo 1, tiny and huge scales, zero-size emitters", "[path]") {
  auto finite_image = [](const RenderResult& r) {
    for (float v : r.color.rgb)
      if (!std::isfinite(v) || v < 0) return false;
    return r.stats.rays.nan_samples == 0;
  };
  SECTION("grazing camera along a lit floor, under a sky") {
    SceneDesc s;
    s.settings.background = Color(1.0);
    s.has_camera = true;
    s.camera.position = Vec3(0, 1e-9, 0);
    s.camera.look_at = Vec3(0, 1e-9, 1);
    place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, lambert(0.9))));
    CHECK(finite_image(render_path(s, 8, 4).result));
  }
  SECTION("albedo 1 inside an emitter (the radiance grows with depth but stays finite)") {
    SceneDesc s;
    s.has_camera = true;
    s.camera.position = Vec3(0);
    s.camera.look_at = Vec3(0, 0, 1);
    s.settings.max_depth = 200;
    MaterialDesc m = lambert(1.0);
    m.emission = Color(1.0);
    place(s, add_shape(s, Sphere{Vec3(0), 1.0}, add_material(s, m)));
    CHECK(finite_image(render_path(s, 4, 4).result));
  }
  SECTION("the whole scene scaled by 1e-6 and by 1e6") {
    for (double k : {1e-6, 1e6}) {
      SceneDesc s = cornell_like();
      std::vector<Child> roots(s.roots.begin(), s.roots.end());
      NodeId group = add_group(s, roots);
      s.roots.clear();
      place(s, group, scale(Vec3(k)));
      s.camera.position *= k;
      s.camera.look_at *= k;
      s.lights[0].intensity *= k * k;   // the same irradiance at the scaled distances
      Measured m = render_path(s, 8, 4);
      INFO("scale " << k);
      CHECK(finite_image(m.result));
      CHECK(m.mean > 0.01);
    }
  }
  SECTION("zero-size emitters are never sampled and never poison a pixel") {
    SceneDesc s = cornell_like();
    MaterialDesc lamp = lambert(0.5);
    lamp.emission = Color(1e6);
    MaterialId id = add_material(s, lamp);
    place(s, add_shape(s, Sphere{Vec3(0, 1, 0), 0.0}, id));
    place(s, add_shape(s, Quad{Vec3(0, 1, 0), Vec3(0, 0, 0), Vec3(0, 0, 1)}, id));
    place(s, add_shape(s, Sphere{Vec3(0, 1.5, 0), 1e-200}, id));
    // Cylinders and cones with no height, no radius, a point for an end, or a tiny size.
    place(s, add_shape(s, Cylinder{Vec3(0, 1, 0), Vec3(0, 1, 0), 0.2, true}, id));
    place(s, add_shape(s, Cylinder{Vec3(0, 1, 0), Vec3(0, 1.2, 0), 0.0, true}, id));
    place(s, add_shape(s, Cylinder{Vec3(0.1, 1, 0), Vec3(0.1, 1 + 1e-150, 0), 1e-150, true}, id));
    place(s, add_shape(s, Cone{Vec3(0, 1, 0), Vec3(0, 1.3, 0), 0.0, 0.0, true}, id));
    place(s, add_shape(s, Cone{Vec3(-0.1, 1, 0), Vec3(-0.1, 1.3, 0), 0.2, 0.0, true}, id));
    place(s, add_shape(s, Cone{Vec3(0.2, 1, 0), Vec3(0.2, 1.3, 0), 0.0, 0.1, false}, id));
    CHECK(finite_image(render_path(s, 8, 4).result));
  }
}

TEST_CASE("emitters of every sampled kind give the unit scene's picture scaled by 1e-150 to 1e150", "[path]") {
  // Radiance does not change when a scene lit only by emitters is scaled, so neither may the
  // picture. The emitters' areas (|e1 x e2|, squared inside glm::length) and the spherical
  // rectangle's, a box's and a mesh's normals overflowed past about 1e77 units (the Cornell
  // box's lamp went dark), and emitters below 1e-200 in area were left out of light sampling.
  auto scene = [](double k) {
    SceneDesc s;
    s.has_camera = true;
    s.camera.position = Vec3(0, 1.2, -3.5) * k;
    s.camera.look_at = Vec3(0, 0.6, 0) * k;
    s.settings.max_depth = 4;
    const MaterialId grey = add_material(s, lambert(0.7));
    MaterialDesc lamp = lambert(0.5);
    lamp.emission = Color(4.0, 3.0, 2.0);
    const MaterialId glow = add_material(s, lamp);
    place(s, add_shape(s, Quad{Vec3(-3, 0, -3) * k, Vec3(6, 0, 0) * k, Vec3(0, 0, 6) * k}, grey));
    place(s, add_shape(s, Sphere{Vec3(0, 0.5, 0.5) * k, 0.5 * k}, grey));
    place(s, add_shape(s, Quad{Vec3(-0.5, 2, 0) * k, Vec3(1, 0, 0) * k, Vec3(0, 0, 0.6) * k}, glow));
    place(s, add_shape(s, Sphere{Vec3(-1.4, 0.3, 0.2) * k, 0.25 * k}, glow));
    place(s, add_shape(s, Triangle{Vec3(1.1, 0, 1) * k, Vec3(1.7, 0, 1.2) * k, Vec3(1.4, 0.8, 1.1) * k, {}}, glow));
    place(s, add_shape(s, Disc{Vec3(-0.8, 1.4, 1.0) * k, Vec3(0.3, -1, 0), 0.3 * k, 0.0}, glow));
    place(s, add_shape(s, Box{Vec3(0.6, 0, -0.6) * k, Vec3(0.9, 0.3, -0.3) * k}, glow));
    place(s, add_shape(s, Cylinder{Vec3(-0.9, 0, -0.8) * k, Vec3(-0.9, 0.4, -0.8) * k, 0.1 * k, true}, glow));
    place(s, add_shape(s, Cone{Vec3(1.6, 0, -0.4) * k, Vec3(1.6, 0.5, -0.4) * k, 0.2 * k, 0.05 * k, true}, glow));
    // A unit mesh placed with scale k (meshes keep single-precision vertices near unit size).
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {{-2.0f, 0.0f, 1.5f}, {-1.4f, 0.0f, 1.7f}, {-1.7f, 0.9f, 1.6f}, {-1.8f, 0.5f, 1.0f}};
    mesh->indices = {0, 1, 2, 0, 2, 3};
    s.meshes.push_back(mesh);
    place(s, add_shape(s, MeshRef{static_cast<MeshId>(s.meshes.size() - 1), false}, glow), scale(Vec3(k)));
    return s;
  };
  const Measured unit = render_path(scene(1.0), 16, 4);
  REQUIRE(unit.mean > 0.05);
  for (double k : {1e-150, 1e-100, 1e-50, 1e50, 1e100, 1e150}) {
    INFO("scale 1e" << std::lround(std::log10(k)));
    const Measured scaled = render_path(scene(k), 16, 4);
    REQUIRE(scaled.result.color.rgb.size() == unit.result.color.rgb.size());
    double worst = 0;
    for (std::size_t i = 0; i < unit.result.color.rgb.size(); ++i)
      worst = std::max(worst, std::abs(static_cast<double>(scaled.result.color.rgb[i]) - unit.result.color.rgb[i]));
    CHECK(worst < 1e-3);  // the same paths, up to the rounding of scaled positions
  }
}

TEST_CASE("a material that reflects more than it receives is scaled down, with a located warning", "[path]") {
  SceneDesc s;
  s.settings.background = Color(1.0);
  look_down(s, 0.8);
  MaterialDesc m = lambert(0.9);
  m.reflect = Color(0.5);
  m.loc = SourceRef{"bright.rts", 3, 7};
  place(s, add_shape(s, Sphere{Vec3(0), 1.0}, add_material(s, m)));
  Measured got = render_path(s, 8, 16);
  REQUIRE(got.result.warnings.size() == 1);
  CHECK(got.result.warnings[0].where.line == 3);
  CHECK(got.result.warnings[0].message.find("scaled by") != std::string::npos);
  // Scaled to reflect at most what arrives: under a sky of 1, at most 1.
  CHECK(got.mean <= 1.0 + kSigmas * got.standard_error);
}

TEST_CASE("the path-traced box agrees with its stored 4096-spp reference, block by block", "[path]") {
  // tests/golden/path/cornell_like_16.pfm: cornell_like() at 16x16, 4096 spp, seed 1, made by
  // this test with RTS_UPDATE_PATH_REFERENCE=1 (look at it: a lit box, a glass and a metal
  // sphere). A 64-spp render of another seed is compared per 4x4 block and channel: the
  // difference of the block means over its standard error (from the render's own per-pixel
  // variance estimates; the reference's, 64 times smaller, added) must stay within 5. For
  // normal errors that fails by chance with probability 48 x 5.7e-7 = 3e-5.
  const std::string ref_path = std::string(RTS_SOURCE_DIR) + "/tests/golden/path/cornell_like_16.pfm";
  SceneDesc s = cornell_like();
  if (std::getenv("RTS_UPDATE_PATH_REFERENCE")) {
    s.settings.seed = 1;
    write_pfm(ref_path, render_path(s, 16, 4096).result.color);
  }
  Image ref = read_pfm(ref_path);
  REQUIRE(ref.width == 16);
  REQUIRE(ref.height == 16);
  s.settings.seed = 2;
  Measured got = render_path(s, 16, 64);
  const std::vector<float>& var = got.result.stats.pixels.variance;
  REQUIRE(var.size() == 16 * 16 * 3);
  double total_got = 0, total_ref = 0;
  for (int by = 0; by < 16; by += 4)
    for (int bx = 0; bx < 16; bx += 4)
      for (int c = 0; c < 3; ++c) {
        double diff = 0, v = 0;
        for (int y = by; y < by + 4; ++y)
          for (int x = bx; x < bx + 4; ++x) {
            std::size_t i = (static_cast<std::size_t>(y) * 16 + x) * 3 + c;
            diff += got.result.color.rgb[i] - ref.rgb[i];
            v += var[i] * (1.0 + 64.0 / 4096.0);
            total_got += got.result.color.rgb[i];
            total_ref += ref.rgb[i];
          }
        double z = (diff / 16) / std::sqrt(std::max(v / 256, 1e-30));
        INFO("block " << bx << "," << by << " channel " << c << ": z = " << z);
        CHECK(std::abs(z) < 5.0);
      }
  CHECK(total_got == Approx(total_ref).epsilon(0.03));
}

TEST_CASE("the sky's importance sampling: a density that integrates to 1 and matches its samples", "[path]") {
  // A sky with a small bright sun: the grid must send most samples there, and pdf() must be
  // the density sample() draws from (else MIS weights and estimates are wrong).
  const Vec3 sun = glm::normalize(Vec3(0.3, 0.8, -0.5));
  path::SkyDistribution sky([&](const Vec3& d) { return glm::dot(d, sun) > 0.99 ? 1000.0 : 1.0; });
  Sampler u(0, 0, 0, 42);
  const int n = 20000;
  double integral = 0, near_sun = 0, ratio = 0, worst_length = 0;
  for (int i = 0; i < n; ++i) {
    Vec3 d = path::uniform_sphere(u.next2());
    integral += sky.pdf(d) * 4.0 * std::numbers::pi / n;
    double pdf = 0;
    Vec3 s = sky.sample(u.next2(), pdf);
    worst_length = std::max(worst_length, std::abs(glm::length(s) - 1.0));
    if (glm::dot(s, sun) > 0.99) near_sun += 1.0 / n;
    ratio += std::abs(pdf - sky.pdf(s)) / sky.pdf(s) / n;
  }
  CHECK(integral == Approx(1.0).epsilon(0.05));
  // The sun's cap is 0.5% of the sky but ~83% of its light: most samples go there.
  CHECK(near_sun > 0.6);
  CHECK(ratio < 1e-12);
  CHECK(worst_length < 1e-9);
}
