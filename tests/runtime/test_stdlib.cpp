// The standard library (stdlib/): found without a path, POV-Ray's include names mapped onto
// it, named colours at their standard values, every file evaluating; and the vector and
// spline builtins against closed forms.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <iostream>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "eval_helpers.hpp"
#include "render/renderer.hpp"
#include "runtime/stdlib_path.hpp"

using namespace rts;
using namespace rts::render;
using rts::test::eval_error;
using rts::test::eval_text;

namespace fs = std::filesystem;

namespace {

const std::string kStdlib = RTS_SOURCE_DIR "/stdlib";

EvalOptions with_stdlib() {
  EvalOptions o;
  o.stdlib_dir = kStdlib;
  return o;
}

// Runs `program`, whose assert()s are the checks; a failed assert fails the test with its message.
void passes(const std::string& program, const EvalOptions& opts = with_stdlib()) {
  try {
    eval_text(program, opts);
  } catch (const LanguageError& e) {
    FAIL(e.what() << "\nin:\n" << program);
  }
}

// sRGB transfer function: linear → encoded byte (what a PNG of a flat-lit white surface holds).
int srgb_byte(double linear) {
  double e = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
  return static_cast<int>(std::lround(e * 255));
}

}  // namespace

TEST_CASE("the standard library is found without a path, and from the build tree", "[eval][stdlib]") {
  // The test binary lives in the build tree, so the source tree's stdlib/ is found.
  std::string found = runtime::find_standard_library();
  REQUIRE(!found.empty());
  CHECK(fs::equivalent(found, kStdlib));
  // Without setting stdlib_dir: found by itself.
  passes("include \"colors.rts\"\nassert(Red == rgb(1, 0, 0))", EvalOptions{});
  // With the std/ prefix, and under POV-Ray's include name.
  passes("include \"std/colors.rts\"\nassert(Green == rgb(0, 1, 0))");
  passes("include \"colors.inc\"\nassert(Gray50 == rgb(0.5))");
  // Including it under two names is one file: included once, no "already defined".
  passes("include \"colors.inc\"\ninclude \"colors.rts\"\ninclude \"std/colors.rts\"\nassert(Blue.b == 1)");
}

