// Noise and procedural patterns (render/shade/pattern/): ranges, mean, continuity, the
// gradient bound isosurfaces rely on, determinism (exact values, any thread count), POV-Ray's
// meanings of the patterns, the wave functions, color-map lookups, and compiled functions.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>

#include <catch2/catch.hpp>

#include "render/renderer.hpp"
#include "render/geometry/function/compiled_function.hpp"
#include "render/geometry/function/noise.hpp"
#include "render/shade/pattern/patterns.hpp"
#include "render/shade/texture.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;
namespace pat = rts::render::pattern;

namespace {

// A fixed, platform-independent sequence of points (splitmix64), spread over [-50, 50]^3.
struct Points {
  uint64_t state = 12345;
  double unit() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
  Vec3 next(double half = 50.0) { return {(unit() * 2 - 1) * half, (unit() * 2 - 1) * half, (unit() * 2 - 1) * half}; }
};

constexpr int kSamples = 100'000;



}  // namespace

TEST_CASE("noise functions stay in their documented ranges", "[noise]") {
  Points pts;
  double lo = 1, hi = -1;
  for (int i = 0; i < kSamples; ++i) {
    const Vec3 p = pts.next();
    const double n = pat::gradient_noise(p);
    lo = std::min(lo, n);
    hi = std::max(hi, n);
    REQUIRE(n >= -1.0);
    REQUIRE(n <= 1.0);
    const double n01 = pat::noise01(p);
    REQUIRE((n01 >= 0.0 && n01 <= 1.0));
    const double f = pat::fbm(p, 6, 2.0, 0.5);
    REQUIRE((f >= -1.0 && f <= 1.0));
    const double t = pat::turbulence(p, 6, 2.0, 0.5);
    REQUIRE((t >= 0.0 && t <= 1.0));
    const double c = pat::cells(p);
    REQUIRE((c >= 0.0 && c < 1.0));
    double f1, f2;
    pat::worley2(p, f1, f2);
    REQUIRE((f1 >= 0.0 && f1 <= std::sqrt(3.0)));
    REQUIRE(f2 >= f1);
  }
  // The range is used, not a sliver of it.
  CHECK(lo < -0.6);
  CHECK(hi > 0.6);
  // Non-finite and huge points give 0, never NaN.
  CHECK(pat::gradient_noise(Vec3(NAN, 0, 0)) == 0.0);
  CHECK(pat::gradient_noise(Vec3(1e300, 2, 3)) == 0.0);
  CHECK(pat::cells(Vec3(INFINITY, 0, 0)) == 0.0);
  CHECK(pat::worley(Vec3(0, -INFINITY, 0)) == 0.0);
}

TEST_CASE("gradient noise is zero on the lattice and has mean zero", "[noise]") {
  for (int x = -3; x <= 3; ++x)
    for (int y = -3; y <= 3; ++y) CHECK(pat::gradient_noise(Vec3(x, y, 7 - x)) == 0.0);
  Points pts;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double n = pat::gradient_noise(pts.next());
    sum += n;
    sum2 += n * n;
  }
  const double mean = sum / kSamples, sd = std::sqrt(sum2 / kSamples - mean * mean);
  // Points 100 apart on average are nearly independent: the mean's standard error is
  // sd / sqrt(N) ~ 0.0007; 0.005 is seven of them (false-failure rate below 1e-11).
  CHECK(std::fabs(mean) < 0.005);
  CHECK(sd > 0.1);   // not flat
}

