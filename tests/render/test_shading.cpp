// Shading building blocks: Snell refraction, Schlick, the material unit (Phong, Fresnel weights,
// the glossy lobe, the BSDF seam), light attenuation and falloff, and the camera's conventions.
#include <bit>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include <catch2/catch.hpp>

#include "render/sample/camera.hpp"
#include "render/shade/integrator.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/material.hpp"

using namespace rts::render;

namespace {
// Sample `index` of light.samples, as the integrator draws it: `jitter` in [0,1)^2 places it
// within its stratum; `perm_seed` pairs strata when samples is not a square.
LightSample sample_light(const CompiledLight& l, const Vec3& point, int index, glm::dvec2 jitter, uint32_t perm_seed) {
  glm::dvec2 u = stratified_2d(static_cast<uint32_t>(index), static_cast<uint32_t>(l.samples), l.strata_side, jitter,
                               perm_seed);
  return rts::render::sample_light(l, point, u);
}
}  // namespace

TEST_CASE("refract obeys Snell's law", "[shading]") {
  double theta = 30.0 * std::numbers::pi / 180.0;
  Vec3 incident(std::sin(theta), -std::cos(theta), 0);
  Vec3 out;
  REQUIRE(refract(incident, Vec3(0, 1, 0), 1.0 / 1.5, out));
  double sin_t = out.x;  // |out| = 1
  CHECK(glm::length(out) == Approx(1.0));
  CHECK(sin_t == Approx(std::sin(theta) / 1.5));
  CHECK(out.y < 0);
}

TEST_CASE("refract reports total internal reflection past the critical angle", "[shading]") {
  double critical = std::asin(1.0 / 1.5);
  Vec3 n(0, 1, 0), out;
  double above = critical + 0.01, below = critical - 0.01;
  CHECK_FALSE(refract(Vec3(std::sin(above), -std::cos(above), 0), n, 1.5, out));
  CHECK(refract(Vec3(std::sin(below), -std::cos(below), 0), n, 1.5, out));
}

TEST_CASE("Schlick: f0 at normal incidence, 1 at grazing", "[shading]") {
  CHECK(schlick(1.0, 0.04) == Approx(0.04));
  CHECK(schlick(0.0, 0.04) == Approx(1.0));
  CHECK(schlick(0.5, 0.04) > 0.04);
}

TEST_CASE("attenuation 1/(c + l d + q d^2)", "[shading]") {
  CHECK(attenuation_factor(Vec3(1, 0, 0), 7.0) == Approx(1.0));
  CHECK(attenuation_factor(Vec3(0, 0, 1), 2.0) == Approx(0.25));
  CHECK(attenuation_factor(Vec3(1, 1, 1), 2.0) == Approx(1.0 / 7.0));
  CHECK(attenuation_factor(Vec3(0, 0, 0), 2.0) == 0.0);  // guarded, not inf
}

// A spot light at (0, 10, 0) aimed straight down, and its radiance 10 away at `deg` degrees
// off its axis.
struct SpotAtAngle {
  LightDesc d;
  CompiledLight l;
  SpotAtAngle(double radius, double falloff) {
    d.kind = LightKind::Spot;
    d.position = Vec3(0, 10, 0);
    d.point_at = Vec3(0, 0, 0);
    d.radius = radius;
    d.falloff = falloff;
    l = compile_lights({d})[0];
  }
  double operator()(double deg) const {
    double a = deg * std::numbers::pi / 180.0;
    Vec3 p = d.position + Vec3(std::sin(a), -std::cos(a), 0) * 10.0;
    return sample_light(l, p, 0, glm::dvec2(0.5), 0).radiance.x;
  }
};

TEST_CASE("spot light: full inside radius, zero past falloff, smooth between", "[shading]") {
  const SpotAtAngle at_angle(10, 20);
  CHECK(at_angle(0) == Approx(1.0));
  CHECK(at_angle(9) == Approx(1.0));
  CHECK(at_angle(21) == 0.0);
  double mid = at_angle(15);
  CHECK(mid > 0.0);
  CHECK(mid < 1.0);
  CHECK(at_angle(12) > at_angle(18));
}

