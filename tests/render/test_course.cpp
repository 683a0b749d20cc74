// The course ray tracers' conventions, against closed-form answers: colored specular, UW's
// clamped light falloff, a vertical field of view, a right-handed view, the depth AOV's
// near/far mapping and miss values.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "render/sample/camera.hpp"
#include "render/accel/flatten.hpp"
#include "render/image/frame.hpp"
#include "render/shade/integrator.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/texture.hpp"
#include "render/renderer.hpp"
#include "scene_fixture.hpp"
#include "tracer.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

// A material that shows only its highlight.
MaterialDesc highlight_only() {
  MaterialDesc m;
  m.ambient = 0;
  m.diffuse = 0;
  m.shininess = 7;
  return m;
}

// `floor` (in the y = 0 plane) with material `m`, lit and seen from straight above (from
// `eye`): R·V = 1, so the pixel is exactly the highlight, specular * specular_color * light.
Rgb seen_from_above(SceneDesc s, const MaterialDesc& m, ShapeGeometry floor, Vec3 eye = Vec3(0, 2, 0)) {
  place(s, add_shape(s, std::move(floor), add_material(s, m)));
  LightDesc l;
  l.position = Vec3(0, 4, 0);
  place(s, add_light(s, l));
  Tracer t(std::move(s));
  return t.trace(Ray{eye, Vec3(0, -1, 0)});
}

Rgb highlight_seen_from_above(double specular, Color specular_color) {
  MaterialDesc m = highlight_only();
  m.specular = specular;
  m.specular_color = specular_color;
  return seen_from_above(SceneDesc{}, m, Plane{Vec3(0, 1, 0), 0.0});
}

// The same highlight where it comes from per-vertex values (a two-triangle floor mesh whose
// four corners all carry `spec`; seen just off its diagonal edge) ...
Rgb vertex_highlight(glm::vec3 spec) {
  SceneDesc s;
  auto mesh = std::make_shared<MeshData>();
  mesh->positions = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
  mesh->indices = {0, 2, 1, 0, 3, 2};
  mesh->specular.assign(4, spec);
  s.meshes.push_back(mesh);
  return seen_from_above(std::move(s), highlight_only(), MeshRef{0, false}, Vec3(0.01, 2, 0.02));
}

// ... or from a texture on `specular` (a checker whose two colors are both `tex`).
Rgb textured_highlight(Color tex, Color specular_color) {
  SceneDesc s;
  TextureDesc checker;
  checker.color1 = checker.color2 = tex;
  s.textures.push_back(checker);
  MaterialDesc m = highlight_only();
  m.specular = 1.0;   // what the builder sets for a texture
  m.specular_color = specular_color;
  m.specular_texture = 0;
  return seen_from_above(std::move(s), m, Plane{Vec3(0, 1, 0), 0.0});
}

double angle_between(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0));
}

}  // namespace

TEST_CASE("a colored specular weights the highlight per channel", "[course]") {
  Rgb tinted = highlight_seen_from_above(1.0, Color(0.2, 0.5, 1.0));
  CHECK(tinted.x == Approx(0.2));
  CHECK(tinted.y == Approx(0.5));
  CHECK(tinted.z == Approx(1.0));
  // A number is a white highlight of that weight; both multiply.
  Rgb white = highlight_seen_from_above(0.5, Color(1.0));
  CHECK(white.x == Approx(0.5));
  CHECK(white.z == Approx(0.5));
  Rgb both = highlight_seen_from_above(0.5, Color(0.2, 0.5, 1.0));
  CHECK(both.y == Approx(0.25));
}

TEST_CASE("per-vertex specular colors tint the highlight; numbers are gray colors", "[course]") {
  // Seen from (almost) straight above: R·V is 1 to within 1e-5, so the pixel is the color.
  Rgb tinted = vertex_highlight({0.2f, 0.5f, 1.0f});
  CHECK(tinted.x == Approx(0.2).epsilon(1e-3));
  CHECK(tinted.y == Approx(0.5).epsilon(1e-3));
  CHECK(tinted.z == Approx(1.0).epsilon(1e-3));
  Rgb gray = vertex_highlight(glm::vec3(0.5f));
  CHECK(gray.x == Approx(0.5).epsilon(1e-3));
  CHECK(gray.z == Approx(0.5).epsilon(1e-3));
}

TEST_CASE("a texture on specular gives the highlight's color channel by channel", "[course]") {
  Rgb tinted = textured_highlight(Color(0.2, 0.5, 1.0), Color(1.0));
  CHECK(tinted.x == Approx(0.2));
  CHECK(tinted.y == Approx(0.5));
  CHECK(tinted.z == Approx(1.0));
  // It multiplies a colored specular's tint.
  Rgb both = textured_highlight(Color(0.5), Color(0.2, 0.5, 1.0));
  CHECK(both.x == Approx(0.1));
  CHECK(both.z == Approx(0.5));
}

