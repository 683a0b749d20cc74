// Checks against closed-form answers (not stored pixels): projected sphere area, Lambertian
// irradiance from a point light, a mirror's reflected color, and Snell's lateral shift
// through a glass slab.
#include <cmath>
#include <numbers>

#include <catch2/catch.hpp>

#include "render/accel/flatten.hpp"
#include "render/shade/integrator.hpp"
#include "render/renderer.hpp"
#include "scene_fixture.hpp"
#include "tracer.hpp"

using namespace rts::render;
using namespace rts::render::test;

TEST_CASE("sphere silhouette covers pi r^2 of an orthographic view", "[analytic]") {
  const double r = 1.3, view = 4.0;
  const int n = 96;
  SceneDesc s;
  s.settings.width = s.settings.height = n;
  s.settings.samples = 16;
  s.has_camera = true;
  s.camera.projection = Projection::Orthographic;
  s.camera.view_width = view;
  s.camera.position = Vec3(0.123, -0.2, -10);   // off-centre: no symmetry luck
  s.camera.look_at = s.camera.position + Vec3(0, 0, 1);
  place(s, add_shape(s, Sphere{Vec3(0), r}, add_material(s, emissive(Color(1.0)))));
  RenderOptions o;
  o.threads = 2;
  RenderResult res = render(s, o);
  double covered = 0;
  for (std::size_t i = 0; i < res.color.rgb.size(); i += 3) covered += res.color.rgb[i];
  double pixel_area = (view / n) * (view / n);
  CHECK(covered * pixel_area == Approx(std::numbers::pi * r * r).epsilon(0.005));
}

TEST_CASE("diffuse plane under a point light: E = I cos(theta) / d^2", "[analytic]") {
  const Vec3 light_pos(0.5, 4.0, -0.25);
  const double intensity = 20.0, kd = 0.7;
  const Color albedo(0.5, 0.25, 1.0), light_color(1.0, 0.5, 0.25);
  SceneDesc s;
  MaterialDesc m;
  m.color = albedo;
  m.diffuse = kd;
  m.ambient = 0;
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, m)));
  LightDesc l;
  l.position = light_pos;
  l.intensity = intensity;
  l.color = light_color;
  l.attenuation = Vec3(0, 0, 1);
  place(s, add_light(s, l));
  Tracer tracer(s);
  for (Vec3 p : {Vec3(0, 0, 0), Vec3(3, 0, 1), Vec3(-2, 0, 5), Vec3(0.5, 0, -0.25)}) {
    Vec3 to_light = light_pos - p;
    double d = glm::length(to_light);
    double cos_theta = to_light.y / d;
    double e = intensity * cos_theta / (d * d);
    Rgb got = tracer.trace(Ray{p + Vec3(0.1, 1.0, 0.2), Vec3(-0.1, -1.0, -0.2)});
    CHECK(got.x == Approx(kd * albedo.r * light_color.r * e).epsilon(1e-9));
    CHECK(got.y == Approx(kd * albedo.g * light_color.g * e).epsilon(1e-9));
    CHECK(got.z == Approx(kd * albedo.b * light_color.b * e).epsilon(1e-9));
  }
}

TEST_CASE("a shadowed point receives only ambient light", "[analytic]") {
  SceneDesc s;
  MaterialDesc m;
  m.ambient = 0.25;
  m.color = Color(0.8);
  s.settings.ambient_light = Color(0.5);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, m)));
  place(s, add_shape(s, Sphere{Vec3(0, 2, 0), 0.5}, add_material(s, m)));
  LightDesc l;
  l.position = Vec3(0, 5, 0);
  place(s, add_light(s, l));
  Tracer tracer(s);
  Rgb shadowed = tracer.trace(Ray{Vec3(0, 1, -3), Vec3(0, -1, 3)});
  CHECK(shadowed.x == Approx(0.25 * 0.8 * 0.5));
  Rgb lit = tracer.trace(Ray{Vec3(3, 1, 0), Vec3(0, -1, 0)});
  CHECK(lit.x > shadowed.x);
}

TEST_CASE("a mirror shows the reflected object's color times its reflectance", "[analytic]") {
  SceneDesc s;
  MaterialDesc mirror;
  mirror.reflect = Color(0.5, 1.0, 0.25);
  mirror.diffuse = 0;
  mirror.ambient = 0;
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, mirror)));
  place(s, add_shape(s, Sphere{Vec3(0, 5, 5), 1.0}, add_material(s, emissive(Color(0.2, 0.6, 0.8)))));
  Ray ray{Vec3(0, 5, -5), Vec3(0, -1, 1)};  // bounces at the origin towards (0,5,5)
  Rgb got = Tracer(s).trace(ray);
  CHECK(got.x == Approx(0.5 * 0.2));
  CHECK(got.y == Approx(1.0 * 0.6));
  CHECK(got.z == Approx(0.25 * 0.8));
  Rgb no_bounce = Tracer(s, 0).trace(ray);  // max_depth 0: no reflection rays
  CHECK(no_bounce.x == 0.0);
  CHECK(no_bounce.y == 0.0);
}