TEST_CASE("a scene's own file wins over the library; std/ always means the library", "[eval][stdlib]") {
  fs::path dir = fs::temp_directory_path() / ("rts_stdlib_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "colors.rts") << "let Red = rgb(0.25)\n";
  std::ofstream(dir / "own.rts") << "include \"colors.rts\"\nassert(Red == rgb(0.25))\n";
  std::ofstream(dir / "lib.rts") << "include \"std/colors.rts\"\nassert(Red == rgb(1, 0, 0))\n";
  SourceManager sources;
  DiagnosticSink sink(std::cerr);
  CHECK_NOTHROW(evaluate_file(sources, (dir / "own.rts").string(), with_stdlib(), sink));
  CHECK_NOTHROW(evaluate_file(sources, (dir / "lib.rts").string(), with_stdlib(), sink));
  // Reads stay allowed under --allow-read's default roots: the library folder is one of them.
  EvalOptions restricted = with_stdlib();
  restricted.restrict_reads = true;
  CHECK_NOTHROW(evaluate_file(sources, (dir / "lib.rts").string(), restricted, sink));
  fs::remove_all(dir);
}

TEST_CASE("a missing library file is a located error naming the library", "[eval][stdlib]") {
  CHECK_THAT(eval_error("include \"std/nope.rts\"", with_stdlib()),
             Catch::Contains("cannot find include file 'std/nope.rts' in the standard library"));
  // A POV-Ray include rts lacks gets the usual message; folders never reach into the library.
  CHECK_THAT(eval_error("include \"stars.inc\"", with_stdlib()),
             Catch::Contains("cannot find include file 'stars.inc' next to this file (rts's standard library has no "
                             "'stars' either"));
  EvalOptions nowhere;
  nowhere.stdlib_dir = "/nonexistent-rts-stdlib";
  CHECK_THAT(eval_error("include \"colors.inc\"", nowhere), Catch::Contains("cannot find include file 'colors.inc'"));
  CHECK_THAT(eval_error("include \"std/../stdlib/colors.rts\"", with_stdlib()),
             Catch::Contains("cannot find include file"));
}

TEST_CASE("POV-Ray's colour names keep POV-Ray's values", "[eval][stdlib]") {
  // POV-Ray 3.7's colors.inc: Green is full green, Gray is 0.752941 (not CSS's #808080),
  // the GrayNN series are NN/100, Gold is POV-Ray's (0.8, 0.498039, 0.196078).
  passes(R"rts(include "colors.rts"
assert(Green == rgb(0, 1, 0), "Green")
assert(Yellow == rgb(1, 1, 0), "Yellow")
assert(Gray == rgb(0.752941), "Gray")
assert(Gray05 == rgb(0.05) and Gray50 == rgb(0.5) and Gray95 == rgb(0.95), "GrayNN")
assert(Gold == rgb(0.8, 0.498039, 0.196078), "Gold")
assert(Maroon == rgb(0.556863, 0.137255, 0.419608), "Maroon")
assert(White == rgb(1) and Black == rgb(0), "White/Black")
)rts");
}

TEST_CASE("CSS colour names hold CSS's colours, decoded to linear RGB", "[eval][stdlib]") {
  // Each name's value, encoded with the sRGB curve, is the byte CSS Color 4 gives it.
  struct Css {
    const char* name;
    int r, g, b;
  };
  const Css checks[] = {{"green", 0, 128, 0},         {"gray", 128, 128, 128},  {"red", 255, 0, 0},
                        {"rebeccapurple", 102, 51, 153}, {"cornflowerblue", 100, 149, 237},
                        {"tan_color", 210, 180, 140}, {"maroon", 128, 0, 0},    {"white", 255, 255, 255}};
  for (const Css& c : checks) {
    SceneDesc s = eval_text(std::string("include \"css_colors.rts\"\nsphere { radius = 1  material = material { color = ") +
                                c.name + " } }",
                            with_stdlib());
    REQUIRE(!s.materials.empty());
    const Color col = s.materials.back().color;
    INFO(c.name);
    CHECK(srgb_byte(col.r) == c.r);
    CHECK(srgb_byte(col.g) == c.g);
    CHECK(srgb_byte(col.b) == c.b);
  }
  // 148 CSS names (tan as tan_color), both files together without a clash.
  std::ifstream in(kStdlib + "/css_colors.rts");
  int lets = 0;
  for (std::string line; std::getline(in, line);) lets += line.rfind("let ", 0) == 0;
  CHECK(lets == 148);
  passes("include \"colors.rts\"\ninclude \"css_colors.rts\"\nassert(Green != green)");
}

TEST_CASE("every library file evaluates, and its materials and shapes build", "[eval][stdlib]") {
  for (const auto& entry : fs::directory_iterator(kStdlib)) {
    if (entry.path().extension() != ".rts") continue;
    INFO(entry.path().filename().string());
    passes("include \"" + entry.path().filename().string() + "\"");
  }
  SceneDesc s = eval_text(R"rts(include "textures.rts"
include "shapes.rts"
for m in [metal_gold, metal_silver, metal_copper, metal_chrome, metal_gold_brushed, glass_window,
          glass_crystal, glass_green, diamond, plastic(rgb(1, 0, 0)), matte(rgb(0.5)), mirror] {
    sphere { radius = 1  material = m }
}
rounded_box(<0, 0, 0>, <2, 1, 1>, 0.2)
wire_box(<0, 0, 0>, <1, 1, 1>, 0.05)
rounded_cylinder(<0, 0, 0>, <0, 2, 0>, 1, 0.25)
capsule(<0, 0, 0>, <1, 0, 0>, 0.3)
axes(2)
torus(1, 0.25, segments = 8, sides = 4)
)rts",
                          with_stdlib());
  CHECK(s.materials.size() >= 12);
  // Glass refracts at its index; metal reflects its colour.
  bool window = false, gold = false;
  for (const auto& m : s.materials) {
    window |= std::abs(m.ior - 1.52) < 1e-12 && m.fresnel;
    gold |= std::abs(m.reflect.r - 1.0) < 1e-12 && std::abs(m.reflect.g - 0.766) < 1e-12 && m.fresnel;
  }
  CHECK(window);
  CHECK(gold);
}