TEST_CASE("clamped attenuation is min(1, 1 / (a + b d + c d^2))", "[course]") {
  const Vec3 k(0.25, 0.05, 0.25);
  for (double d : {0.0, 0.5, 1.0, 1.5, 2.0, 4.0, 10.0}) {
    double denom = k.x + k.y * d + k.z * d * d;
    CHECK(attenuation_factor(k, d, true) == Approx(std::min(1.0, 1.0 / denom)));
    CHECK(attenuation_factor(k, d, false) == Approx(1.0 / denom));
  }
  // At the light itself a pure quadratic has a zero denominator: the clamp gives the full color.
  CHECK(attenuation_factor(Vec3(0, 0, 1), 0.0, true) == 1.0);
  // MIT's color / (alpha d^2) is the quadratic term alone.
  CHECK(attenuation_factor(Vec3(0, 0, 0.5), 3.0, false) == Approx(1.0 / (0.5 * 9.0)));

  // Through a compiled point light: near (denominator < 1) exactly its power, far attenuated.
  LightDesc d;
  d.position = Vec3(0.0);
  d.color = Color(1.0, 0.5, 0.25);
  d.attenuation = k;
  d.attenuation_clamp = true;
  CompiledLight l = compile_lights({d})[0];
  LightSample near = sample_light(l, Vec3(1, 0, 0), glm::dvec2(0.5));
  CHECK(near.radiance.x == Approx(1.0));
  CHECK(near.radiance.z == Approx(0.25));
  LightSample far = sample_light(l, Vec3(0, 4, 0), glm::dvec2(0.5));
  CHECK(far.radiance.x == Approx(1.0 / (0.25 + 0.2 + 4.0)));
  // A constant-only attenuation below 1 is clamped too (the precomputed path).
  d.attenuation = Vec3(0.5, 0, 0);
  CHECK(sample_light(compile_lights({d})[0], Vec3(7, 0, 0), glm::dvec2(0.5)).radiance.x == Approx(1.0));
  d.attenuation_clamp = false;
  CHECK(sample_light(compile_lights({d})[0], Vec3(7, 0, 0), glm::dvec2(0.5)).radiance.x == Approx(2.0));
}

TEST_CASE("fov_axis vertical: fov spans the image's height", "[course]") {
  CameraDesc c;
  c.position = Vec3(0, 0, -5);
  c.look_at = Vec3(0.0);
  c.fov = 40;
  const int w = 200, h = 100;
  const double half = 20.0 * std::numbers::pi / 180.0;
  // Default: horizontal. The left edge's middle is fov/2 off the axis.
  Camera horizontal(c, w, h);
  CHECK(angle_between(horizontal.generate(0, h / 2.0, {}).direction, c.look_at - c.position) == Approx(half));
  c.fov_vertical = true;
  Camera vertical(c, w, h);
  CHECK(angle_between(vertical.generate(w / 2.0, 0, {}).direction, c.look_at - c.position) == Approx(half));
  // The horizontal angle follows from the aspect ratio: tan(x/2) = tan(fov/2) * w / h.
  double x_half = angle_between(vertical.generate(0, h / 2.0, {}).direction, c.look_at - c.position);
  CHECK(std::tan(x_half) == Approx(std::tan(half) * w / h));
}

TEST_CASE("handedness right mirrors the view left-right", "[course]") {
  CameraDesc c;
  c.position = Vec3(0, 0, 5);   // the courses' camera, on +z looking towards -z
  c.look_at = Vec3(0.0);
  const int w = 64, h = 48;
  Camera left(c, w, h);
  c.right_handed = true;
  Camera right(c, w, h);
  // Right-handed (OpenGL): +x is to the right seen from +z, so the left edge looks towards -x.
  CHECK(right.generate(0, h / 2.0, {}).direction.x < 0);
  CHECK(left.generate(0, h / 2.0, {}).direction.x > 0);
  // Up is unchanged.
  CHECK(right.generate(w / 2.0, 0, {}).direction.y > 0);
  Vec3 a = left.generate(10, 7, {}).direction, b = right.generate(w - 10, 7, {}).direction;
  CHECK(a.x == Approx(b.x));
  CHECK(a.y == Approx(b.y));
}

TEST_CASE("depth range maps near..far linearly, misses get their value", "[course]") {
  RenderResult result;
  Frame frame;
  AovFlags flags;
  flags.depth = true;
  allocate_frame(result, 5, 1, flags, true, {}, frame);
  const float depths[5] = {-1.0f, 2.0f, 6.0f, 8.0f, 30.0f};  // -1: nothing hit
  for (int i = 0; i < 5; ++i) frame.depth[i] = depths[i];
  finish_depth(result, frame, std::make_pair(4.0, 8.0), 0.75f);
  const Image& img = result.aovs["depth"];
  CHECK(img.rgb[0] == 0.75f);              // miss
  CHECK(img.rgb[3] == 0.0f);               // nearer than near: clamped black
  CHECK(img.rgb[6] == Approx(0.5f));       // halfway
  CHECK(img.rgb[9] == Approx(1.0f));       // at far
  CHECK(img.rgb[12] == 1.0f);              // beyond far: clamped white
  CHECK(img.rgb[7] == img.rgb[6]);         // gray
}

TEST_CASE("the normal AOV writes the miss value where nothing is hit", "[course]") {
  SceneDesc s;
  s.settings.width = 8;
  s.settings.height = 8;
  s.has_camera = true;
  s.camera.position = Vec3(0, 0, -5);
  place(s, add_shape(s, Sphere{Vec3(0), 1.5}));
  RenderOptions o;
  o.threads = 1;
  o.aovs = {"normal"};
  o.normal_miss = 0.5f;
  RenderResult r = render(s, o);
  const Image& n = r.aovs["normal"];
  CHECK(n.at(0, 0)[0] == 0.5f);            // a corner: background
  CHECK(n.at(0, 0)[2] == 0.5f);
  CHECK(n.at(4, 4)[2] < 0.1f);             // the sphere's front faces -z: blue near 0
}
