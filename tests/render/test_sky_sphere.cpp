// sky_sphere (render/shade/sky_sphere.cpp): the colour a ray that leaves the scene sees is the
// layered pattern's closed-form value in its direction, for camera rays, mirror reflections
// and (path mode) as the light of a diffuse plane; the feature is reported only when used.
//
// Camera rays here come from an orthographic camera, so every pixel looks the same way and
// the whole image must be one value: exact checks (1e-6, float images). The path-mode check is
// statistical, as in test_path.cpp: the image mean within 5 standard errors (plus 1e-4
// relative) of the closed form, which fails by chance with probability 5.7e-7 for a normal
// mean (the render is seeded, so a build passes or fails every time).
#include <cmath>
#include <vector>

#include <catch2/catch.hpp>

#include "render/accel/flatten.hpp"
#include "render/renderer.hpp"
#include "render/shade/features.hpp"
#include "render/shade/texture.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

const Color kHorizon(0.9, 0.6, 0.3), kZenith(0.1, 0.3, 0.8);

// `gradient { axis = "y"  color_map = [[0, horizon], [1, zenith]] }` as the builder makes it.
TextureDesc gradient_y(Color lo, Color hi, double lo_transmit = 0.0, double hi_transmit = 0.0) {
  TextureDesc t;
  t.kind = TextureKind::Pattern;
  t.pattern.kind = PatternKind::Gradient;
  t.pattern.axis = 1;
  t.pattern.color_map = {{0.0, {lo.r, lo.g, lo.b}, lo_transmit}, {1.0, {hi.r, hi.g, hi.b}, hi_transmit}};
  return t;
}

TextureId add_texture(SceneDesc& s, TextureDesc t) {
  s.textures.push_back(std::move(t));
  return static_cast<TextureId>(s.textures.size() - 1);
}

// The environment = a sky_sphere of these layers (bottom first), transformed by `transform`.
void set_sky(SceneDesc& s, std::vector<TextureId> layers, const Mat4& transform = Mat4(1.0),
             std::vector<Color> colors = {}) {
  TextureDesc sky;
  sky.kind = TextureKind::SkySphere;
  colors.resize(layers.size(), Color(0.0));
  sky.sky_layers = std::move(layers);
  sky.sky_layer_colors = std::move(colors);
  sky.transform = transform;
  s.settings.environment = add_texture(s, sky);
}

Color mix(Color a, Color b, double t) { return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t}; }

// Every pixel of an orthographic view looking along `d`.
std::vector<float> look_along(const SceneDesc& sky, Vec3 d, IntegratorKind integrator = IntegratorKind::Whitted) {
  SceneDesc s = sky;
  s.settings.width = s.settings.height = 4;
  s.settings.integrator = integrator;
  s.has_camera = true;
  s.camera.projection = Projection::Orthographic;
  s.camera.position = Vec3(0, 1, 0);   // above the mirror plane of the reflection test
  s.camera.look_at = s.camera.position + d;
  s.camera.up = std::abs(d.y) > 0.9 ? Vec3(0, 0, 1) : Vec3(0, 1, 0);
  RenderOptions o;
  o.threads = 1;
  return render(s, o).color.rgb;
}

void check_all(const std::vector<float>& rgb, Color want) {
  REQUIRE(!rgb.empty());
  for (std::size_t i = 0; i < rgb.size(); i += 3) {
    INFO("pixel " << i / 3 << " got " << rgb[i] << " " << rgb[i + 1] << " " << rgb[i + 2] << " want " << want.r
                  << " " << want.g << " " << want.b);
    CHECK(rgb[i] == Approx(want.r).margin(1e-6));
    CHECK(rgb[i + 1] == Approx(want.g).margin(1e-6));
    CHECK(rgb[i + 2] == Approx(want.b).margin(1e-6));
  }
}

Vec3 elevation(double degrees) {
  const double a = glm::radians(degrees);
  return {0.0, std::sin(a), std::cos(a)};
}

}  // namespace