TEST_CASE("POV-Ray's finish and interior names are colour-free materials to derive from", "[eval][stdlib]") {
  // finish.rts (Shiny ...), metals.rts (F_MetalA ...) and glass.rts (F_Glass1 ..., I_Glass ...):
  // each sets only its finish or interior properties, so deriving adds the colour and keeps them.
  SceneDesc s = eval_text(R"rts(include "textures.rts"
sphere { radius = 1  material = Shiny with { color = rgb(1, 0, 0) } }
sphere { radius = 1  material = Phong_Glossy with { color = rgb(0, 1, 0) } }
sphere { radius = 1  material = Mirror }
sphere { radius = 1  material = Luminous with { color = rgb(0, 0, 1) } }
sphere { radius = 1  material = I_Glass with { transmit = 1 } }
sphere { radius = 1  material = F_Glass5 }
sphere { radius = 1  material = F_MetalE }
)rts",
                          with_stdlib());
  REQUIRE(s.materials.size() >= 7);
  auto find = [&](auto pred) {
    for (const auto& m : s.materials)
      if (pred(m)) return true;
    return false;
  };
  // Shiny: a tight half-vector highlight on the derived red, rts's default diffuse kept.
  CHECK(find([](const MaterialDesc& m) {
    return m.color.r == 1 && m.color.g == 0 && m.blinn && m.specular > 0.8 && m.shininess >= 500 && m.diffuse == 0.7;
  }));
  // Phong_Glossy: a Phong lobe and a faint reflection.
  CHECK(find([](const MaterialDesc& m) { return m.color.g == 1 && !m.blinn && m.specular == 1 && m.reflect.r > 0.05 && m.reflect.r < 0.3; }));
  // Mirror: no diffuse or ambient light, a full reflection, no highlight.
  CHECK(find([](const MaterialDesc& m) { return m.diffuse == 0 && m.ambient == 0 && m.reflect.g == 1 && m.specular == 0; }));
  // Luminous: its colour whatever the light.
  CHECK(find([](const MaterialDesc& m) { return m.color.b == 1 && m.ambient == 1 && m.diffuse == 0; }));
  // I_Glass: glass's index, used once the material transmits.
  CHECK(find([](const MaterialDesc& m) { return m.ior == 1.5 && m.transmit.r == 1; }));
  // F_Glass5: Fresnel reflections; F_MetalE: the most reflective of the metal finishes.
  CHECK(find([](const MaterialDesc& m) { return m.fresnel && m.reflect.r == 1 && m.diffuse == 0; }));
  // F_MetalE is POV-Ray's: brilliance 6, metallic, roughness 1/120, reflection 0.8.
  CHECK(find([](const MaterialDesc& m) {
    return m.blinn && m.reflect.r == 0.8 && m.shininess == 120 && m.brilliance == 6 && m.metallic == 1 && m.ambient == 0.1;
  }));
}