TEST_CASE("an area light with point_at is a spot: the cone's factor from its centre, on every sample", "[shading]") {
  // POV-Ray's spotlight with an area_light attenuates once per light, from its centre: each
  // sample of the rectangle carries the same factor (a point's light is the samples' mean).
  const SpotAtAngle spot(10, 20);
  LightDesc d = spot.d;
  d.kind = LightKind::Area;
  d.area_spot = true;
  d.u = Vec3(2, 0, 0);
  d.v = Vec3(0, 0, 2);
  d.samples = 1;
  const CompiledLight l = compile_lights({d})[0];
  for (double deg : {0.0, 12.0, 15.0, 18.0, 25.0}) {
    const double a = deg * std::numbers::pi / 180.0;
    const Vec3 p = d.position + Vec3(std::sin(a), -std::cos(a), 0) * 10.0;
    for (glm::dvec2 on : {glm::dvec2(0.1, 0.2), glm::dvec2(0.5), glm::dvec2(0.9, 0.7)}) {
      INFO("angle " << deg << " sample " << on.x << ", " << on.y);
      CHECK(rts::render::sample_light(l, p, on).radiance.x == Approx(spot(deg)).margin(1e-12));
    }
  }
  // Without point_at the same rectangle lights every direction.
  d.area_spot = false;
  const CompiledLight plain = compile_lights({d})[0];
  CHECK(rts::render::sample_light(plain, d.position + Vec3(10, -1, 0), glm::dvec2(0.5)).radiance.x == Approx(1.0));
}

TEST_CASE("variable reflection: reflect_min head-on to reflect at grazing angles (POV-Ray's reflection { min, max })", "[shading]") {
  // The unpolarised Fresnel reflectance: 4% head-on for glass (((1.5 - 1) / 2.5)^2), all of it at
  // grazing incidence, none across an index-matched interface, all under total reflection.
  CHECK(fresnel_dielectric(1.0, 1.5) == Approx(0.04).margin(1e-12));
  CHECK(fresnel_dielectric(0.0, 1.5) == Approx(1.0).margin(1e-12));
  CHECK(fresnel_dielectric(0.7, 1.0) == Approx(0.0).margin(1e-12));
  CHECK(fresnel_dielectric(0.2, 1.0 / 1.5) == 1.0);
  CHECK(fresnel_dielectric(0.5, 1.5) > fresnel_dielectric(0.9, 1.5));
  MaterialDesc m;
  m.reflect = Color(0.9);
  m.has_reflect_min = true;
  m.reflect_min = Color(0.1);
  // Without fresnel: (1 - cos)^falloff blends reflect_min (head-on) into reflect (grazing).
  CHECK(variable_reflection(m, 1.0, 1.5).x == Approx(0.1));
  CHECK(variable_reflection(m, 0.0, 1.5).x == Approx(0.9));
  CHECK(variable_reflection(m, 0.5, 1.5).x == Approx(0.1 + 0.8 * 0.5));
  m.reflect_falloff = 3.0;
  CHECK(variable_reflection(m, 0.5, 1.5).x == Approx(0.1 + 0.8 * 0.125));
  // With fresnel: F reflect + (1 - F) reflect_min.
  m.fresnel = true;
  CHECK(variable_reflection(m, 1.0, 1.5).x == Approx(0.04 * 0.9 + 0.96 * 0.1));
}

TEST_CASE("spot light of radius 90: full over the half-space in front, none behind", "[shading]") {
  // POV-Ray scenes write `radius 90` (with falloff 90): a hemisphere light.
  const SpotAtAngle at_angle(90, 90);
  CHECK(at_angle(0) == Approx(1.0));
  CHECK(at_angle(89.9) == Approx(1.0));
  CHECK(at_angle(90.1) == 0.0);
  CHECK(at_angle(179) == 0.0);
}

TEST_CASE("directional light: no attenuation, direction reversed", "[shading]") {
  LightDesc d;
  d.kind = LightKind::Directional;
  d.direction = Vec3(0, -2, 0);
  d.intensity = 3;
  d.attenuation = Vec3(0, 0, 1);
  CompiledLight l = compile_lights({d})[0];
  LightSample s = sample_light(l, Vec3(100, -50, 3), 0, glm::dvec2(0.5), 0);
  CHECK(s.radiance.x == Approx(3.0));
  CHECK(s.direction.y == Approx(1.0));
  CHECK(std::isinf(s.distance));
}