TEST_CASE("noise repeats every 256 units along each axis, exactly", "[noise]") {
  // The lattice hashes floor(p) modulo 256 (noise.cpp's lattice()), so gradient noise, the
  // vector noise and their octave sums at lambda 2 (each octave's shift a multiple of 256 too)
  // repeat with period 256 on every axis: bit for bit when p + 256 is exact, as here (points
  // on a 2^-32 grid in [-300, 300]^3). cells and worley hash the whole cell index and do not.
  Points pts;
  auto grid = [](double v) { return std::round(v * 0x1.0p32) * 0x1.0p-32; };
  auto same = [](const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  int moved_by_128 = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const Vec3 r = pts.next(300.0);
    const Vec3 p(grid(r.x), grid(r.y), grid(r.z));
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 shift(0.0);
      shift[axis] = 256.0;
      const Vec3 q = p + shift;
      REQUIRE(q - shift == p);   // the shift is exact
      INFO("p = " << p.x << ", " << p.y << ", " << p.z << ", axis " << axis);
      REQUIRE(pat::gradient_noise(q) == pat::gradient_noise(p));
      REQUIRE(pat::gradient_noise(p - shift) == pat::gradient_noise(p));
      REQUIRE(pat::noise01(q) == pat::noise01(p));
      REQUIRE(same(pat::vector_noise(q), pat::vector_noise(p)));
      if (i % 10 == 0) {
        REQUIRE(pat::fbm(q, 6, 2.0, 0.5) == pat::fbm(p, 6, 2.0, 0.5));
        REQUIRE(pat::turbulence(q, 6, 2.0, 0.5) == pat::turbulence(p, 6, 2.0, 0.5));
        REQUIRE(same(pat::vector_turbulence(q, 6, 2.0, 0.5), pat::vector_turbulence(p, 6, 2.0, 0.5)));
      }
      Vec3 half(0.0);
      half[axis] = 128.0;
      if (pat::gradient_noise(p + half) != pat::gradient_noise(p)) ++moved_by_128;
    }
  }
  // 256 is the period, not a multiple of a shorter one: half of it moves nearly every value.
  CHECK(moved_by_128 > 3 * n * 99 / 100);
}

TEST_CASE("noise is continuous and its gradient stays under the documented bound", "[noise]") {
  Points pts;
  constexpr double h = 1e-5;
  double max_slope = 0;
  for (int i = 0; i < kSamples; ++i) {
    const Vec3 p = pts.next(8.0);
    const double n = pat::gradient_noise(p);
    const Vec3 g((pat::gradient_noise(p + Vec3(h, 0, 0)) - n) / h, (pat::gradient_noise(p + Vec3(0, h, 0)) - n) / h,
                 (pat::gradient_noise(p + Vec3(0, 0, h)) - n) / h);
    max_slope = std::max(max_slope, glm::length(g));
  }
  INFO("largest |grad noise| measured: " << max_slope);
  CHECK(max_slope < pat::kNoiseGradientBound);
  CHECK(max_slope > 1.0);   // the bound is not vacuous: real slopes come near it
  // fbm and turbulence are averages of scaled noise: their slope is at most the bound times
  // the largest frequency.
  const Vec3 p(0.3, 0.7, 1.1);
  const double step = 1e-7;
  CHECK(std::fabs(pat::fbm(p + Vec3(step, 0, 0), 4, 2, 0.5) - pat::fbm(p, 4, 2, 0.5)) <=
        pat::kNoiseGradientBound * 8 * step * 1.01);
}

TEST_CASE("noise values are exact and the same on every build", "[noise]") {
  // Reference values recorded from this implementation (GCC -O0 and -O2, GCC -O3
  // -march=native with -ffp-contract=off, clang -O2 all give these bits): any build, compiler
  // or sanitizer must reproduce them exactly (no platform RNG, no fused multiply-adds).
  const Vec3 p(0.1234, 5.678, -9.1011);
  CHECK(pat::gradient_noise(p) == -0x1.9ed6677888b4p-3);
  CHECK(pat::fbm(p, 6, 2, 0.5) == 0x1.9217a5c6113dfp-10);
  CHECK(pat::turbulence(p, 5, 2.1, 0.45) == 0x1.8030a955df9d5p-3);
  CHECK(pat::worley(p) == 0x1.310c310e1d3e1p-1);
  CHECK(pat::cells(p) == 0x1.00502e56a447dp-1);
  const Vec3 v = pat::vector_noise(p);
  CHECK(v.x == pat::gradient_noise(p));
  CHECK(v.y == -0x1.0d4c7fde4fbfbp-1);
  CHECK(v.z == -0x1.1ed901121c3a8p-2);
  const Vec3 t = pat::vector_turbulence(p, 6, 2, 0.5);
  CHECK(t == Vec3(0x1.8bcf472ef8f9p-9, -0x1.2596ca9b61b2cp-1, -0x1.f36d23a59bb36p-7));
}