TEST_CASE("every material name of the library renders in both integrators", "[eval][stdlib]") {
  // Every top-level `let` of the material files (woods, stones, metals, glass, textures: rts's
  // own names and POV-Ray's T_Wood12, T_Gold_3C, Chrome_Metal ...), found as rts import finds
  // them, and the finishes), on its own ball in a grid; rendered Whitted and path, each ball's
  // middle is finite, and lit (not the background) unless it is a clear glass or a mirror.
  std::vector<std::string> names;
  std::vector<bool> clear;
  for (const char* file : {"woods.rts", "stones.rts", "metals.rts", "glass.rts", "finish.rts", "textures.rts"}) {
    std::ifstream in(kStdlib + "/" + file);
    REQUIRE(in);
    std::string line;
    while (std::getline(in, line)) {
      if (line.rfind("let ", 0) != 0) continue;
      const std::string name = line.substr(4, line.find_first_of(" =", 4) - 4);
      if (name.size() > 3 && name.compare(name.size() - 3, 3, "_f0") == 0) continue;   // metals' colours
      if (name.rfind("P_", 0) == 0) continue;   // metals.inc's pigments (colours), woods.inc's grains
      // woods.inc's colour maps, textures.inc's pigments (Jade, Candy_Cane: patterns), colours and colour maps are no
      // materials; its materials (Glass, M_Glass, Chrome_Metal ...) are tested.
      {
        const std::size_t v = line.find_first_not_of(' ', line.find('=') + 1);
        const std::string word = line.substr(v, line.find_first_of(" {(", v) - v);
        static const std::set<std::string> patterns = {"bozo", "spotted", "granite", "marble", "wood", "agate",
                                                       "onion", "leopard", "wrinkles", "crackle", "cells", "bumps",
                                                       "dents", "ripples", "waves", "gradient", "checker", "rgb"};
        if (line[v] == '[' || line[v] == '<' || patterns.count(word)) continue;
      }
      names.push_back(name);
      // Clear glasses show the background through them, and the perfect mirror reflects it.
      const bool glassy = std::string(file) == "glass.rts" || name.find("Glass") != std::string::npos ||
                          name == "Crystal" || name == "mirror" || name == "Mirror";
      clear.push_back(glassy);
    }
  }
  REQUIRE(names.size() > 250);
  const int columns = 20, rows = static_cast<int>((names.size() + columns - 1) / columns), cell = 6;
  std::string program = "include \"textures.rts\"\npoint_light { position = <0, 0, -100> }\n";
  program += fmt::format("camera {{ projection = \"orthographic\"  position = <{0}, {1}, -10>  look_at = <{0}, {1}, 0>  "
                         "view_width = {2} }}\n",
                         columns - 1.0, -(rows - 1.0), 2.0 * columns);
  for (std::size_t i = 0; i < names.size(); ++i)
    program += fmt::format("sphere {{ center = <{}, {}, 0>  radius = 0.9  material = {} }}\n", 2.0 * (i % columns),
                           -2.0 * (i / columns), names[i]);
  SceneDesc s = eval_text(program, with_stdlib());
  s.settings.width = columns * cell;
  s.settings.height = rows * cell;
  s.settings.background = Color(0.3, 0.5, 0.7);
  for (IntegratorKind kind : {IntegratorKind::Whitted, IntegratorKind::Path}) {
    s.settings.integrator = kind;
    s.settings.samples = kind == IntegratorKind::Path ? 4 : 1;
    RenderOptions o;
    o.threads = 2;
    const RenderResult r = rts::render::render(s, o);
    CHECK(r.stats.rays.nan_samples == 0);
    for (std::size_t i = 0; i < names.size(); ++i) {
      const int x = static_cast<int>(i % columns) * cell + cell / 2, y = static_cast<int>(i / columns) * cell + cell / 2;
      // The mean of the ball's middle 3x3 pixels: in path mode a partly reflective ball's single
      // pixel may have picked the reflection lobe at all 4 samples (F_MetalD: 0.4^4 = 2.6%) and
      // show just the background; 36 samples all doing so is 0.4^36.
      float px[3] = {0, 0, 0};
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          for (int c = 0; c < 3; ++c)
            px[c] += r.color.rgb[(static_cast<std::size_t>(y + dy) * r.color.width + x + dx) * 3 + c] / 9.0f;
      INFO(names[i] << (kind == IntegratorKind::Path ? " (path)" : " (whitted)") << ": " << px[0] << " " << px[1] << " "
                    << px[2]);
      REQUIRE((std::isfinite(px[0]) && std::isfinite(px[1]) && std::isfinite(px[2])));
      const bool background = std::abs(px[0] - 0.3f) < 1e-3f && std::abs(px[1] - 0.5f) < 1e-3f && std::abs(px[2] - 0.7f) < 1e-3f;
      if (!clear[i]) CHECK(!background);
    }
  }
}

TEST_CASE("shape macros check their arguments", "[eval][stdlib]") {
  CHECK_THAT(eval_error("include \"shapes.rts\"\nrounded_box(<0, 0, 0>, <1, 1, 1>, 0.6)", with_stdlib()),
             Catch::Contains("rounded_box: radius 0.6 must be > 0 and at most half the smallest side"));
  CHECK_THAT(eval_error("include \"shapes.rts\"\nrounded_cylinder(<0, 0, 0>, <0, 1, 0>, 0.5, 0.6)", with_stdlib()),
             Catch::Contains("rounded_cylinder: edge 0.6"));
}