TEST_CASE("area light samples lie on the rectangle and split the power", "[shading]") {
  LightDesc d;
  d.kind = LightKind::Area;
  d.position = Vec3(0, 5, 0);
  d.u = Vec3(2, 0, 0);
  d.v = Vec3(0, 0, 4);
  d.samples = 9;
  CompiledLight l = compile_lights({d})[0];
  double total = 0;
  for (int i = 0; i < 9; ++i) {
    LightSample s = sample_light(l, Vec3(0), i, glm::dvec2(0.3, 0.7), 99);
    Vec3 p = s.direction * s.distance;
    CHECK(p.y == Approx(5.0));
    CHECK(std::abs(p.x) <= 1.0);
    CHECK(std::abs(p.z) <= 2.0);
    total += s.radiance.x;
  }
  CHECK(total == Approx(1.0));
}

TEST_CASE("camera: left-handed view, +x to the right, +y up", "[shading]") {
  CameraDesc c;
  c.position = Vec3(0, 0, -5);
  c.look_at = Vec3(0);
  c.fov = 90;
  Camera cam(c, 200, 100);
  Ray right = cam.generate(200, 50, glm::dvec2(0.5));  // right edge, middle row
  CHECK(right.direction.x > 0);
  CHECK(right.direction.x == Approx(right.direction.z));  // 45 degrees: fov 90
  Ray top = cam.generate(100, 0, glm::dvec2(0.5));
  CHECK(top.direction.y > 0);
  CHECK(top.direction.y / top.direction.z == Approx(0.5));  // aspect 2:1
}

TEST_CASE("orthographic camera: parallel rays over view_width", "[shading]") {
  CameraDesc c;
  c.projection = Projection::Orthographic;
  c.position = Vec3(0, 0, -5);
  c.view_width = 4;
  Camera cam(c, 100, 100);
  Ray left = cam.generate(0, 50, glm::dvec2(0.5));
  CHECK(left.origin.x == Approx(-2.0));
  CHECK(left.direction.z == Approx(1.0));
}

TEST_CASE("depth of field: every lens sample converges on the focal plane", "[shading]") {
  CameraDesc c;
  c.position = Vec3(0, 0, -5);
  c.aperture = 0.5;
  c.focus_distance = 5;
  Camera cam(c, 64, 64);
  Ray a = cam.generate(10, 20, glm::dvec2(0.1, 0.9)), b = cam.generate(10, 20, glm::dvec2(0.8, 0.2));
  CHECK(a.origin != b.origin);
  double ta = 5.0 / a.direction.z, tb = 5.0 / b.direction.z;  // both reach z = 0
  Vec3 pa = a.at(ta), pb = b.at(tb);
  CHECK(pa.x == Approx(pb.x).margin(1e-9));
  CHECK(pa.y == Approx(pb.y).margin(1e-9));
}

TEST_CASE("disc area light samples lie inside the inscribed ellipse", "[shading]") {
  LightDesc d;
  d.kind = LightKind::Area;
  d.position = Vec3(0, 5, 0);
  d.u = Vec3(4, 0, 0);  // ellipse semi-axes 2 (x) and 1 (z)
  d.v = Vec3(0, 0, 2);
  d.disc = true;
  d.samples = 7;  // not a square: N-rooks strata
  CompiledLight l = compile_lights({d})[0];
  double max_r = 0;
  for (int i = 0; i < 7; ++i)
    for (double j : {0.01, 0.5, 0.99}) {
      LightSample s = sample_light(l, Vec3(0), i, glm::dvec2(j, 1.0 - j), 1234);
      Vec3 p = s.direction * s.distance;
      double r = (p.x / 2) * (p.x / 2) + p.z * p.z;  // ellipse equation, <= 1 inside
      CHECK(r <= 1.0 + 1e-9);
      max_r = std::max(max_r, r);
    }
  CHECK(max_r > 0.5);  // the samples spread out, not all at the centre
}

