// Pattern textures and noise in the language: the noise builtins, pattern blocks and their
// errors, and user functions compiled once (runtime/function_compiler.cpp) agreeing exactly
// with the interpreter.
#include <algorithm>
#include <cmath>
#include <string>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "eval_helpers.hpp"
#include "render/geometry/function/compiled_function.hpp"
#include "render/geometry/function/noise.hpp"
#include "render/shade/pattern/patterns.hpp"
#include "render/geometry/shapes/height_field.hpp"
#include "render/geometry/shapes/isosurface.hpp"

using namespace rts;
using rts::test::eval_diagnostic;
using rts::test::eval_text;

namespace {

// The value of a number expression, read back exactly through a texture's scale (which must
// be positive: callers keep it so).
double value_of(const std::string& prelude, const std::string& expr) {
  render::SceneDesc s = eval_text(prelude + "\nplane { normal = <0, 1, 0>  material = material { texture = gradient { scale = " + expr + " } } }");
  REQUIRE(!s.textures.empty());
  return s.textures.back().scale;
}

}  // namespace

TEST_CASE("noise builtins call the renderer's noise", "[patterns]") {
  const glm::dvec3 p(0.1234, 5.678, -9.1011);
  CHECK(value_of("", "noise(<0.1234, 5.678, -9.1011>)") == render::pattern::noise01(p));
  CHECK(value_of("", "fbm(<0.1234, 5.678, -9.1011>) + 1") == render::pattern::fbm(p, 6, 2, 0.5) + 1);
  CHECK(value_of("", "turbulence(<0.1234, 5.678, -9.1011>, 5, 2.1, 0.45)") ==
        render::pattern::turbulence(p, 5, 2.1, 0.45));
  CHECK(value_of("", "cells(<0.1234, 5.678, -9.1011>)") == render::pattern::cells(p));
  CHECK(value_of("", "worley(<0.1234, 5.678, -9.1011>)") == render::pattern::worley(p));
  CHECK(eval_diagnostic("let x = fbm(<1, 2, 3>, 0)").message ==
        "the octaves of 'fbm' must be a whole number from 1 to 16, got 0");
  CHECK(eval_diagnostic("let x = noise(1)").message == "argument 1 of 'noise' must be a vector, got a number");
  // POV-Ray's vturbulence(lambda, omega, octaves, p): each component read back alone.
  const glm::dvec3 vt = render::pattern::vector_turbulence(p, 6, 2.0, 0.5);
  for (int k = 0; k < 3; ++k)
    CHECK(value_of("let v = vturbulence(2, 0.5, 6, <0.1234, 5.678, -9.1011>)",
                   fmt::format("v.{} + 100", "xyz"[k])) == vt[k] + 100);
  CHECK(eval_diagnostic("let v = vturbulence(2, 0.5, 1.5, <1, 2, 3>)").message ==
        "the octaves of 'vturbulence' must be a whole number from 1 to 16, got 1.5");
}

TEST_CASE("pattern blocks build pattern textures with POV-Ray's defaults", "[patterns]") {
  render::SceneDesc s = eval_text(
      "plane { normal = <0, 1, 0>  material = material { texture = marble { turbulence = 0.8  color_map = [[0, rgb(1)], [0.5, rgb(0.5, 0.2, 0.1)], "
      "[1, rgb(0)]] } scale 0.5 } }\n"
      "sphere { radius = 1  material = material { texture = wood { turbulence = <0.1, 0.2, 0>  octaves = 3  wave = \"sine\" } "
      "bump = bumps { }  bump_scale = 0.3 } }\n");
  REQUIRE(s.textures.size() == 3);
  const render::TextureDesc& marble = s.textures[0];
  CHECK(marble.kind == render::TextureKind::Pattern);
  CHECK(marble.pattern.kind == render::PatternKind::Marble);
  CHECK(marble.pattern.wave == render::WaveKind::Triangle);
  CHECK(marble.pattern.turbulence == glm::dvec3(0.8));
  REQUIRE(marble.pattern.color_map.size() == 3);
  CHECK(marble.pattern.color_map[1].color == glm::dvec3(0.5, 0.2, 0.1));
  CHECK(marble.transform[0][0] == 0.5);
  const render::TextureDesc& wood = s.textures[1];
  CHECK(wood.pattern.wave == render::WaveKind::Sine);
  CHECK(wood.pattern.octaves == 3);
  CHECK(wood.pattern.turbulence == glm::dvec3(0.1, 0.2, 0));
  // No color_map: black at 0 to white at 1.
  REQUIRE(s.textures[2].pattern.color_map.size() == 2);
  CHECK(s.textures[2].pattern.color_map[1].color == glm::dvec3(1.0));
  CHECK(s.materials[1].bump == 2);
}