TEST_CASE("vrotate and vaxis_rotate turn vectors as `rotate` turns objects", "[eval][builtins]") {
  passes(R"rts(
macro near(a, b) { return length(a - b) < 1e-12 }
assert(near(vrotate(<1, 0, 0>, <0, 90, 0>), <0, 0, -1>), "x about y by 90 is -z (as POV-Ray)")
assert(near(vrotate(<1, 0, 0>, <0, 0, 90>), <0, 1, 0>), "x about z by 90 is y")
assert(near(vrotate(<0, 1, 0>, <90, 0, 0>), <0, 0, 1>), "y about x by 90 is z")
// x first, then y, then z: <0,0,1> about x by 90 is -y, then about z by 90 is +x.
assert(near(vrotate(<0, 0, 1>, <90, 0, 90>), <1, 0, 0>), "order x, y, z")
assert(near(vaxis_rotate(<1, 0, 0>, <0, 1, 0>, 90), vrotate(<1, 0, 0>, <0, 90, 0>)), "axis y = rotate y")
assert(near(vaxis_rotate(<1, 0, 0>, <0, 5, 0>, 90), <0, 0, -1>), "the axis is normalised")
// 120 degrees about the diagonal cycles the axes: x -> y -> z.
assert(near(vaxis_rotate(<1, 0, 0>, <1, 1, 1>, 120), <0, 1, 0>), "diagonal x->y")
assert(near(vaxis_rotate(<0, 1, 0>, <1, 1, 1>, 120), <0, 0, 1>), "diagonal y->z")
assert(abs(vlength(<3, 4, 12>) - 13) < 1e-12 and vdot(<1, 2, 3>, <4, 5, 6>) == 32, "vlength, vdot")
assert(vcross(<1, 0, 0>, <0, 1, 0>) == <0, 0, 1> and near(vnormalize(<0, 3, 4>), <0, 0.6, 0.8>), "vcross, vnormalize")
assert(lerp(2, 4, 0.25) == 2.5 and lerp(<0, 0, 0>, <2, 4, 8>, 0.5) == <1, 2, 4>, "lerp")
assert(distance(<1, 2, 3>, <4, 6, 3>) == 5, "distance")
assert(smoothstep(0, 1, -1) == 0 and smoothstep(0, 1, 2) == 1 and smoothstep(0, 2, 1) == 0.5, "smoothstep ends/middle")
assert(abs(smoothstep(0, 1, 0.25) - 0.15625) < 1e-15, "smoothstep 3t^2-2t^3")
assert(abs(degrees(radians(37)) - 37) < 1e-12 and clamp(5, 0, 2) == 2, "degrees/radians, clamp")
)rts");
  CHECK_THAT(eval_error("vaxis_rotate(<1, 0, 0>, <0, 0, 0>, 90)"), Catch::Contains("axis must not be the zero vector"));
  CHECK_THAT(eval_error("vrotate(<1, 0, 0>, 90)"), Catch::Contains("argument 2 of 'vrotate' must be a vector"));
}

TEST_CASE("spline: linear, cubic and natural against closed forms", "[eval][builtins]") {
  passes(R"rts(
macro near(a, b) { return abs(a - b) < 1e-12 }
let line = [[0, 0], [1, 2], [3, 6]]
assert(near(spline("linear", line, 0.5), 1) and near(spline("linear", line, 2), 4), "linear")
assert(spline("linear", line, -1) == 0 and spline("linear", line, 9) == 6, "clamped at the ends")
assert(spline("linear", [[0, <0, 0, 0>], [2, <2, 4, 6>]], 1) == <1, 2, 3>, "vectors")
assert(spline("linear", [[0, rgb(0)], [1, rgb(1)]], 0.5) == rgb(0.5), "colors")
// Catmull-Rom's tangents are exact for a parabola, so the curve is the parabola: y = t^2.
let para = [[0, 0], [1, 1], [2, 4], [3, 9]]
assert(near(spline("cubic", para, 1.5), 2.25), "cubic on t^2 at 1.5")
assert(near(spline("cubic", para, 1), 1) and near(spline("cubic", para, 2), 4), "cubic passes its inner keys")
assert(near(spline("cubic", para, 0), 1), "cubic: the first key only shapes the tangent")
// Natural spline through (0,0), (1,1), (2,0): M1 = -3, so S(0.5) = -0.5/8 + 1.5*0.5 = 0.6875.
assert(near(spline("natural", [[0, 0], [1, 1], [2, 0]], 0.5), 0.6875), "natural, three keys")
assert(near(spline("natural", [[0, 0], [1, 1], [2, 0]], 1.5), 0.6875), "natural, symmetric")
// A natural spline through collinear keys is the line, however they are spaced.
assert(near(spline("natural", [[0, 1], [0.5, 2], [2, 5], [2.25, 5.5]], 1.3), 3.6), "natural reproduces a line")
)rts");
  CHECK_THAT(eval_error("spline(\"bezier\", [[0, 0], [1, 1]], 0)"), Catch::Contains("unknown kind 'bezier'"));
  CHECK_THAT(eval_error("spline(\"cubic\", [[0, 0], [1, 1], [2, 2]], 0)"),
             Catch::Contains("a cubic spline needs at least 4 keys, got 3"));
  CHECK_THAT(eval_error("spline(\"linear\", [[0, 0], [0, 1]], 0)"), Catch::Contains("the keys' t must increase"));
  CHECK_THAT(eval_error("spline(\"linear\", [[0, 0], [1, <1, 1, 1>]], 0)"),
             Catch::Contains("the values must be all numbers, all vectors or all colors"));
}