TEST_CASE("a camera ray sees the sky's gradient at its direction's height", "[sky]") {
  SceneDesc s;
  set_sky(s, {add_texture(s, gradient_y(kHorizon, kZenith))});
  // gradient y over the unit direction: its y, a ramp repeating below the horizon (y + 1).
  for (double deg : {0.0, 10.0, 30.0, 60.0, 89.0}) {
    INFO("elevation " << deg);
    check_all(look_along(s, elevation(deg)), mix(kHorizon, kZenith, std::sin(glm::radians(deg))));
  }
  INFO("below the horizon the ramp repeats");
  check_all(look_along(s, elevation(-30.0)), mix(kHorizon, kZenith, 0.5));
}

TEST_CASE("the sky's own transform turns the pattern, not its layers' colours", "[sky]") {
  SceneDesc s;
  // Rotated 90 degrees about z: the gradient now runs along -x (the inverse rotation takes a
  // direction d to (d.y, -d.x, 0) ... so looking along -x sees the zenith colour).
  set_sky(s, {add_texture(s, gradient_y(kHorizon, kZenith))}, rotate_deg(90.0, Vec3(0, 0, 1)));
  check_all(look_along(s, Vec3(-1, 0, 0)), kZenith);
  check_all(look_along(s, Vec3(0, 0, 1)), kHorizon);
  // A translation moves nothing: POV-Ray transforms the direction as a direction.
  SceneDesc t;
  set_sky(t, {add_texture(t, gradient_y(kHorizon, kZenith))}, translate(Vec3(0, 0.5, 0)));
  check_all(look_along(t, elevation(30.0)), mix(kHorizon, kZenith, 0.5));
}

TEST_CASE("layers: the last is on top, transmit shows the ones below and then the background", "[sky]") {
  const Color top(1.0, 1.0, 1.0), bottom(0.2, 0.4, 0.6), background(0.05, 0.1, 0.0);
  SceneDesc s;
  s.settings.background = background;
  const TextureId lower = add_texture(s, gradient_y(bottom, bottom));
  // The upper layer: opaque at the horizon, clear at the zenith (transmit = y).
  const TextureId upper = add_texture(s, gradient_y(top, top, 0.0, 1.0));
  set_sky(s, {lower, upper});
  for (double deg : {0.0, 30.0, 90.0}) {
    const double t = std::sin(glm::radians(deg));
    INFO("elevation " << deg << ": transmit " << t);
    check_all(look_along(s, elevation(deg)), mix(top, bottom, t));
  }
  SECTION("a see-through bottom layer shows the background") {
    SceneDesc b;
    b.settings.background = background;
    set_sky(b, {add_texture(b, gradient_y(bottom, bottom, 0.25, 0.25))});
    check_all(look_along(b, elevation(45.0)), mix(bottom, background, 0.25));
  }
  SECTION("a solid colour layer") {
    SceneDesc c;
    set_sky(c, {kNoId}, Mat4(1.0), {bottom});
    check_all(look_along(c, elevation(20.0)), bottom);
  }
}

TEST_CASE("a mirror reflects the sky; path mode sees the same sky", "[sky]") {
  SceneDesc s;
  set_sky(s, {add_texture(s, gradient_y(kHorizon, kZenith))});
  MaterialDesc mirror;
  mirror.color = Color(0.0);
  mirror.ambient = mirror.diffuse = mirror.specular = 0.0;
  mirror.reflect = Color(1.0);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, mirror)));
  // Looking down at 30 degrees below the horizon: the reflection leaves 30 degrees above it.
  check_all(look_along(s, elevation(-30.0)), mix(kHorizon, kZenith, 0.5));
  SceneDesc camera_only;
  set_sky(camera_only, {add_texture(camera_only, gradient_y(kHorizon, kZenith))});
  check_all(look_along(camera_only, elevation(40.0), IntegratorKind::Path),
            mix(kHorizon, kZenith, std::sin(glm::radians(40.0))));
}