TEST_CASE("omega and lambda reach the pattern: marble's and wood's turbulence as the noise functions predict",
          "[patterns]") {
  // Marble adds POV-Ray's scalar turbulence T(p) = noise01(p) + sum_{i>=1} omega^i noise01(lambda^i p)
  // to x; wood takes the vector warp p + turbulence * vector_turbulence(p, octaves, lambda, omega)
  // first. Each block's omega and lambda must reach both, from the language to the value.
  namespace pat = render::pattern;
  auto pattern_of = [](const std::string& block) {
    const render::SceneDesc s = eval_text("plane { normal = <0, 1, 0>  material = material { texture = " + block + " } }");
    REQUIRE(s.textures.size() == 1);
    return s.textures[0].pattern;
  };
  auto pov_turbulence = [](const glm::dvec3& p, int octaves, double lambda, double omega) {
    double v = pat::noise01(p), l = lambda, o = omega;
    for (int i = 2; i <= octaves; ++i, l *= lambda, o *= omega) v += o * pat::noise01(p * l);
    return v;
  };
  const glm::dvec3 points[] = {{0.3, 0.2, 0.1}, {-1.7, 2.25, 0.8}, {4.1, -0.35, 2.2}, {0.05, 0.9, -3.3}, {2.6, 1.3, 7.7}};
  struct Params { double omega, lambda; };
  for (const Params& k : {Params{0.5, 2.0}, Params{0.8, 2.0}, Params{0.5, 3.1}, Params{0.3, 1.7}}) {
    const std::string props = fmt::format("octaves = 4  omega = {}  lambda = {}", k.omega, k.lambda);
    INFO(props);
    const render::PatternDesc marble = pattern_of("marble { turbulence = 0.7  " + props + " }");
    const render::PatternDesc wood = pattern_of("wood { turbulence = <0.4, 0.3, 0.2>  " + props + " }");
    CHECK(marble.omega == k.omega);
    CHECK(marble.lambda == k.lambda);
    for (const glm::dvec3& p : points) {
      INFO("p = " << p.x << ", " << p.y << ", " << p.z);
      CHECK(pat::raw_value(marble, p) == Approx(p.x + 0.7 * pov_turbulence(p, 4, k.lambda, k.omega)).epsilon(1e-13));
      const glm::dvec3 q = p + glm::dvec3(0.4, 0.3, 0.2) * pat::vector_turbulence(p, 4, k.lambda, k.omega);
      CHECK(pat::raw_value(wood, p) == Approx(std::sqrt(q.x * q.x + q.y * q.y)).epsilon(1e-13));
    }
  }
  // And the change is not lost in the noise: each parameter moves both patterns' values.
  const render::PatternDesc m0 = pattern_of("marble { turbulence = 0.7 }");
  const render::PatternDesc m_omega = pattern_of("marble { turbulence = 0.7  omega = 0.8 }");
  const render::PatternDesc m_lambda = pattern_of("marble { turbulence = 0.7  lambda = 3.1 }");
  const render::PatternDesc w0 = pattern_of("wood { turbulence = 0.5 }");
  const render::PatternDesc w_omega = pattern_of("wood { turbulence = 0.5  omega = 0.8 }");
  const render::PatternDesc w_lambda = pattern_of("wood { turbulence = 0.5  lambda = 3.1 }");
  double moved[4] = {0, 0, 0, 0};
  for (const glm::dvec3& p : points) {
    moved[0] += std::fabs(pat::raw_value(m_omega, p) - pat::raw_value(m0, p));
    moved[1] += std::fabs(pat::raw_value(m_lambda, p) - pat::raw_value(m0, p));
    moved[2] += std::fabs(pat::raw_value(w_omega, p) - pat::raw_value(w0, p));
    moved[3] += std::fabs(pat::raw_value(w_lambda, p) - pat::raw_value(w0, p));
  }
  for (double m : moved) CHECK(m / 5 > 0.01);
}