TEST_CASE("vector turbulence gives the same bits on every code path", "[noise]") {
  // vector_turbulence runs an AVX form where the CPU has AVX (noise.cpp); it must give the
  // portable SSE2 code's bits for any point and parameters: on a CPU without AVX both sides
  // are the same code and this passes trivially.
  Points pts;
  const auto same_bits = [](const Vec3& a, const Vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  int differ = 0;
  for (int i = 0; i < kSamples; ++i) {
    const Vec3 p = pts.next(i % 3 == 0 ? 300.0 : 50.0);
    const int octaves = 1 + i % 16;
    const double lambda = 1.5 + pts.unit(), omega = 0.2 + 0.6 * pts.unit();
    if (!same_bits(pat::vector_turbulence(p, octaves, lambda, omega),
                   pat::vector_turbulence_portable(p, octaves, lambda, omega)))
      ++differ;
  }
  CHECK(differ == 0);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const Vec3& p : {Vec3(0.0), Vec3(1, 2, 3), Vec3(-1e-300, 0.5, -0.5), Vec3(3.9e15, 1, 1), Vec3(1e15, -2.5e14, 7),
                        Vec3(inf, 0, 0), Vec3(0, nan, 0), Vec3(-inf, nan, inf)}) {
    for (int octaves : {0, 1, 6, 16, 40}) {
      CHECK(same_bits(pat::vector_turbulence(p, octaves, 2, 0.5), pat::vector_turbulence_portable(p, octaves, 2, 0.5)));
      CHECK(same_bits(pat::vector_turbulence(p, octaves, 1e300, 1e300),
                      pat::vector_turbulence_portable(p, octaves, 1e300, 1e300)));
    }
  }
}

TEST_CASE("a pattern texture renders the same bytes with any thread count", "[noise]") {
  SceneDesc s;
  s.settings.width = 48;
  s.settings.height = 36;
  s.settings.samples = 2;
  s.has_camera = true;
  s.camera.position = Vec3(0, 2, -4);
  s.camera.look_at = Vec3(0, 0, 0);
  TextureDesc marble;
  marble.kind = TextureKind::Pattern;
  marble.pattern.kind = PatternKind::Marble;
  marble.pattern.wave = WaveKind::Triangle;
  marble.pattern.turbulence = Vec3(0.8);
  marble.pattern.color_map = {{0.0, {0.9, 0.9, 0.9}}, {1.0, {0.2, 0.1, 0.3}}};
  s.textures.push_back(marble);
  MaterialDesc m;
  m.texture = 0;
  place(s, add_shape(s, Sphere{Vec3(0), 1.0}, add_material(s, m)));
  LightDesc light;
  light.position = Vec3(3, 5, -4);
  place(s, add_light(s, light));
  RenderOptions one, four;
  one.threads = 1;
  four.threads = 4;
  const RenderResult a = render(s, one), b = render(s, four);
  CHECK(a.color.rgb == b.color.rgb);
  const auto& used = a.stats.features_used;
  CHECK(std::find(used.begin(), used.end(), "pattern") != used.end());
}

