// Counter-based random numbers: every value is a hash of (pixel x, y, sample index, seed,
// dimension), so no state is shared between threads and the image does not depend on which
// thread rendered which tile. `dimension` advances with each value a sample path consumes.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

namespace rts::render {

// splitmix64's finaliser: a bijective 64-bit mix with good avalanche.
constexpr uint64_t mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr uint64_t hash_combine(uint64_t h, uint64_t v) { return mix64(h ^ mix64(v)); }

// Uniform double in [0, 1) from the top 53 bits.
constexpr double to_unit(uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

// Kensler's "Correlated Multi-Jittered Sampling" permutation: a bijection of [0, n) chosen by
// `seed`, used to pair strata for N-rooks sampling when N is not a square.
inline uint32_t permute(uint32_t i, uint32_t n, uint32_t seed) {
  if (n <= 1) return 0;
  uint32_t w = n - 1;
  w |= w >> 1; w |= w >> 2; w |= w >> 4; w |= w >> 8; w |= w >> 16;
  do {
    i ^= seed; i *= 0xe170893d; i ^= seed >> 16; i ^= (i & w) >> 4; i ^= seed >> 8;
    i *= 0x0929eb3f; i ^= seed >> 23; i ^= (i & w) >> 1; i *= 1 | seed >> 27; i *= 0x6935fa69;
    i ^= (i & w) >> 11; i *= 0x74dcb303; i ^= (i & w) >> 2; i *= 0x9e501cc3; i ^= (i & w) >> 2;
    i *= 0xc860a3df; i &= w; i ^= i >> 5;
  } while (i >= n);
  return (i + seed) % n;
}

// sqrt(n) when n is a perfect square, else 0 (then strata are N-rooks).
inline uint32_t square_side(uint32_t n) {
  uint32_t side = static_cast<uint32_t>(std::lround(std::sqrt(static_cast<double>(n))));
  return side * side == n ? side : 0;
}

// The i-th of n stratified points in the unit square, jittered by `jitter`: a side x side
// grid when n is a perfect square (side = square_side(n), precomputed by callers in hot
// loops), N-rooks (Latin hypercube) otherwise.
inline glm::dvec2 stratified_2d(uint32_t i, uint32_t n, uint32_t side, glm::dvec2 jitter,
                                uint32_t perm_seed) {
  if (side > 0) {
    double inv = 1.0 / side;
    return {((i % side) + jitter.x) * inv, ((i / side) + jitter.y) * inv};
  }
  double inv = 1.0 / n;
  return {(i + jitter.x) * inv, (permute(i, n, perm_seed) + jitter.y) * inv};
}

inline glm::dvec2 stratified_2d(uint32_t i, uint32_t n, glm::dvec2 jitter, uint32_t perm_seed) {
  return stratified_2d(i, n, square_side(n), jitter, perm_seed);
}

class Sampler {
 public:
  Sampler(uint32_t x, uint32_t y, uint32_t sample, uint64_t seed)
      : key_(hash_combine(hash_combine(hash_combine(mix64(seed), x), y), sample)),
        pixel_key_(hash_combine(hash_combine(mix64(seed), x), y)) {}

  double next() { return to_unit(hash_combine(key_, dimension_++)); }
  glm::dvec2 next2() {
    double a = next();
    return {a, next()};
  }
  uint32_t next_bits() { return static_cast<uint32_t>(hash_combine(key_, dimension_++) >> 32); }
  // Identical for every sample of a pixel: pairs the pixel's strata (N-rooks permutation).
  uint32_t pixel_bits() const { return static_cast<uint32_t>(pixel_key_ >> 32); }
  uint32_t dimension() const { return dimension_; }
  // Steps over `n` values a path does not draw (a light that sends nothing), so the values
  // after them are the ones a path that drew them would get.
  void skip(uint32_t n) { dimension_ += n; }

 private:
  uint64_t key_;
  uint64_t pixel_key_;
  uint32_t dimension_ = 0;
};

}  // namespace rts::render