TEST_CASE("a gradient block with a color_map is the gradient pattern, with its axis, turbulence and wave",
          "[patterns]") {
  const render::SceneDesc s = eval_text(
      "plane { normal = <0, 1, 0>  material = material { texture = gradient { axis = \"z\"  turbulence = 0.3  octaves = 3  "
      "color_map = [[0, rgb(1, 0, 0)], [1, rgb(0, 0, 1)]] } } }");
  REQUIRE(s.textures.size() == 1);
  const render::PatternDesc& d = s.textures[0].pattern;
  CHECK(s.textures[0].kind == render::TextureKind::Pattern);
  CHECK(d.kind == render::PatternKind::Gradient);
  CHECK(d.axis == 2);
  CHECK(d.turbulence == glm::dvec3(0.3));
  CHECK(d.octaves == 3);
  CHECK(d.wave == render::WaveKind::Ramp);
  // Its value: the warped point's z, ramped (render test "gradient with a color map: ...").
  const glm::dvec3 p(0.4, -1.2, 2.35);
  const glm::dvec3 w = p + 0.3 * render::pattern::vector_turbulence(p, 3, 2.0, 0.5);
  CHECK(render::pattern::wave(d, render::pattern::raw_value(d, p)) == Approx(w.z - std::floor(w.z)).margin(1e-12));
}

TEST_CASE("noise in a height_field function: the grid holds the language's noise, and rays meet it there",
          "[patterns][height_field]") {
  // h(p) = noise(4 p + <0.3, 0, 0.7>) stays in [0, 1], so the height field stores it unclamped
  // (as a float) at x = ix / (nx - 1), z = iz / (nz - 1); a ray straight down at a grid point
  // lands on that height.
  const std::string prelude = "macro terrain(p) { return noise(p * 4 + <0.3, 0, 0.7>) }\n";
  const render::SceneDesc s = eval_text(prelude + "height_field { function = terrain  resolution = [9, 7] }\n");
  const render::HeightField* f = nullptr;
  for (const render::ShapeDesc& d : s.shapes)
    if (const auto* g = shape_if<render::HeightField>(d.geometry)) f = g;
  REQUIRE(f != nullptr);
  REQUIRE(f->data->nx == 9);
  REQUIRE(f->data->nz == 7);
  double spread_lo = 1, spread_hi = 0;
  for (int iz = 0; iz < 7; ++iz)
    for (int ix = 0; ix < 9; ++ix) {
      const double x = ix / 8.0, z = iz / 6.0;
      const double h = f->data->height[iz * 9 + ix];
      INFO("grid point " << ix << ", " << iz);
      CHECK(h == Approx(render::pattern::noise01(glm::dvec3(x, 0, z) * 4.0 + glm::dvec3(0.3, 0, 0.7))).margin(1e-6));
      spread_lo = std::min(spread_lo, h);
      spread_hi = std::max(spread_hi, h);
      if ((ix + iz) % 4 == 0) {
        // The language's own noise() at that point (read back exactly), and the traced surface.
        const double lang = value_of(prelude, fmt::format("terrain(<{:.17g}, 0, {:.17g}>)", x, z));
        CHECK(h == Approx(lang).margin(1e-6));
        render::SurfaceHit hit;
        // Just inside the square's edges, so the ray stays in the column.
        const double rx = std::clamp(x, 1e-9, 1 - 1e-9), rz = std::clamp(z, 1e-9, 1 - 1e-9);
        REQUIRE(intersect(*f, render::Ray{render::Vec3(rx, 5, rz), render::Vec3(0, -1, 0)}, render::Interval::positive(), hit));
        CHECK(hit.point.y == Approx(lang).margin(1e-5));
      }
    }
  // Noise, not a constant: the grid spans a good part of [0, 1].
  CHECK(spread_hi - spread_lo > 0.2);
}