TEST_CASE("material unit: Fresnel glass splits one budget, TIR reflects it all, opaque Fresnel rises", "[shading]") {
  MaterialDesc glass;
  glass.transmit = Color(0.9);
  glass.reflect = Color(0.1);
  glass.fresnel = true;
  const Vec3 n(0, 1, 0);
  for (double deg : {0.0, 30.0, 60.0, 85.0}) {
    const double a = deg * 3.141592653589793 / 180.0;
    const Vec3 incident(std::sin(a), -std::cos(a), 0);
    const double cos_i = std::cos(a);
    SpecularWeights w = specular_weights(glass, incident, n, cos_i, 1.0, 1.5);
    CAPTURE(deg);
    // reflect + transmit never exceeds max(reflect, transmit) = 0.9.
    CHECK(w.reflect.x + w.transmit.x <= 0.9 + 1e-12);
    CHECK(w.transmit.x > 0.0);
    CHECK(glm::length(w.refracted) == Approx(1.0));
    // Leaving the glass past the critical angle (41.8 degrees): all of it reflects.
    SpecularWeights inside = specular_weights(glass, incident, n, cos_i, 1.5, 1.0);
    if (deg > 42.0) {
      CHECK(inside.transmit == Rgb(0.0));
      CHECK(inside.reflect.x == Approx(0.9));
    }
  }
  MaterialDesc metal;
  metal.reflect = Color(0.5);
  metal.fresnel = true;
  SpecularWeights head_on = specular_weights(metal, Vec3(0, -1, 0), n, 1.0, 1.0, 1.0);
  SpecularWeights grazing = specular_weights(metal, Vec3(0, -1, 0), n, 0.0, 1.0, 1.0);
  CHECK(head_on.reflect.x == Approx(0.5));
  CHECK(grazing.reflect.x == Approx(1.0));
  metal.fresnel = false;
  CHECK(specular_weights(metal, Vec3(0, -1, 0), n, 0.0, 1.0, 1.0).reflect.x == 0.5);
}

TEST_CASE("material unit: POV-Ray's brilliance steepens the diffuse term; metallic tints the highlight", "[shading]") {
  MaterialDesc m;
  m.diffuse = 0.5;
  m.brilliance = 3;
  const Vec3 n(0, 1, 0), to_light = glm::normalize(Vec3(1, 1, 0));
  const double n_dot_l = glm::dot(n, to_light);
  const Rgb surface(0.9, 0.5, 0.2);
  CHECK(phong<false>(m, surface, n, to_light, n_dot_l, n).y == Approx(0.5 * std::pow(n_dot_l, 3) * 0.5));
  // Metallic: the highlight takes the surface's colour facing the light (POV-Ray's F is 5e-7
  // there) and the light's own colour at grazing (F = 1).
  m.diffuse = 0;
  m.brilliance = 1;
  m.specular = 1;
  m.shininess = 10;
  m.blinn = true;
  m.metallic = 1;
  const Rgb facing = phong<true>(m, surface, n, n, 1.0, n);
  CHECK(facing.x == Approx(0.9).epsilon(1e-5));
  CHECK(facing.z == Approx(0.2).epsilon(1e-5));
  const Vec3 grazing = glm::normalize(Vec3(1, 1e-9, 0));
  const Rgb edge = phong<true>(m, surface, n, grazing, glm::dot(n, grazing), glm::normalize(Vec3(-1, 1e-9, 0)));
  CHECK(edge.z / edge.x == Approx(1.0).epsilon(1e-3));
  // Half metallic at 60 degrees: POV-Ray's curve gives F = 0.0114 there (x = 2/3).
  m.metallic = 0.5;
  const Vec3 l60 = glm::normalize(Vec3(std::sqrt(3.0), 1, 0));
  const Vec3 v60 = glm::normalize(Vec3(-std::sqrt(3.0), 1, 0));
  const double f = 0.014567225 / ((2.0 / 3.0 - 1.12) * (2.0 / 3.0 - 1.12)) - 0.011612903;
  const Rgb mid = phong<true>(m, surface, n, l60, 0.5, v60);
  CHECK(mid.z / mid.x == Approx((1 + 0.5 * (1 - f) * (0.2 - 1)) / (1 + 0.5 * (1 - f) * (0.9 - 1))));
  // Left at their defaults, neither changes a thing (the Whitted images stay as they were).
  MaterialDesc plain;
  plain.specular = 0.3;
  CHECK(phong<true>(plain, surface, n, to_light, n_dot_l, n).x ==
        plain.diffuse * n_dot_l * 0.9 + 0.3 * std::pow(glm::dot(2.0 * n_dot_l * n - to_light, n), plain.shininess));
}