TEST_CASE("patterns mean what POV-Ray's mean", "[patterns]") {
  PatternDesc d;
  d.color_map = {{0.0, {0, 0, 0}}, {1.0, {1, 1, 1}}};
  auto value = [&](PatternKind k, WaveKind w, Vec3 q) {
    d.kind = k;
    d.wave = w;
    return pat::wave(d, pat::raw_value(d, q));
  };
  SECTION("marble: a triangle wave along x, period 1") {
    CHECK(value(PatternKind::Marble, WaveKind::Triangle, Vec3(0.0, 5, 3)) == Approx(0.0).margin(1e-12));
    CHECK(value(PatternKind::Marble, WaveKind::Triangle, Vec3(0.25, -2, 1)) == Approx(0.5));
    CHECK(value(PatternKind::Marble, WaveKind::Triangle, Vec3(0.5, 0, 0)) == Approx(1.0));
    CHECK(value(PatternKind::Marble, WaveKind::Triangle, Vec3(0.75, 9, 9)) == Approx(0.5));
  }
  SECTION("wood: cylinders around z, a triangle wave of the radius") {
    CHECK(value(PatternKind::Wood, WaveKind::Triangle, Vec3(0.3, 0.4, 0)) == Approx(1.0));   // r = 0.5
    CHECK(value(PatternKind::Wood, WaveKind::Triangle, Vec3(0.3, 0.4, 7)) == Approx(1.0));
    CHECK(value(PatternKind::Wood, WaveKind::Triangle, Vec3(0, 0.25, -3)) == Approx(0.5));
  }
  SECTION("onion: spheres, a ramp of the distance") {
    CHECK(value(PatternKind::Onion, WaveKind::Ramp, Vec3(0, 0.3, 0)) == Approx(0.3));
    CHECK(value(PatternKind::Onion, WaveKind::Ramp, Vec3(0, 0, 1.3)) == Approx(0.3));
  }
  SECTION("leopard: ((sin x + sin y + sin z) / 3)^2") {
    const double s = (std::sin(1.0) + std::sin(2.0) + std::sin(0.5)) / 3;
    CHECK(value(PatternKind::Leopard, WaveKind::Ramp, Vec3(1, 2, 0.5)) == Approx(s * s));
  }
  SECTION("crackle is 0 on the border between two cells and positive inside") {
    double lo = 1, hi = 0;
    Points pts;
    for (int i = 0; i < 20000; ++i) {
      const double v = value(PatternKind::Crackle, WaveKind::Ramp, pts.next(5));
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    CHECK(lo < 0.02);
    CHECK(hi > 0.5);
  }
  SECTION("granite, wrinkles, crackle, agate, leopard, dents stay in [0, 1] (no ramp wrap-around)") {
    Points pts;
    for (PatternKind k : {PatternKind::Granite, PatternKind::Wrinkles, PatternKind::Crackle, PatternKind::Agate,
                          PatternKind::Leopard, PatternKind::Dents, PatternKind::Bozo}) {
      d.kind = k;
      for (int i = 0; i < 20000; ++i) {
        const double v = pat::raw_value(d, pts.next(10));
        REQUIRE((v >= 0.0 && v <= 1.0));
      }
    }
  }
  SECTION("turbulence moves the pattern; zero turbulence leaves it") {
    d.turbulence = Vec3(0.0);
    const double plain = value(PatternKind::Wood, WaveKind::Triangle, Vec3(0.3, 0.2, 0.1));
    d.turbulence = Vec3(0.5);
    CHECK(value(PatternKind::Wood, WaveKind::Triangle, Vec3(0.3, 0.2, 0.1)) != plain);
  }
}

TEST_CASE("gradient with a color map: the ramped coordinate along its axis, warped by turbulence", "[patterns]") {
  // POV-Ray's `gradient y color_map { ... } turbulence t`: the value is the point's y (ramp wave:
  // it repeats every unit), after the warp p + t * vector_turbulence(p); the color map turns it
  // into a color. Checked through the compiled texture, as a surface evaluates it.
  const glm::dvec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
  TextureDesc t;
  t.kind = TextureKind::Pattern;
  t.pattern.kind = PatternKind::Gradient;
  t.pattern.wave = WaveKind::Ramp;   // the builder's default for gradient
  t.pattern.color_map = {{0.0, red}, {0.5, green}, {1.0, blue}};
  auto color_at = [&](const Vec3& q) {
    const CompiledTexture tex(t, nullptr);
    TexturePoint p;
    p.object_point = q;
    const Color c = tex.eval(p);
    return glm::dvec3(c.r, c.g, c.b);
  };
  auto near = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-9; };
  for (int axis = 0; axis < 3; ++axis) {
    INFO("axis " << axis);
    t.pattern.axis = axis;
    t.pattern.turbulence = Vec3(0.0);
    auto along = [&](double v, const Vec3& other) {
      Vec3 q = other;
      q[axis] = v;
      return q;
    };
    // Only the axis' coordinate counts; the ramp repeats it every unit (negative values too).
    CHECK(near(color_at(along(0.0, Vec3(3, -7, 2))), red));
    CHECK(near(color_at(along(0.25, Vec3(3, -7, 2))), 0.5 * (red + green)));
    CHECK(near(color_at(along(0.25, Vec3(-40, 5, 0.5))), 0.5 * (red + green)));
    CHECK(near(color_at(along(0.5, Vec3(1, 1, 1))), green));
    CHECK(near(color_at(along(2.75, Vec3(1, 2, 3))), 0.5 * (green + blue)));
    CHECK(near(color_at(along(-0.25, Vec3(1, 2, 3))), 0.5 * (green + blue)));
    CHECK(near(color_at(along(0.9, Vec3(0, 0, 0))), 0.2 * green + 0.8 * blue));

    // Turbulence: the same lookup at the warped point's coordinate, and the bands now wander
    // across the other axes (without it the color is constant there).
    const Vec3 turb(0.3, 0.4, 0.5);
    t.pattern.turbulence = turb;
    t.pattern.octaves = 4;
    Points pts;
    double wander = 0.0;
    const int n = 500;
    for (int i = 0; i < n; ++i) {
      const Vec3 q = pts.next(3.0);
      const Vec3 w = q + turb * pat::vector_turbulence(q, 4, 2.0, 0.5);
      const double v = w[axis] - std::floor(w[axis]);
      REQUIRE(near(color_at(q), pat::color_map_lookup(t.pattern.color_map, v)));
      Vec3 q2 = q + Vec3(0.7, 0.7, 0.7);
      q2[axis] = q[axis];   // the same coordinate along the axis: the same color without turbulence
      wander += glm::length(color_at(q2) - color_at(q));
    }
    CHECK(wander / n > 0.1);
  }
}