TEST_CASE("trace: the first hit on an object and its normal, in world space", "[eval][builtins]") {
  passes(R"rts(
macro near(a, b) { return length(a - b) < 1e-9 }
// A unit sphere moved to <0, 1, 0>: a ray down the y axis meets its top at <0, 2, 0>, normal +y.
let ball = sphere { radius = 1 } translate <0, 1, 0>
let h = trace(ball, <0, 5, 0>, <0, -1, 0>)
assert(near(h[0], <0, 2, 0>) and near(h[1], <0, 1, 0>), "top of the ball")
// From the side at height 1.5: x = sqrt(1 - 0.25), the normal is the point minus the centre.
let s = trace(ball, <-5, 1.5, 0>, <1, 0, 0>)
assert(near(s[0], <-sqrt(0.75), 1.5, 0>) and near(s[1], <-sqrt(0.75), 0.5, 0>), "side of the ball")
// A miss is none; the direction need not be unit.
assert(trace(ball, <5, 5, 5>, <0, 1, 0>) == none, "miss")
assert(near(trace(ball, <0, 5, 0>, <0, -10, 0>)[0], <0, 2, 0>), "unnormalised direction")
// A rotated, scaled box inside a group: scale 2 makes the top face y = 2.
let crate = group { box { min = <-1, 0, -1>  max = <1, 1, 1> } } scale 2 rotate <0, 45, 0>
let c = trace(crate, <0.1, 9, 0.1>, <0, -1, 0>)
assert(near(c[0], <0.1, 2, 0.1>) and near(c[1], <0, 1, 0>), "top of the crate")
// Placing on a surface: spheres dropped onto the ball sit on it.
for i in 0 .. 5 {
    let p = trace(ball, <i * 0.2, 9, 0>, <0, -1, 0>)
    assert(abs(length(p[0] - <0, 1, 0>) - 1) < 1e-9, "on the surface")
    sphere { center = p[0] + p[1] * 0.1  radius = 0.1 }
}
)rts");
  CHECK_THAT(eval_error("trace(sphere { radius = 1 }, <0, 0, 0>, <0, 0, 0>)"),
             Catch::Contains("trace: the direction must not be the zero vector"));
  CHECK_THAT(eval_error("trace(3, <0, 0, 0>, <0, 0, 1>)"),
             Catch::Contains("argument 1 of 'trace' must be an object (a shape or a group), got a number"));
}

TEST_CASE("fog settings are checked and reach the scene", "[eval][fog]") {
  SceneDesc s = eval_text("settings { fog_distance = 10  fog_color = rgb(0.5)  fog_offset = 1  fog_altitude = 2 }");
  CHECK(s.settings.fog_distance == 10);
  CHECK(s.settings.fog_color.g == 0.5);
  CHECK(s.settings.fog_offset == 1);
  CHECK(s.settings.fog_altitude == 2);
  CHECK(eval_text("settings { }").settings.fog_distance == 0);  // no fog unless asked
  CHECK_THAT(eval_error("settings { fog_distance = -1 }"), Catch::Contains("fog_distance"));
  CHECK_THAT(eval_error("settings { fog_altitude = -1 }"), Catch::Contains("fog_altitude"));
  CHECK_THAT(eval_error("settings { fog_colour = rgb(1) }"), Catch::Contains("did you mean 'fog_color'?"));
}