TEST_CASE("noise in an isosurface function: rays stop where f crosses the threshold, not before", "[patterns]") {
  // f(p) = |p| - 1 + 0.3 noise(3 p): a lumpy ball. |grad f| <= 1 + 0.3 * 3 * 0.5 * kNoiseGradientBound
  // = 2.8, so max_gradient 3 is safe. Each probe ray from outside must stop where f = threshold
  // (|f| <= max_gradient * accuracy) and f must stay above the threshold on the way in.
  namespace pat = render::pattern;
  const render::SceneDesc s = eval_text(
      "macro lumpy(p) { return length(p) - 1 + 0.3 * noise(p * 3) }\n"
      "isosurface { function = lumpy  threshold = 0  max_gradient = 3  accuracy = 1e-6\n"
      "             contained_by = sphere { center = <0, 0, 0>  radius = 2 } }\n");
  const render::IsosurfaceData* iso = nullptr;
  for (const render::ShapeDesc& d : s.shapes)
    if (const auto* g = shape_if<render::Isosurface>(d.geometry)) iso = &**g;
  REQUIRE(iso != nullptr);
  auto f = [](const glm::dvec3& p) { return glm::length(p) - 1 + 0.3 * pat::noise01(p * 3.0); };
  double r_lo = 10, r_hi = 0;
  const int n = 40;
  for (int i = 0; i < n; ++i) {
    // Directions spread over the sphere (a golden-angle spiral), rays from radius 5 inwards,
    // offset a little so they do not all pass through the origin.
    const double y = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - y * y), phi = 2.399963229728653 * i;
    const glm::dvec3 dir(r * std::cos(phi), y, r * std::sin(phi));
    const glm::dvec3 origin = dir * 5.0 + glm::dvec3(0.05, -0.03, 0.02);
    const render::Ray ray{origin, -dir};
    render::SurfaceHit hit;
    INFO("ray " << i);
    REQUIRE(intersect(*iso, ray, render::Interval::positive(), hit));
    CHECK(std::fabs(f(hit.point)) < 3 * 1e-6 * 2);
    for (int k = 1; k < 400; ++k) {   // outside all the way from the container to the hit
      const double t = 3.0 + (hit.t - 3.0) * k / 400.0;
      REQUIRE(f(origin - dir * t) > 0.0);
    }
    r_lo = std::min(r_lo, glm::length(hit.point));
    r_hi = std::max(r_hi, glm::length(hit.point));
  }
  // The noise shapes it: radii between 0.7 and 1, not one sphere's.
  CHECK(r_lo >= 0.7 - 1e-6);
  CHECK(r_hi <= 1.0 + 1e-6);
  CHECK(r_hi - r_lo > 0.05);
}

TEST_CASE("noise in a placement loop places each copy at its noise value", "[patterns]") {
  const render::SceneDesc s = eval_text("for i in 0 .. 6 { sphere { center = <i, noise(<i * 0.37, 0.5, 0>), 0>  radius = 0.1 } }\n");
  REQUIRE(s.shapes.size() == 6);
  for (int i = 0; i < 6; ++i) {
    const auto* sp = shape_if<render::Sphere>(s.shapes[i].geometry);
    REQUIRE(sp != nullptr);
    CHECK(sp->center.y == render::pattern::noise01(glm::dvec3(i * 0.37, 0.5, 0)));
  }
}

TEST_CASE("a color map entry may be a texture (POV-Ray's pigment_map)", "[patterns]") {
  render::SceneDesc s = eval_text(
      "let inner = gradient { axis = \"y\" } scale 0.5\n"
      "plane { normal = <0, 1, 0>  material = material { texture = bozo { color_map = [[0, rgb(1, 0, 0)], "
      "[0.5, inner], [1, rgb(0, 0, 1), 0.25]] } } }\n");
  REQUIRE(s.textures.size() == 2);
  const auto& map = s.textures[1].pattern.color_map;
  REQUIRE(map.size() == 3);
  CHECK(map[0].texture == render::kNoId);
  CHECK(map[1].texture == 0);   // the entry's texture, realised before the map's own
  CHECK(s.textures[0].transform[0][0] == 0.5);
  CHECK(map[2].transmit == 0.25);
  // A textured entry takes its transmit from the texture: a third number is refused.
  CHECK(eval_diagnostic("plane { normal = <0, 1, 0>  material = material { texture = bozo { color_map = "
                        "[[0, checker(rgb(0), rgb(1), 1), 0.5]] } } }")
            .message.starts_with("property 'color_map' of bozo cannot hold this list"));
}

