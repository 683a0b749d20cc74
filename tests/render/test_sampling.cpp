// Counter-based sampling: deterministic per (pixel, sample, seed, dimension), uniform, and
// stratified.
#include <set>

#include <catch2/catch.hpp>

#include "render/sample/camera.hpp"
#include "render/sample/sampler.hpp"

using namespace rts::render;

TEST_CASE("sampler values depend only on their coordinates", "[sampling]") {
  Sampler a(3, 4, 5, 42), b(3, 4, 5, 42);
  for (int i = 0; i < 10; ++i) CHECK(a.next() == b.next());
  Sampler other_pixel(4, 3, 5, 42), other_seed(3, 4, 5, 43), other_sample(3, 4, 6, 42);
  Sampler ref(3, 4, 5, 42);
  double v = ref.next();
  CHECK(other_pixel.next() != v);
  CHECK(other_seed.next() != v);
  CHECK(other_sample.next() != v);
}

TEST_CASE("sampler values are uniform in [0,1)", "[sampling]") {
  Sampler s(1, 2, 3, 4);
  const int n = 20000;
  int buckets[10] = {};
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    double v = s.next();
    REQUIRE(v >= 0.0);
    REQUIRE(v < 1.0);
    sum += v;
    ++buckets[static_cast<int>(v * 10)];
  }
  CHECK(sum / n == Approx(0.5).margin(0.01));
  for (int b : buckets) CHECK(std::abs(b - n / 10) < n / 50);
}

TEST_CASE("square sample counts give one sample per grid cell", "[sampling]") {
  const uint32_t n = 16;
  std::set<std::pair<int, int>> cells;
  for (uint32_t i = 0; i < n; ++i) {
    glm::dvec2 p = stratified_2d(i, n, glm::dvec2(0.999, 0.001), 7);
    cells.insert({static_cast<int>(p.x * 4), static_cast<int>(p.y * 4)});
  }
  CHECK(cells.size() == n);
}

TEST_CASE("non-square sample counts are N-rooks: one sample per row and per column", "[sampling]") {
  for (uint32_t n : {2u, 3u, 5u, 6u, 7u, 10u}) {
    std::set<int> rows, cols;
    for (uint32_t i = 0; i < n; ++i) {
      glm::dvec2 p = stratified_2d(i, n, glm::dvec2(0.5), 12345);
      cols.insert(static_cast<int>(p.x * n));
      rows.insert(static_cast<int>(p.y * n));
    }
    CHECK(cols.size() == n);
    CHECK(rows.size() == n);
  }
}

TEST_CASE("permute is a bijection", "[sampling]") {
  for (uint32_t n : {1u, 2u, 9u, 33u, 100u}) {
    std::set<uint32_t> seen;
    for (uint32_t i = 0; i < n; ++i) seen.insert(permute(i, n, 0xabcdef));
    CHECK(seen.size() == n);
    CHECK(*seen.rbegin() == n - 1);
  }
}

TEST_CASE("concentric disc mapping stays in the unit disc and reaches its edge", "[sampling]") {
  double max_r = 0;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      glm::dvec2 d = concentric_disc({i / 20.0, j / 20.0});
      double r = glm::length(d);
      CHECK(r <= 1.0 + 1e-12);
      max_r = std::max(max_r, r);
    }
  CHECK(max_r == Approx(1.0));
}

TEST_CASE("the reversed Sobol dimension-1 tables are the composition they replace", "[sampling]") {
  // Sampler::next2 uses sobol_dim1_reversed(a) for reverse(sobol_dim1(reverse(a))); the
  // scrambled Sobol images depend on every bit being the same.
  uint64_t x = 0x243f6a8885a308d3ULL;
  for (int k = 0; k < 100000; ++k) {
    x = mix64(x);
    const uint32_t a = static_cast<uint32_t>(x >> 17);
    REQUIRE(sobol_dim1_reversed(a) == reverse_bits(sobol_dim1(reverse_bits(a))));
  }
  for (uint32_t bit = 0; bit < 32; ++bit)
    REQUIRE(sobol_dim1_reversed(1u << bit) == reverse_bits(sobol_dim1(reverse_bits(1u << bit))));
}

TEST_CASE("next3 hands out the values of three next() calls, for every sampler kind", "[sampling]") {
  // The glossy lobe draws its point with next3; images depend on every bit being the same as
  // the three separate draws it replaced.
  for (SamplerKind kind : {SamplerKind::Random, SamplerKind::Stratified, SamplerKind::Sobol}) {
    for (uint32_t index : {0u, 1u, 5u, 63u, 1000u}) {
      const SamplePattern pattern{kind, 99, 16};
      Sampler three(pattern, 7, 11, 1, index), one(pattern, 7, 11, 1, index);
      (void)three.next2();
      (void)one.next2();
      for (int k = 0; k < 4; ++k) {
        const glm::dvec3 v = three.next3();
        const double a = one.next(), b = one.next(), c = one.next();
        REQUIRE(v.x == a);
        REQUIRE(v.y == b);
        REQUIRE(v.z == c);
      }
      CHECK(three.dimension() == one.dimension());
      CHECK(three.next() == one.next());
    }
  }
}