namespace {

// A clear glass slab (no diffuse or ambient term) filling -thickness <= y <= 0.
SceneDesc glass_slab(double thickness, double ior) {
  SceneDesc s;
  MaterialDesc glass;
  glass.transmit = Color(1.0);
  glass.ior = ior;
  glass.diffuse = 0;
  glass.ambient = 0;
  place(s, add_shape(s, Box{Vec3(-100, -thickness, -100), Vec3(100, 0, 100)}, add_material(s, glass)));
  return s;
}

}  // namespace

TEST_CASE("glass slab shifts a ray laterally by t sin(theta - theta') / cos(theta')", "[analytic]") {
  const double thickness = 2.0, ior = 1.5;
  SceneDesc s = glass_slab(thickness, ior);
  for (double deg : {10.0, 40.0, 65.0}) {
    double theta = deg * std::numbers::pi / 180.0;
    double theta_t = std::asin(std::sin(theta) / ior);
    double expected_shift = thickness * std::sin(theta - theta_t) / std::cos(theta_t);
    Vec3 dir(std::sin(theta), -std::cos(theta), 0);
    Vec3 origin(0, 5, 0);

    // Trace it through the same geometry and refraction the integrator uses.
    Tracer tracer(s);
    WorldHit in;
    REQUIRE(tracer.world->intersect(Ray{origin, dir}, Interval::positive(), in));
    Vec3 inside(0.0);
    REQUIRE(refract(dir, in.normal, 1.0 / ior, inside));
    Ray r2{offset_ray_origin(in.point, in.normal, inside, in.error), inside};
    WorldHit out;
    REQUIRE(tracer.world->intersect(r2, Interval::positive(), out));
    CHECK(out.point.y == Approx(-thickness));
    Vec3 outside(0.0);
    REQUIRE(refract(inside, -out.normal, ior, outside));  // leaving: normal faces the ray
    CHECK(glm::dot(outside, dir) == Approx(1.0));       // parallel to the incident ray

    // Distance from the exit point to the incident line.
    Vec3 rel = out.point - origin;
    double shift = glm::length(rel - glm::dot(rel, dir) * dir);
    // The tolerance covers the ray-origin offsets (error bounds, ~1e-14) at the two interfaces.
    CHECK(shift == Approx(expected_shift).epsilon(1e-7));
  }
}

TEST_CASE("the integrator sees through the slab along the shifted ray", "[analytic]") {
  const double thickness = 2.0, ior = 1.5, theta = 40.0 * std::numbers::pi / 180.0;
  const double theta_t = std::asin(std::sin(theta) / ior);
  SceneDesc s = glass_slab(thickness, ior);
  Vec3 dir(std::sin(theta), -std::cos(theta), 0);
  // Where the ray leaves the slab: entry at the origin, then along the refracted direction.
  Vec3 exit(thickness * std::tan(theta_t), -thickness, 0);
  Vec3 target = exit + 3.0 * dir;  // an emitter on the shifted ray, below the slab
  place(s, add_shape(s, Sphere{target, 0.2}, add_material(s, emissive(Color(0.3, 0.6, 0.9)))));
  Tracer tracer(s);
  Rgb through = tracer.trace(Ray{-5.0 * dir, dir});
  CHECK(through.x == Approx(0.3));
  CHECK(through.z == Approx(0.9));
  // Without refraction (ior 1) the straight line misses the emitter by the lateral shift.
  s.materials[0].ior = 1.0;
  Rgb straight = Tracer(s).trace(Ray{-5.0 * dir, dir});
  CHECK(straight.x == 0.0);
}

TEST_CASE("no shadow acne at tiny or huge scene scales", "[analytic]") {
  // A sphere lit from the eye: every visible point faces the light and nothing occludes it,
  // so no pixel on the sphere may fall back to ambient-only (self-shadowing from a spawned
  // ray that starts below the surface).
  for (double scale : {1e-4, 1.0, 1e5}) {
    SceneDesc s;
    s.settings.width = s.settings.height = 32;
    s.has_camera = true;
    s.camera.position = Vec3(0.3, 0.2, -5) * scale + Vec3(scale * 100, 0, 0);
    s.camera.look_at = Vec3(scale * 100, 0, 0);
    s.camera.fov = 30;
    MaterialDesc m;
    m.ambient = 0;
    m.diffuse = 1;
    m.reflect = Color(0.2);  // spawned reflection rays must not re-hit the sphere either
    place(s, add_shape(s, Sphere{Vec3(scale * 100, 0, 0), scale}, add_material(s, m)));
    LightDesc l;
    l.position = s.camera.position;
    place(s, add_light(s, l));
    RenderOptions o;
    o.aovs = {"depth"};
    RenderResult r = render(s, o);
    int sphere_pixels = 0, dark = 0;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        if (r.aovs["depth"].at(x, y)[0] == 0.0f) continue;  // background
        ++sphere_pixels;
        if (r.color.at(x, y)[0] <= 0.0f) ++dark;
      }
    INFO("scale " << scale);
    CHECK(sphere_pixels > 100);
    CHECK(dark == 0);
  }
}

