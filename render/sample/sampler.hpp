// Sample generation: counter-based hashes (no shared state, so images do not depend on the
// thread count), stratification helpers, and the three pixel samplers (random, stratified,
// Owen-scrambled Sobol).
#pragma once

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <string_view>

#include <glm/glm.hpp>

#include "render/scene/sampler_kind.hpp"

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

// ---- low-discrepancy building blocks (Burley 2020, "Practical Hash-based Owen Scrambling") ---

constexpr uint32_t reverse_bits(uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// A hash that only lets a bit depend on the bits below it: on bit-reversed input that is a
// nested uniform (Owen) scramble of the digits, each subtree flipped by its own random bit.
inline uint32_t laine_karras(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

inline uint32_t owen_scramble(uint32_t x, uint32_t seed) {
  return reverse_bits(laine_karras(reverse_bits(x), seed));
}

// The first two Sobol dimensions (a (0,2)-sequence): van der Corput and the Pascal-matrix
// dimension, as 32-bit fractions.
inline uint32_t sobol_dim0(uint32_t i) { return reverse_bits(i); }

// The second dimension is linear over GF(2): the XOR of generator column v_k for every set
// bit k of i (v_0 = 2^31, v_{k+1} = v_k ^ (v_k >> 1)). Bit by bit that is up to 32 iterations
// with unpredictable branches on a scrambled index; profile finding (perf, the soft-shadow
// race scene, 1 thread): Sampler::next2 was 42% of the render. Four tables of 256 entries,
// one per byte of i, give exactly the same bits in four lookups.
struct SobolDim1Tables {
  uint32_t byte[4][256];
  constexpr SobolDim1Tables() : byte{} {
    uint32_t v[32] = {};
    v[0] = 0x80000000u;
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
    for (int j = 0; j < 4; ++j)
      for (uint32_t b = 0; b < 256; ++b) {
        uint32_t x = 0;
        for (int bit = 0; bit < 8; ++bit)
          if (b & (1u << bit)) x ^= v[8 * j + bit];
        byte[j][b] = x;
      }
  }
};
inline constexpr SobolDim1Tables kSobolDim1{};

constexpr uint32_t sobol_dim1(uint32_t i) {
  return kSobolDim1.byte[0][i & 0xffu] ^ kSobolDim1.byte[1][(i >> 8) & 0xffu] ^
         kSobolDim1.byte[2][(i >> 16) & 0xffu] ^ kSobolDim1.byte[3][i >> 24];
}

// reverse_bits(sobol_dim1(reverse_bits(a))), linear over GF(2) too, in four byte tables: the
// Owen-scrambled pair below works on bit-reversed indices, and this spares it two of the
// seven bit reversals per pair (profile finding, soft-shadow race scene: Sampler::next2 15%
// of the render after the batched light samples). The same bits as the composition.
struct SobolDim1ReversedTables {
  uint32_t byte[4][256];
  constexpr SobolDim1ReversedTables() : byte{} {
    for (int j = 0; j < 4; ++j)
      for (uint32_t b = 0; b < 256; ++b) byte[j][b] = reverse_bits(sobol_dim1(reverse_bits(b << (8 * j))));
  }
};
inline constexpr SobolDim1ReversedTables kSobolDim1Reversed{};

constexpr uint32_t sobol_dim1_reversed(uint32_t a) {
  return kSobolDim1Reversed.byte[0][a & 0xffu] ^ kSobolDim1Reversed.byte[1][(a >> 8) & 0xffu] ^
         kSobolDim1Reversed.byte[2][(a >> 16) & 0xffu] ^ kSobolDim1Reversed.byte[3][a >> 24];
}

// A 32-bit fraction to [0, 1), with random low bits below the 2^-32 cell so values are not
// confined to a lattice.
inline double fraction_to_unit(uint32_t x, uint64_t low) {
  return (static_cast<double>(x) + to_unit(low)) * 0x1.0p-32;
}

// ---- samplers -----------------------------------------------------------------------------

// A pixel's samples form `batches` independent interleaved sets (sample s is index s / K of
// batch s % K), each stratified or low-discrepancy on its own with its own scrambling, so the
// spread of the batch means measures the error of the pixel honestly whatever the sampler.
// A stratified set holds `set_size` points; indices past it start a fresh, independent set.
struct SamplePattern {
  SamplerKind kind = SamplerKind::Random;
  uint64_t seed = 0;
  uint32_t set_size = 1;
};

// Counter-based: every value is a hash of (seed, pixel, batch, index, dimension), so no state
// is shared between threads and the image does not depend on which thread rendered which tile.
// `dimension` advances with each value a sample path consumes; next2() takes one 2-D pair.
class Sampler {
 public:
  // Independent random samples (tests and one-off draws).
  Sampler(uint32_t x, uint32_t y, uint32_t sample, uint64_t seed)
      : Sampler(SamplePattern{SamplerKind::Random, seed, 1}, x, y, 0, sample) {}

  Sampler(const SamplePattern& pattern, uint32_t x, uint32_t y, uint32_t batch, uint32_t index)
      : kind_(pattern.kind),
        set_key_(hash_combine(hash_combine(hash_combine(mix64(pattern.seed), x), y), batch)),
        key_(hash_combine(set_key_, index)),
        index_(index) {
    if (kind_ == SamplerKind::Stratified) {
      uint32_t n = std::max<uint32_t>(1, pattern.set_size);
      set_key_ = hash_combine(set_key_, 0x5e7000000ULL + index / n);  // one key per set
      index_ = index % n;
      set_size_ = n;
      side_ = square_side(n);
    }
  }

  double next() {
    uint32_t d = dimension_++;
    switch (kind_) {
      case SamplerKind::Random: break;
      case SamplerKind::Stratified: {
        uint64_t h = hash_combine(set_key_, d);
        return (permute(index_, set_size_, static_cast<uint32_t>(h)) + to_unit(hash_combine(key_, d))) /
               set_size_;
      }
      case SamplerKind::Sobol: return sobol_padded(d, reverse_bits(index_));
    }
    return to_unit(hash_combine(key_, d));
  }

  // Three values, as three next() calls return them (the glossy lobe's point in the ball):
  // one dispatch on the kind and the index's reversal shared (profile finding, glossy race
  // scene: Sampler::next 6% of the render, three calls per glossy ray).
  glm::dvec3 next3() {
    if (kind_ != SamplerKind::Sobol) {
      double a = next(), b = next();
      return {a, b, next()};
    }
    const uint32_t d = dimension_, reversed = reverse_bits(index_);
    dimension_ += 3;
    return {sobol_padded(d, reversed), sobol_padded(d + 1, reversed), sobol_padded(d + 2, reversed)};
  }

  glm::dvec2 next2() {
    uint32_t d = dimension_;
    dimension_ += 2;
    switch (kind_) {
      case SamplerKind::Random: break;
      case SamplerKind::Stratified: {
        uint64_t h = hash_combine(set_key_, d);
        glm::dvec2 jitter(to_unit(hash_combine(key_, d)), to_unit(hash_combine(key_, d + 1)));
        // Each dimension pair visits the set's strata in its own random order.
        uint32_t i = permute(index_, set_size_, static_cast<uint32_t>(h));
        return stratified_2d(i, set_size_, side_, jitter, static_cast<uint32_t>(h >> 32));
      }
      case SamplerKind::Sobol: {
        // As next(): owen_scramble(sobol_dimK(i), s) with i = owen_scramble(index, h) = reverse(a),
        // the cancelling reversals left out (sobol_dim1_reversed), the same bits.
        uint64_t h = hash_combine(set_key_, d), h2 = hash_combine(set_key_, d + 1);
        uint32_t a = laine_karras(reverse_bits(index_), static_cast<uint32_t>(h));
        return {fraction_to_unit(reverse_bits(laine_karras(reverse_bits(a), static_cast<uint32_t>(h >> 32))),
                                 hash_combine(key_, d)),
                fraction_to_unit(reverse_bits(laine_karras(sobol_dim1_reversed(a), static_cast<uint32_t>(h2))),
                                 hash_combine(key_, d + 1))};
      }
    }
    return {to_unit(hash_combine(key_, d)), to_unit(hash_combine(key_, d + 1))};
  }

  // Random bits (permutation seeds), independent of the sampler kind.
  uint32_t next_bits() { return static_cast<uint32_t>(hash_combine(key_, dimension_++) >> 32); }
  uint32_t dimension() const { return dimension_; }
  // Steps over `n` values a path does not draw (a light that sends nothing), so the values
  // after them are the ones a path that drew them would get.
  void skip(uint32_t n) { dimension_ += n; }

 private:
  // Dimension d of a scrambled Sobol sample, padded from the first Sobol dimension:
  // owen_scramble(sobol_dim0(i), s) with i = owen_scramble(index, h), written with the
  // reversals that cancel left out (i = reverse(a), sobol_dim0(i) = a); `reversed_index` is
  // reverse_bits(index_), shared by next3's three values.
  [[gnu::always_inline]] double sobol_padded(uint32_t d, uint32_t reversed_index) const {
    uint64_t h = hash_combine(set_key_, d);
    uint32_t a = laine_karras(reversed_index, static_cast<uint32_t>(h));
    return fraction_to_unit(reverse_bits(laine_karras(reverse_bits(a), static_cast<uint32_t>(h >> 32))),
                            hash_combine(key_, d));
  }

  SamplerKind kind_;
  uint64_t set_key_;   // the (pixel, batch[, set]): shared by the points of one set
  uint64_t key_;       // this sample
  uint32_t index_;     // index within the set
  uint32_t set_size_ = 1, side_ = 1;
  uint32_t dimension_ = 0;
};

}  // namespace rts::render