TEST_CASE("ripples and waves as colors wrap as POV-Ray's do; as heights they stay smooth", "[patterns]") {
  // POV-Ray applies frequency and phase inside ripples and waves (rings per unit) and again to
  // the color map's index, so at frequency 2 the color jumps where the value crosses 0.5: its
  // hard-edged bands. A bump's height takes them once and has no jump.
  PatternDesc d;
  d.wave = WaveKind::Ramp;
  d.color_map = {{0.0, {0, 0, 0}}, {1.0, {1, 1, 1}}};
  for (PatternKind k : {PatternKind::Ripples, PatternKind::Waves}) {
    d.kind = k;
    INFO("pattern " << static_cast<int>(k));
    SECTION("at frequency 1 color and height agree for ripples; waves' color stays inside [0, 1]") {
      d.frequency = 1;
      Points pts;
      for (int i = 0; i < 5000; ++i) {
        const Vec3 q = pts.next(3);
        const double c = pat::wave(d, pat::raw_value(d, q));
        REQUIRE((c >= 0.05 && c <= 0.95));   // POV-Ray's 0.5 + 0.2 * mean: at most +-0.45
        if (k == PatternKind::Ripples) REQUIRE(c == pat::wave(d, pat::raw_value(d, q, true), true));
      }
    }
    SECTION("at frequency 2 the color jumps along a line; the height does not") {
      d.frequency = 2;
      double color_jump = 0, height_jump = 0;
      const int n = 20000;
      for (int i = 0; i < n; ++i) {
        const Vec3 a(-3 + 6.0 * i / n, 0.37, 0.1), b(-3 + 6.0 * (i + 1) / n, 0.37, 0.1);
        color_jump = std::max(color_jump, std::fabs(pat::wave(d, pat::raw_value(d, a)) - pat::wave(d, pat::raw_value(d, b))));
        height_jump = std::max(height_jump, std::fabs(pat::wave(d, pat::raw_value(d, a, true), true) -
                                                      pat::wave(d, pat::raw_value(d, b, true), true)));
      }
      CHECK(color_jump > 0.5);     // a wrap from near 1 to near 0 between neighbours 0.0003 apart
      CHECK(height_jump < 0.02);   // a slope of at most about 2 pi * frequency
    }
  }
}

TEST_CASE("wave functions", "[patterns]") {
  PatternDesc d;
  d.kind = PatternKind::Bozo;
  d.wave = WaveKind::Ramp;
  CHECK(pat::wave(d, 0.3) == Approx(0.3));
  CHECK(pat::wave(d, 1.0) == 1.0);   // [0, 1] passes unchanged
  CHECK(pat::wave(d, 1.25) == Approx(0.25));
  CHECK(pat::wave(d, -0.25) == Approx(0.75));
  d.wave = WaveKind::Sine;
  CHECK(pat::wave(d, 0.25) == Approx(1.0));
  CHECK(pat::wave(d, 0.75) == Approx(0.0).margin(1e-12));
  d.wave = WaveKind::Scallop;
  CHECK(pat::wave(d, 0.5) == Approx(1.0));
  d.wave = WaveKind::Cubic;
  CHECK(pat::wave(d, 0.5) == Approx(0.5));
  CHECK(pat::wave(d, 0.25) == Approx(0.15625));
  d.wave = WaveKind::Clamp;
  CHECK(pat::wave(d, 3.0) == 1.0);
  d.wave = WaveKind::Ramp;
  d.frequency = 2;
  d.phase = 0.1;
  CHECK(pat::wave(d, 0.3) == Approx(0.7));
  CHECK(pat::wave(d, NAN) == 0.0);
}