TEST_CASE("path mode: a white diffuse plane under the sky converges to albedo times its irradiance", "[sky]") {
  // Under a constant sky of radiance L a Lambertian plane of albedo a sends a L; under the
  // gradient L(y) = h + (z - h) y of the upper hemisphere, a (h + (z - h) 2/3) (the cosine-
  // weighted mean of y is 2/3). The plane hides the lower half of the sky.
  const double a = 0.8;
  auto plane_under = [&](bool gradient) {
    SceneDesc s;
    if (gradient)
      set_sky(s, {add_texture(s, gradient_y(kHorizon, kZenith))});
    else
      set_sky(s, {kNoId}, Mat4(1.0), {Color(0.5)});
    MaterialDesc m;
    m.color = Color(a);
    m.diffuse = 1.0;
    m.ambient = 0.0;
    place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, m)));
    s.has_camera = true;
    s.camera.projection = Projection::Orthographic;
    s.camera.position = Vec3(0, 1, 0);
    s.camera.look_at = Vec3(0, 0, 0);
    s.camera.up = Vec3(0, 0, 1);
    s.settings.width = s.settings.height = 16;
    s.settings.samples = 64;
    s.settings.max_depth = 8;
    s.settings.integrator = IntegratorKind::Path;
    RenderOptions o;
    o.threads = 2;
    return render(s, o);
  };
  auto check_channel = [](const RenderResult& r, int c, double expected) {
    const std::vector<float>& rgb = r.color.rgb;
    const double n = static_cast<double>(rgb.size() / 3);
    double sum = 0, sum2 = 0;
    for (std::size_t i = static_cast<std::size_t>(c); i < rgb.size(); i += 3) {
      sum += rgb[i];
      sum2 += static_cast<double>(rgb[i]) * rgb[i];
    }
    const double mean = sum / n;
    const double se = std::sqrt(std::max(0.0, (sum2 / n - mean * mean) * n / (n - 1)) / n);
    INFO("channel " << c << " mean " << mean << " expected " << expected << " standard error " << se);
    CHECK(std::abs(mean - expected) <= 5.0 * se + 1e-4 * expected);
  };
  const RenderResult constant = plane_under(false);
  CHECK(constant.stats.rays.nan_samples == 0);
  check_channel(constant, 0, a * 0.5);
  const RenderResult gradient = plane_under(true);
  CHECK(gradient.stats.rays.nan_samples == 0);
  const Color want = mix(kHorizon, kZenith, 2.0 / 3.0);
  check_channel(gradient, 0, a * want.r);
  check_channel(gradient, 1, a * want.g);
  check_channel(gradient, 2, a * want.b);
}

TEST_CASE("sky_sphere is a feature only when the environment is one", "[sky]") {
  SceneDesc s;
  place(s, add_shape(s, Sphere{Vec3(0), 1.0}));
  CHECK_FALSE(analyze_features(s, flatten_scene(s), FeatureContext{}).has(Feature::SkySphere));
  s.settings.environment = add_texture(s, gradient_y(kHorizon, kZenith));   // a plain pattern environment
  CHECK_FALSE(analyze_features(s, flatten_scene(s), FeatureContext{}).has(Feature::SkySphere));
  set_sky(s, {s.settings.environment});
  CHECK(analyze_features(s, flatten_scene(s), FeatureContext{}).has(Feature::SkySphere));
  CHECK(feature_name(Feature::SkySphere) == "sky_sphere");
}

TEST_CASE("the sky never gives NaN: no direction, huge scales, transmit out of range", "[sky]") {
  SceneDesc s;
  s.settings.background = Color(0.3);
  const TextureId layer = add_texture(s, gradient_y(kHorizon, kZenith, 0.0, 1.0));
  set_sky(s, {layer}, scale(Vec3(1e-300, 1e300, 1.0)));
  const std::vector<CompiledTexture> compiled = compile_textures(s);
  const CompiledTexture& sky = compiled[s.settings.environment];
  for (Vec3 d : {Vec3(0.0), Vec3(NAN, 0, 0), Vec3(INFINITY, 1, 0), Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, -1e-300, 1)}) {
    const Color c = sky.eval_direction(d);
    INFO(d.x << " " << d.y << " " << d.z);
    CHECK(std::isfinite(c.r));
    CHECK(std::isfinite(c.g));
    CHECK(std::isfinite(c.b));
  }
  CHECK(sky.eval_direction(Vec3(0.0)) == Color(0.3));   // no direction: the background
}