TEST_CASE("material unit: Phong peaks along the mirror direction; glossy rays stay above the surface", "[shading]") {
  MaterialDesc m;
  m.diffuse = 0.5;
  m.specular = 0.4;
  m.shininess = 20;
  const Vec3 n(0, 1, 0), to_light = glm::normalize(Vec3(1, 1, 0));
  const double n_dot_l = glm::dot(n, to_light);
  const Rgb peak = phong<true>(m, Rgb(1.0), n, to_light, n_dot_l, glm::normalize(Vec3(-1, 1, 0)));
  const Rgb off = phong<true>(m, Rgb(1.0), n, to_light, n_dot_l, glm::normalize(Vec3(-0.5, 1, 0)));
  const Rgb plain = phong<false>(m, Rgb(1.0), n, to_light, n_dot_l, glm::normalize(Vec3(-1, 1, 0)));
  CHECK(plain.x == Approx(0.5 * n_dot_l));
  CHECK(peak.x == Approx(0.5 * n_dot_l + 0.4));
  CHECK(off.x < peak.x);
  CHECK(off.x > plain.x);
  // A rough mirror's rays spread, but never below the surface.
  m.roughness = 0.8;
  Sampler s(0, 0, 0, 7);
  const Vec3 mirror = glm::normalize(Vec3(1, 0.05, 0));
  bool spread = false;
  for (int i = 0; i < 200; ++i) {
    Vec3 d = reflected_direction(m, mirror, n, s);
    CHECK(glm::dot(d, n) > 0.0);
    spread = spread || glm::dot(d, mirror) < 0.99;
  }
  CHECK(spread);
  m.roughness = 0.0;
  CHECK(reflected_direction(m, mirror, n, s) == mirror);
}

namespace {
// A Lambertian BSDF, to show (and check) the seam's shape.
struct TestLambert {
  Rgb albedo{0.5};
  Vec3 n{0, 1, 0};
  Rgb f(const Vec3&) const { return albedo / 3.141592653589793; }
  double pdf(const Vec3& wi) const { return std::max(0.0, glm::dot(n, wi)) / 3.141592653589793; }
  bool sample(double, glm::dvec2, BsdfSample&) const { return false; }
};
}  // namespace
static_assert(Bsdf<TestLambert>, "the BSDF seam's three calls");
static_assert(!Bsdf<MaterialDesc>, "a material description is not a BSDF");

TEST_CASE("the glossy lobe's inline cube root stays within 64 ulps of libm's", "[shading]") {
  // unit_cbrt replaced std::cbrt in in_unit_ball: the lobe's radial distribution is r^3
  // uniform (1.5e-14 relative moves no image byte).
  uint64_t x = 0x9e3779b97f4a7c15ULL;
  for (int k = 0; k < 200000; ++k) {
    x = rts::render::mix64(x);
    double u = static_cast<double>(x >> 11) * 0x1.0p-53;
    if (k % 5 == 0) u = std::ldexp(u, -(k % 64));   // values near 0 too
    const double want = std::cbrt(u), got = unit_cbrt(u);
    const auto ulps = std::llabs(static_cast<long long>(std::bit_cast<uint64_t>(want)) -
                                 static_cast<long long>(std::bit_cast<uint64_t>(got)));
    REQUIRE(ulps <= 64);
  }
  CHECK(unit_cbrt(0.0) == 0.0);
  CHECK(unit_cbrt(0.125) == Approx(0.5).epsilon(1e-14));
  CHECK(unit_cbrt(1.0) == Approx(1.0).epsilon(1e-14));
}