TEST_CASE("sky_sphere: layers bottom first, gradient with a color map, transmit, located errors", "[eval][sky]") {
  SceneDesc s = eval_text(R"rts(settings { environment = sky_sphere {
  layers = [gradient { axis = "y"  color_map = [[0, rgb(1)], [1, rgb(0, 0, 1)]] },
            bozo { color_map = [[0, rgb(1), 1], [1, rgb(0.5), 0.25]] } scale 0.5,
            rgb(0.1)]
} rotate <0, 30, 0> })rts");
  REQUIRE(s.settings.environment < s.textures.size());
  const TextureDesc& sky = s.textures[s.settings.environment];
  CHECK(sky.kind == TextureKind::SkySphere);
  REQUIRE(sky.sky_layers.size() == 3);
  const TextureDesc& gradient = s.textures[sky.sky_layers[0]];
  CHECK(gradient.kind == TextureKind::Pattern);
  CHECK(gradient.pattern.kind == PatternKind::Gradient);
  CHECK(gradient.pattern.axis == 1);
  const TextureDesc& clouds = s.textures[sky.sky_layers[1]];
  CHECK(clouds.pattern.color_map[0].transmit == 1.0);
  CHECK(clouds.pattern.color_map[1].transmit == 0.25);
  CHECK(clouds.transform[0][0] == Approx(0.5));
  CHECK(sky.sky_layers[2] == kNoId);
  CHECK(sky.sky_layer_colors[2].r == Approx(0.1));
  CHECK(sky.transform[2][0] == Approx(std::sin(30.0 * 3.14159265358979 / 180.0)));   // the sky's own rotate
  // Solid colours alone (POV-Ray's `sky_sphere { pigment { rgb ... } }`, imported): a list of
  // colours travels as a list of vectors and is still layers.
  SceneDesc plain = eval_text("settings { environment = sky_sphere { layers = [rgb(0.2, 0.3, 0.4), rgb(0.5)] } }");
  const TextureDesc& plain_sky = plain.textures[plain.settings.environment];
  REQUIRE(plain_sky.sky_layers.size() == 2);
  CHECK(plain_sky.sky_layers[0] == kNoId);
  CHECK(plain_sky.sky_layer_colors[0].b == Approx(0.4));
  CHECK(plain_sky.sky_layer_colors[1].g == Approx(0.5));
  // The two-colour gradient is unchanged without a color_map.
  CHECK(eval_text("settings { environment = gradient { axis = \"y\" } }").textures[0].kind == TextureKind::Gradient);

  CHECK_THAT(eval_error("settings { environment = sky_sphere { } }"), Catch::Contains("needs property 'layers'"));
  CHECK_THAT(eval_error("settings { environment = sky_sphere { layer = [bozo { }] } }"),
             Catch::Contains("did you mean 'layers'?"));
  CHECK_THAT(eval_error("settings { environment = sky_sphere { layers = [bozo { }, 3] } }"),
             Catch::Contains("textures and colors"));
  CHECK_THAT(eval_error("settings { environment = sky_sphere { layers = [bozo { color_map = [[0, rgb(1), 1.5]] }] } }"),
             Catch::Contains("transmit 1.5"));
  CHECK_THAT(eval_error("settings { environment = sky_sphere { layers = [sky_sphere { layers = [bozo { }] }] } }"),
             Catch::Contains("layer 1 of sky_sphere is a sky_sphere"));
  CHECK_THAT(eval_error("sphere { radius = 1  material = material { color = sky_sphere { layers = [bozo { }] } } }"),
             Catch::Contains("settings { environment = ... }"));
  // Located: file:line:col of the property.
  CHECK_THAT(eval_error("settings {\n  environment = sky_sphere { layers = [bozo { color_map = [[0, rgb(1), -1]] }] } }"),
             Catch::Contains(":2:"));
}