TEST_CASE("glossy reflection blurs around the mirror image", "[analytic]") {
  // A rough mirror reflecting a large emitter: the average over many glossy samples stays
  // close to the mirror's value (the emitter fills most of the lobe) but individual samples
  // differ at the emitter's edge, unlike a perfect mirror.
  SceneDesc s;
  MaterialDesc rough;
  rough.reflect = Color(1.0);
  rough.diffuse = 0;
  rough.ambient = 0;
  rough.roughness = 0.3;
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, rough)));
  place(s, add_shape(s, Sphere{Vec3(0, 5, 5), 1.5}, add_material(s, emissive(Color(1.0)))));
  s.settings.seed = 3;
  Tracer tracer(s);
  Ray ray{Vec3(0, 5, -5), Vec3(0, -1, 1)};
  int lit = 0;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    Sampler sampler(0, 0, static_cast<uint32_t>(i), 3);
    RayCounters counters;
    lit += tracer.integrator->trace(ray, sampler, counters).x > 0.5;
  }
  CHECK(lit > n / 2);  // mostly on the emitter...
  CHECK(lit < n);      // ...but the lobe reaches past its edge
}

TEST_CASE("smooth normals opposite to the winding shade like consistent ones", "[analytic]") {
  // The triangle winds clockwise as seen from the camera (geometric normal +z, away from it);
  // its vertex normals point at the camera (-z). Lit head-on, it must shade as a lit
  // Lambertian surface, n·l = 1, whichever way the normals were given.
  const double kd = 0.7;
  MaterialDesc m;
  m.color = Color(1.0);
  m.diffuse = kd;
  m.ambient = 0;
  LightDesc l;
  l.kind = LightKind::Directional;
  l.direction = Vec3(0, 0, 1);  // travelling away from the camera: onto the visible side
  const Vec3 a(-1, -1, 0), b(1, -1, 0), c(0, 1, 0);
  const Ray ray{Vec3(0, -0.2, -5), Vec3(0, 0, 1)};
  for (Vec3 given : {Vec3(0, 0, -1), Vec3(0, 0, 1)}) {
    CAPTURE(given);
    SECTION("triangle") {
      SceneDesc s;
      Triangle t = triangle(a, b, c);
      t.normals = Boxed<TriangleNormals>(TriangleNormals{given, given, given});
      place(s, add_shape(s, t, add_material(s, m)));
      place(s, add_light(s, l));
      Rgb got = Tracer(s).trace(ray);
      CHECK(got.x == Approx(kd).epsilon(1e-9));
    }
    SECTION("mesh") {
      SceneDesc s;
      auto mesh = std::make_shared<MeshData>();
      mesh->positions = {a, b, c};
      mesh->normals = {given, given, given};
      mesh->indices = {0, 1, 2};
      s.meshes.push_back(mesh);
      place(s, add_shape(s, MeshRef{0, true}, add_material(s, m)));
      place(s, add_light(s, l));
      Rgb got = Tracer(s).trace(ray);
      CHECK(got.x == Approx(kd).epsilon(1e-9));
    }
  }
}

TEST_CASE("fresnel glass never outshines a uniform background", "[analytic]") {
  // A glass sphere in a uniformly white world (no lights, no ambient, no diffuse): every
  // path ends in the background, so energy conservation means no pixel may exceed 1 by
  // more than rounding — whatever reflect and transmit say.
  for (double reflect : {0.0, 0.5, 1.0}) {
    for (double ior : {1.33, 1.5, 2.42}) {
      CAPTURE(reflect, ior);
      SceneDesc s;
      s.settings.background = Color(1.0);
      MaterialDesc glass;
      glass.ambient = 0;
      glass.diffuse = 0;
      glass.reflect = Color(reflect);
      glass.transmit = Color(1.0);
      glass.ior = ior;
      glass.fresnel = true;
      place(s, add_shape(s, Sphere{Vec3(0), 1.0}, add_material(s, glass)));
      Tracer tracer(s, 8);
      double worst = 0;
      for (int i = 0; i <= 40; ++i) {
        double x = -1.0 + 2.0 * i / 40.0;  // across the sphere, centre to rim
        for (double y : {0.0, 0.37, 0.71}) {
          Rgb got = tracer.trace(Ray{Vec3(x, y, -5), Vec3(0, 0, 1)});
          worst = std::max({worst, got.x, got.y, got.z});
        }
      }
      CHECK(worst <= 1.0 + 1e-6);
      CHECK(worst >= 0.5);  // and the glass is not black either
    }
  }
}