TEST_CASE("color map lookup interpolates linearly and clamps outside", "[patterns]") {
  const std::vector<ColorMapEntry> map = {{0.2, {1, 0, 0}}, {0.5, {0, 1, 0}}, {0.5, {0, 0, 1}}, {0.9, {1, 1, 1}}};
  CHECK(pat::color_map_lookup(map, 0.0) == glm::dvec3(1, 0, 0));
  CHECK(pat::color_map_lookup(map, 0.2) == glm::dvec3(1, 0, 0));
  const glm::dvec3 mid = pat::color_map_lookup(map, 0.35);
  CHECK(mid.x == Approx(0.5));
  CHECK(mid.y == Approx(0.5));
  CHECK(mid.z == 0.0);
  // Two entries at one value make a sharp edge: green just below, blue just above.
  CHECK(pat::color_map_lookup(map, 0.4999999).y == Approx(1.0).epsilon(1e-5));
  CHECK(pat::color_map_lookup(map, 0.5000001).z == Approx(1.0).epsilon(1e-5));
  const glm::dvec3 upper = pat::color_map_lookup(map, 0.7);
  CHECK(upper.x == Approx(0.5));
  CHECK(upper.y == Approx(0.5));
  CHECK(upper.z == 1.0);
  CHECK(pat::color_map_lookup(map, 5.0) == glm::dvec3(1, 1, 1));
  CHECK(pat::color_map_lookup(map, NAN) == glm::dvec3(1, 0, 0));
}

TEST_CASE("every pattern's color map is looked up over the pattern's range", "[patterns]") {
  const glm::dvec3 red(0.9, 0.1, 0.1), blue(0.1, 0.2, 0.9);
  for (int k = 0; k <= static_cast<int>(PatternKind::Waves); ++k) {
    TextureDesc t;
    t.kind = TextureKind::Pattern;
    t.pattern.kind = static_cast<PatternKind>(k);
    t.pattern.wave = t.pattern.kind == PatternKind::Marble || t.pattern.kind == PatternKind::Wood ? WaveKind::Triangle
                                                                                                   : WaveKind::Ramp;
    t.pattern.frequency = t.pattern.kind == PatternKind::Ripples || t.pattern.kind == PatternKind::Waves ? 3.0 : 1.0;
    t.pattern.color_map = {{0.0, red}, {1.0, blue}};
    t.transform = glm::scale(Mat4(1.0), Vec3(0.5));
    const CompiledTexture tex(t, nullptr);
    Points pts;
    double lo = 1, hi = 0;
    for (int i = 0; i < 4000; ++i) {
      TexturePoint p;
      p.object_point = pts.next(4.0);
      const Color c = tex.eval(p);
      // On the segment red → blue: the blend fraction from r and from b agree.
      const double tr = (c.r - red.x) / (blue.x - red.x), tb = (c.b - red.z) / (blue.z - red.z);
      INFO("pattern " << k);
      REQUIRE(tr == Approx(tb).margin(1e-9));
      REQUIRE((tr >= -1e-12 && tr <= 1 + 1e-12));
      lo = std::min(lo, tr);
      hi = std::max(hi, tr);
    }
    INFO("pattern " << k << " spans " << lo << " .. " << hi);
    // Each pattern reaches well into both halves of its map (granite's values are small and
    // dents' cubed: they reach the middle).
    CHECK(lo < 0.3);
    CHECK(hi > 0.45);
  }
}