TEST_CASE("pattern block errors are located and say what to do", "[patterns]") {
  auto message = [](const std::string& text) { return eval_diagnostic(text).message; };
  CHECK(message("let t = marble { turbulance = 1 }\nplane { normal = <0, 1, 0>  material = material { texture = t } }")
            .starts_with("unknown property 'turbulance' for marble; did you mean 'turbulence'?"));
  CHECK(message("plane { normal = <0, 1, 0>  material = material { texture = bozo { color_map = [[0.5, rgb(1)], [0.2, rgb(0)]] } } }") ==
        "the color_map of bozo must list its values in ascending order: entry 2 (0.2) comes after 0.5");
  CHECK(message("plane { normal = <0, 1, 0>  material = material { texture = bozo { color_map = [[0.5, 1]] } } }")
            .starts_with("property 'color_map' of bozo cannot hold this list: a color map is a list of [number, color] pairs"));
  CHECK(message("plane { normal = <0, 1, 0>  material = material { texture = bozo { wave = \"square\" } } }")
            .starts_with("property 'wave' of bozo must be \"ramp\""));
  CHECK(message("plane { normal = <0, 1, 0>  material = material { texture = granite { octaves = 40 } } }") ==
        "property 'octaves' of granite must be from 1 to 16, got 40");
  CHECK(message("plane { normal = <0, 1, 0>  material = material { texture = pattern { } } }")
            .starts_with("pattern needs property 'function'"));
  CHECK(message("plane { normal = <0, 1, 0>  material = material { texture = agate { function = 1 } } }")
            .starts_with("unknown property 'function' for agate"));
}

TEST_CASE("a user function is compiled once and agrees exactly with the interpreter", "[patterns]") {
  const std::string prelude =
      "let k = 2\n"
      "let shift = <1, 0, 0.5>\n"
      "macro ring(q, width = 0.5) { return abs(length(q) % 1 - width) }\n"
      "macro f(p) {\n"
      "  let q = p * k + shift\n"
      "  let v = 0\n"
      "  if q.x > 1.5 { v = fbm(q, 4, 2, 0.5) * 0.5 + 0.5 } else { v = turbulence(q) + noise(-q) }\n"
      "  v += 0.1 * sin(q.y) * cos(q.z) + ring(q) + worley(q / 3) * cells(q) + max(0, dot(normalize(q), <0, 1, 0>))\n"
      "  if v > 2 { return pow(v, 0.5) + atan2(q.y, q.x) * 0 + clamp(mix(0.2, 0.4, 0.5), 0, 1) } else { return v + 0.001 }\n"
      "}\n"
      "plane { normal = <0, 1, 0>  material = material { texture = pattern { function = f } } }\n";
  const render::SceneDesc s = eval_text(prelude);
  REQUIRE(s.textures.size() == 1);
  const auto& fn = s.textures[0].pattern.function;
  REQUIRE(fn != nullptr);
  CHECK(s.textures[0].pattern.wave == render::WaveKind::Clamp);
  const glm::dvec3 points[] = {{0.3, 0.2, 0.1}, {-1.7, 2.25, 0.8}, {4.1, -0.35, 2.2}, {0.05, 0.9, -3.3}, {2.5, 2.5, 2.5}};
  for (const glm::dvec3& p : points) {
    const std::string call = fmt::format("f(<{:.17g}, {:.17g}, {:.17g}>)", p.x, p.y, p.z);
    INFO(call);
    CHECK(value_of(prelude, call) == fn->eval(p));
  }
}

TEST_CASE("what a compiled function may not do is a located error", "[patterns]") {
  auto diag = [](const std::string& body) {
    return eval_diagnostic("macro f(p) {\n" + body + "\n}\nplane { normal = <0, 1, 0>  material = material { texture = pattern { function = f } } }");
  };
  Diagnostic d = diag("for i in 0 .. 3 { }\nreturn 1");
  CHECK(d.message.starts_with("a compiled function (a pattern or isosurface macro) may hold only"));
  CHECK(d.loc.line() == 2);
  CHECK(diag("return p").message == "macro 'f' returns a vector; a pattern function returns a number");
  CHECK(diag("let s = \"text\"\nreturn 1").message.starts_with("this expression cannot be compiled"));
  CHECK(diag("return print(1)").message.starts_with("'print' cannot be called in a compiled function"));
  CHECK(diag("if p.x > 0 { return 1 }\nreturn 0").message ==
        "in a compiled function, an 'if' must return on both branches or on neither");
  CHECK(diag("let n = 1").message == "macro 'f' must end with 'return' to be used as a function");
  CHECK(eval_diagnostic("macro g(p) { return g(p) }\nplane { normal = <0, 1, 0>  material = material { texture = pattern { function = g } } }")
            .message.starts_with("macros nest more than 32 deep"));
  CHECK(eval_diagnostic("macro g() { return 1 }\nplane { normal = <0, 1, 0>  material = material { texture = pattern { function = g } } }")
            .message.starts_with("macro 'g' is used as a function of a point, so it needs a parameter"));
}