TEST_CASE("compiled functions evaluate straight-line code", "[patterns]") {
  CompiledFunction f;
  uint16_t two, x2, s, n, r;
  REQUIRE(f.constant(2.0, two));
  REQUIRE(f.emit(CompiledFunction::Op::Mul, {CompiledFunction::kX, two}, x2));
  REQUIRE(f.emit(CompiledFunction::Op::Sin, {x2}, s));
  REQUIRE(f.emit(CompiledFunction::Op::Noise, {CompiledFunction::kX, CompiledFunction::kY, CompiledFunction::kZ}, n));
  REQUIRE(f.emit(CompiledFunction::Op::Add, {s, n}, r));
  f.set_result(r);
  uint16_t again;
  REQUIRE(f.constant(2.0, again));
  CHECK(again == two);   // constants are shared
  const Vec3 p(0.3, -1.2, 2.5);
  CHECK(f.eval(p) == std::sin(0.6) + pat::noise01(p));
  CHECK(f.instructions() == 5);
  CHECK(f.listing().find("noise r0 r1 r2") != std::string::npos);
  // A NaN result reads as 0.
  CompiledFunction g;
  uint16_t neg1, root;
  REQUIRE(g.constant(-1.0, neg1));
  REQUIRE(g.emit(CompiledFunction::Op::Sqrt, {neg1}, root));
  g.set_result(root);
  CHECK(g.eval(p) == 0.0);
  // It is full at kMaxRegisters.
  CompiledFunction big;
  uint16_t last = CompiledFunction::kX;
  std::size_t made = 0;
  while (big.emit(CompiledFunction::Op::Neg, {last}, last)) ++made;
  CHECK(made == CompiledFunction::kMaxRegisters - 3);
}

TEST_CASE("compiled functions fold repeats, pow(a, 2) and sin/cos pairs without changing a bit", "[patterns]") {
  using Op = CompiledFunction::Op;
  // f = sin(6x) cos(6y) + sin(6y) cos(6z) + sin(6z) cos(6x) + pow(x - y, 2) + pow(z, 3), the
  // gyroid's shape: every 6·coordinate is used by a sin and a cos, and the same products recur.
  CompiledFunction f;
  uint16_t six, two, three, c[3], s[3], co[3], t[3], r, d, sq, cube, again;
  REQUIRE(f.constant(6.0, six));
  REQUIRE(f.constant(2.0, two));
  REQUIRE(f.constant(3.0, three));
  for (uint16_t k = 0; k < 3; ++k) REQUIRE(f.emit(Op::Mul, {six, k}, c[k]));
  REQUIRE(f.emit(Op::Mul, {six, CompiledFunction::kX}, again));
  CHECK(again == c[0]);  // the same instruction reuses its register
  for (int k = 0; k < 3; ++k) {
    REQUIRE(f.emit(Op::Sin, {c[k]}, s[k]));
    REQUIRE(f.emit(Op::Cos, {c[(k + 1) % 3]}, co[k]));
    REQUIRE(f.emit(Op::Mul, {s[k], co[k]}, t[k]));
  }
  REQUIRE(f.emit(Op::Add, {t[0], t[1]}, r));
  REQUIRE(f.emit(Op::Add, {r, t[2]}, r));
  REQUIRE(f.emit(Op::Sub, {CompiledFunction::kX, CompiledFunction::kY}, d));
  REQUIRE(f.emit(Op::Pow, {d, two}, sq));
  REQUIRE(f.emit(Op::Pow, {CompiledFunction::kZ, three}, cube));
  REQUIRE(f.emit(Op::Add, {r, sq}, r));
  REQUIRE(f.emit(Op::Add, {r, cube}, r));
  f.set_result(r);
  const std::string listing = f.listing();
  CHECK(listing.find("sincos") != std::string::npos);
  CHECK(listing.find("cossin") != std::string::npos);  // cos(6y) is emitted before sin(6y)
  CHECK(listing.find("pow") != std::string::npos);      // pow(z, 3) stays a pow
  // 3 constants, 3 products, 3 sincos pairs (6), 3 products, 2 sums, the difference, its
  // square (a Mul), the cube, 2 sums: 22 instructions, the second Mul(6, x) shared.
  CHECK(f.instructions() == 22);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (int i = 0; i < 20000; ++i) {
    double x = u(rng) * (i % 3 == 0 ? 2e6 : 8.0), y = u(rng) * 8.0, z = u(rng) * (i % 5 == 0 ? 1e-6 : 8.0);
    const double want = std::sin(6 * x) * std::cos(6 * y) + std::sin(6 * y) * std::cos(6 * z) +
                        std::sin(6 * z) * std::cos(6 * x) + std::pow(x - y, 2.0) + std::pow(z, 3.0);
    const double got = f.eval(Vec3(x, y, z));
    REQUIRE(std::memcmp(&got, &want, sizeof got) == 0);
  }
}
