// Perlin's improved noise ("Improving Noise", SIGGRAPH 2002): a quintic fade, twelve edge
// gradients picked by a permutation of 0..255. The permutation is built at compile time by a
// Fisher-Yates shuffle driven by a fixed integer hash, so it is the same on every platform.
#include "render/geometry/function/noise.hpp"

#include <algorithm>
#include <array>
#include <cmath>

// x86-64 builds carry a second vector_turbulence for CPUs with AVX, chosen at run time (the
// build itself targets the SSE2 baseline). See vector_turbulence_avx.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RTS_NOISE_AVX 1
#include <immintrin.h>
#else
#define RTS_NOISE_AVX 0
#endif

namespace rts::render::pattern {

namespace {

// splitmix64's finaliser: a good 64-bit integer mix, used for the permutation and for cells.
constexpr uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

constexpr std::array<uint8_t, 512> make_permutation() {
  std::array<uint8_t, 256> p{};
  for (int i = 0; i < 256; ++i) p[i] = static_cast<uint8_t>(i);
  uint64_t state = 0x5eed'2002'9e37'79b9ULL;
  for (int i = 255; i > 0; --i) {
    state = mix64(state + 0x9e3779b97f4a7c15ULL);
    const int j = static_cast<int>(state % static_cast<uint64_t>(i + 1));
    const uint8_t t = p[i];
    p[i] = p[j];
    p[j] = t;
  }
  std::array<uint8_t, 512> doubled{};
  for (int i = 0; i < 512; ++i) doubled[i] = p[i & 255];
  return doubled;
}
constexpr std::array<uint8_t, 512> kPerm = make_permutation();

double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
double lerp(double t, double a, double b) { return a + t * (b - a); }

// Perlin's 12 edge gradients (16 cases, four repeated), as in his reference code, as a table
// (indexed by hash & 15): a dot product instead of his branches, which mispredict on every
// other corner.
constexpr double kGrad[16][3] = {{1, 1, 0},  {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},  {-1, 0, 1},
                                 {1, 0, -1}, {-1, 0, -1}, {0, 1, 1},  {0, -1, 1}, {0, 1, -1}, {0, -1, -1},
                                 {1, 1, 0},  {0, -1, 1}, {-1, 1, 0}, {0, -1, -1}};

// Beyond this magnitude a double has no fractional part left: the noise is 0 there (as at a
// lattice point), and the integer conversions below cannot overflow.
constexpr double kMaxCoordinate = 4.0e15;

// (A NaN or an infinity fails the comparison too.)
bool usable(const Vec3& p) {
  return std::fabs(p.x) < kMaxCoordinate && std::fabs(p.y) < kMaxCoordinate && std::fabs(p.z) < kMaxCoordinate;
}

// floor(x) for |x| < kMaxCoordinate, without a libm call (x86-64's baseline has no rounding
// instruction, so std::floor is a function call: three per noise value).
double fast_floor(double x) {
  const double t = static_cast<double>(static_cast<int64_t>(x));   // toward zero
  return t > x ? t - 1.0 : t;
}
// floor(x) modulo 256, exact for any |x| < kMaxCoordinate.
int lattice(double floored) { return static_cast<int>(static_cast<int64_t>(floored) & 255); }

// vector_noise's second and third components re-hash each corner's hash at these offsets, so
// the three pick unrelated gradients at every corner.
constexpr int kComponentOffset[3] = {0, 85, 170};

// vector_noise's arithmetic, components 0 and 1 side by side in one SSE2 register (a GCC/clang
// vector type: plain element-wise double arithmetic on any target). The pattern race scene
// (bench/race/patterns.rts) spent 30% of its instructions in vector_noise, 583 a call
// (callgrind): three table lookups, three multiplies and two adds per gradient, 24 gradients.
// Precomputing each hash's three gradients in one row, and pairing two components, halves
// that. Element-wise IEEE operations in the same order give the same bits as the scalar code
// (-ffp-contract=off keeps them unfused): tests/render/test_noise.cpp's exact values hold.
using Pair2 = double __attribute__((vector_size(16)));
inline Pair2 lerp2(double t, Pair2 a, Pair2 b) { return a + t * (b - a); }
inline Pair2 fade2(Pair2 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// For each corner hash h, the gradients the three components use there: component 0 takes
// kGrad[h], components 1 and 2 kGrad[kPerm[h + kComponentOffset[c]]] (re-hashed, so the three
// are uncorrelated). x01 holds components 0 and 1's x coefficients, and so on.
struct alignas(16) CornerGradients {
  Pair2 x01, y01, z01;
  double g2[3];
};
struct CornerGradientTable {
  CornerGradients row[256];
  const CornerGradients& operator[](int h) const { return row[h]; }
};
CornerGradientTable make_corner_gradients() {
  CornerGradientTable t;
  for (int h = 0; h < 256; ++h) {
    const double* g0 = kGrad[h & 15];
    const double* g1 = kGrad[kPerm[(h + kComponentOffset[1]) & 255] & 15];
    const double* g2 = kGrad[kPerm[(h + kComponentOffset[2]) & 255] & 15];
    t.row[h].x01 = Pair2{g0[0], g1[0]};
    t.row[h].y01 = Pair2{g0[1], g1[1]};
    t.row[h].z01 = Pair2{g0[2], g1[2]};
    t.row[h].g2[0] = g2[0];
    t.row[h].g2[1] = g2[1];
    t.row[h].g2[2] = g2[2];
  }
  return t;
}
const CornerGradientTable kCornerGradients = make_corner_gradients();

uint64_t cell_hash(int64_t x, int64_t y, int64_t z) {
  return mix64(static_cast<uint64_t>(x) * 0x9e3779b97f4a7c15ULL ^ mix64(static_cast<uint64_t>(y) + 0x632be59bd9b4e019ULL) ^
               mix64(static_cast<uint64_t>(z) * 0x85ebca77c2b2ae63ULL + 0x27d4eb2f165667c5ULL));
}
double unit(uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }   // [0, 1)

}  // namespace

double gradient_noise(const Vec3& p) {
  if (!usable(p)) return 0.0;
  const double fx = fast_floor(p.x), fy = fast_floor(p.y), fz = fast_floor(p.z);
  const int X = lattice(fx), Y = lattice(fy), Z = lattice(fz);
  const double x = p.x - fx, y = p.y - fy, z = p.z - fz;
  const Pair2 uv = fade2(Pair2{x, y});
  const double u = uv[0], v = uv[1], w = fade(z);
  const int A = kPerm[X] + Y, AA = kPerm[A] + Z, AB = kPerm[A + 1] + Z;
  const int B = kPerm[X + 1] + Y, BA = kPerm[B] + Z, BB = kPerm[B + 1] + Z;
  // Perlin's lerp(w, lerp(v, lerp(u, c0, c1), lerp(u, c2, c3)), lerp(v, lerp(u, c4, c5), ..))
  // over the corners c0..c7 (corner i at (i & 1, (i >> 1) & 1, i >> 2)), with each corner below
  // paired with the one above it: the same IEEE operations per element, half the instructions
  // for the u and v lerps and the gradient ramps (as vector_noise_inline's component 2).
  const int lo[4] = {kPerm[AA], kPerm[BA], kPerm[AB], kPerm[BB]};
  const int hi[4] = {kPerm[AA + 1], kPerm[BA + 1], kPerm[AB + 1], kPerm[BB + 1]};
  const double xs[2] = {x, x - 1}, ys[2] = {y, y - 1};
  const Pair2 zs2 = {z, z - 1};
  Pair2 c[4];
#pragma GCC unroll 4
  for (int j = 0; j < 4; ++j) {
    const double* gl = kGrad[lo[j] & 15];
    const double* gh = kGrad[hi[j] & 15];
    c[j] = Pair2{gl[0], gh[0]} * xs[j & 1] + Pair2{gl[1], gh[1]} * ys[j >> 1] + Pair2{gl[2], gh[2]} * zs2;
  }
  const Pair2 rv = lerp2(v, lerp2(u, c[0], c[1]), lerp2(u, c[2], c[3]));
  const double r = lerp(w, rv[0], rv[1]);
  // The sum of eight gradient ramps peaks just above 1 in a few corners of the cell; the
  // documented range is [-1, 1].
  return std::clamp(r, -1.0, 1.0);
}

double fbm(const Vec3& p, int octaves, double lambda, double omega) {
  octaves = std::clamp(octaves, 1, kMaxOctaves);
  double sum = 0.0, norm = 0.0, amp = 1.0, freq = 1.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * gradient_noise(p * freq);
    norm += std::fabs(amp);
    amp *= omega;
    freq *= lambda;
  }
  return norm > 0.0 ? sum / norm : 0.0;
}

double turbulence(const Vec3& p, int octaves, double lambda, double omega) {
  octaves = std::clamp(octaves, 1, kMaxOctaves);
  double sum = 0.0, norm = 0.0, amp = 1.0, freq = 1.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * std::fabs(gradient_noise(p * freq));
    norm += std::fabs(amp);
    amp *= omega;
    freq *= lambda;
  }
  return norm > 0.0 ? std::fabs(sum) / norm : 0.0;
}

namespace {

// vector_noise's body, inlined into vector_turbulence's octave loop (a call per octave, with
// its result through memory, was 240 instructions of a six-octave warp).
[[gnu::always_inline]] inline Vec3 vector_noise_inline(const Vec3& p) {
  // One walk of the lattice for all three components (a third of the work of three noise
  // calls, which is what turbulence warps spend their time on): each corner's hash picks three
  // gradients, the second and third through the permutation again at fixed offsets. The
  // corner's three gradients come from one row of kCornerGradients, and components 0 and 1 are
  // computed as a pair (Pair2 below); see there for why and for why the bits do not change.
  if (!usable(p)) return Vec3(0.0);
  const double fx = fast_floor(p.x), fy = fast_floor(p.y), fz = fast_floor(p.z);
  const int X = lattice(fx), Y = lattice(fy), Z = lattice(fz);
  const double x = p.x - fx, y = p.y - fy, z = p.z - fz;
  // x's and y's fades as a pair (the same operations per element as fade()).
  const Pair2 uv = fade2(Pair2{x, y});
  const double u = uv[0], v = uv[1], w = fade(z);
  const int A = kPerm[X] + Y, AA = kPerm[A] + Z, AB = kPerm[A + 1] + Z;
  const int B = kPerm[X + 1] + Y, BA = kPerm[B] + Z, BB = kPerm[B + 1] + Z;
  const int corner[8] = {kPerm[AA], kPerm[BA], kPerm[AB], kPerm[BB], kPerm[AA + 1], kPerm[BA + 1], kPerm[AB + 1], kPerm[BB + 1]};
  // Corner i sits at (i & 1, (i >> 1) & 1, i >> 2) in the cell.
  const double xs[2] = {x, x - 1}, ys[2] = {y, y - 1}, zs[2] = {z, z - 1};
  Pair2 d01[8];    // components 0 and 1's gradient ramps at each corner
#pragma GCC unroll 8
  for (int i = 0; i < 8; ++i) {
    const CornerGradients& g = kCornerGradients[corner[i]];
    const double cx = xs[i & 1], cy = ys[(i >> 1) & 1], cz = zs[i >> 2];
    d01[i] = g.x01 * cx + g.y01 * cy + g.z01 * cz;
  }
  const Pair2 r01 = lerp2(w, lerp2(v, lerp2(u, d01[0], d01[1]), lerp2(u, d01[2], d01[3])),
                          lerp2(v, lerp2(u, d01[4], d01[5]), lerp2(u, d01[6], d01[7])));
  // Component 2 pairs the corner below (z) with the one above it: d2[j] holds corners j and
  // j + 4, so the u and v lerps run on both z layers at once and only the last (w) is scalar.
  // The same IEEE operations on each element as lerp(w, lerp(v, lerp(u, ..), ..), ..) of the
  // eight scalars (profile finding: component 2 alone was a third of the octave's arithmetic).
  const Pair2 zs2 = {z, z - 1};
  Pair2 d2[4];
#pragma GCC unroll 4
  for (int j = 0; j < 4; ++j) {
    const CornerGradients& lo = kCornerGradients[corner[j]];
    const CornerGradients& hi = kCornerGradients[corner[j + 4]];
    const double cx = xs[j & 1], cy = ys[j >> 1];
    d2[j] = Pair2{lo.g2[0], hi.g2[0]} * cx + Pair2{lo.g2[1], hi.g2[1]} * cy + Pair2{lo.g2[2], hi.g2[2]} * zs2;
  }
  const Pair2 r2v = lerp2(v, lerp2(u, d2[0], d2[1]), lerp2(u, d2[2], d2[3]));
  const double r2 = lerp(w, r2v[0], r2v[1]);
  return {std::clamp(r01[0], -1.0, 1.0), std::clamp(r01[1], -1.0, 1.0), std::clamp(r2, -1.0, 1.0)};
}

#if RTS_NOISE_AVX
// vector_turbulence on CPUs with AVX: the three components side by side in one 256-bit
// register (the fourth lane is unused), so each corner's ramp is 3 multiplies and 2 adds for
// all three and each lerp one operation, where the SSE2 code above needs a pair register for
// components 0 and 1 and another, corner below with corner above, for component 2. Profile
// finding (callgrind, bench/race/patterns.rts at 800x600): vector_turbulence was 21% of the
// process's instructions, 2,160 a wood sample (six octaves of the warp); this form takes 26-30%
// less time per call (a loop over 300,000 points). The same IEEE operations, in the same
// order, on each lane as vector_noise_inline does on each component, AVX has no fused
// multiply-add (and -ffp-contract=off forbids contracting), and the clamp keeps std::clamp's
// operand order: the same bits (tests/render/test_noise.cpp compares it with
// vector_turbulence_portable).
struct alignas(32) CornerRow4 {
  double x[4], y[4], z[4];   // components 0, 1, 2 (and 0) of the gradients at a corner hash
};
struct CornerTable4 {
  CornerRow4 row[256];
};
CornerTable4 make_corner_table4() {
  CornerTable4 t{};
  for (int h = 0; h < 256; ++h) {
    const double* g[3] = {kGrad[h & 15], kGrad[kPerm[(h + kComponentOffset[1]) & 255] & 15],
                          kGrad[kPerm[(h + kComponentOffset[2]) & 255] & 15]};
    for (int c = 0; c < 3; ++c) {
      t.row[h].x[c] = g[c][0];
      t.row[h].y[c] = g[c][1];
      t.row[h].z[c] = g[c][2];
    }
  }
  return t;
}
const CornerTable4 kCornerTable4 = make_corner_table4();

[[gnu::target("avx")]] inline __m256d lerp4(__m256d t, __m256d a, __m256d b) {
  return _mm256_add_pd(a, _mm256_mul_pd(t, _mm256_sub_pd(b, a)));
}

[[gnu::target("avx")]] Vec3 vector_turbulence_avx(const Vec3& p0, int octaves, double lambda, double omega) {
  __m256d sum = _mm256_setzero_pd();
  const __m256d lo = _mm256_set1_pd(-1.0), hi = _mm256_set1_pd(1.0);
  double amp = 1.0, freq = 1.0;
  for (int o = 0; o < octaves; ++o) {
    const Vec3 p = p0 * freq;
    __m256d n = _mm256_setzero_pd();
    if (usable(p)) {
      const double fx = fast_floor(p.x), fy = fast_floor(p.y), fz = fast_floor(p.z);
      const int X = lattice(fx), Y = lattice(fy), Z = lattice(fz);
      const double x = p.x - fx, y = p.y - fy, z = p.z - fz;
      const Pair2 uv = fade2(Pair2{x, y});
      const __m256d u = _mm256_set1_pd(uv[0]), v = _mm256_set1_pd(uv[1]), w = _mm256_set1_pd(fade(z));
      const int A = kPerm[X] + Y, AA = kPerm[A] + Z, AB = kPerm[A + 1] + Z;
      const int B = kPerm[X + 1] + Y, BA = kPerm[B] + Z, BB = kPerm[B + 1] + Z;
      const int corner[8] = {kPerm[AA], kPerm[BA], kPerm[AB], kPerm[BB], kPerm[AA + 1], kPerm[BA + 1], kPerm[AB + 1], kPerm[BB + 1]};
      const __m256d xs[2] = {_mm256_set1_pd(x), _mm256_set1_pd(x - 1)};
      const __m256d ys[2] = {_mm256_set1_pd(y), _mm256_set1_pd(y - 1)};
      const __m256d zs[2] = {_mm256_set1_pd(z), _mm256_set1_pd(z - 1)};
      __m256d d[8];
#pragma GCC unroll 8
      for (int i = 0; i < 8; ++i) {
        const CornerRow4& g = kCornerTable4.row[corner[i]];
        d[i] = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_load_pd(g.x), xs[i & 1]),
                                           _mm256_mul_pd(_mm256_load_pd(g.y), ys[(i >> 1) & 1])),
                             _mm256_mul_pd(_mm256_load_pd(g.z), zs[i >> 2]));
      }
      const __m256d r = lerp4(w, lerp4(v, lerp4(u, d[0], d[1]), lerp4(u, d[2], d[3])),
                              lerp4(v, lerp4(u, d[4], d[5]), lerp4(u, d[6], d[7])));
      // std::clamp(r, -1, 1) is r < -1 ? -1 : (1 < r ? 1 : r); max_pd(a, b) is a > b ? a : b
      // and min_pd(a, b) is a < b ? a : b, so the constants go first.
      n = _mm256_min_pd(hi, _mm256_max_pd(lo, r));
    }
    sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(amp), n));
    amp *= omega;
    freq *= lambda;
  }
  alignas(32) double out[4];
  _mm256_store_pd(out, sum);
  return {out[0], out[1], out[2]};
}

bool cpu_has_avx() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx");
}
#endif

}  // namespace

Vec3 vector_noise(const Vec3& p) { return vector_noise_inline(p); }

Vec3 vector_turbulence_portable(const Vec3& p, int octaves, double lambda, double omega) {
  octaves = std::clamp(octaves, 1, kMaxOctaves);
  Vec3 sum(0.0);
  double amp = 1.0, freq = 1.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * vector_noise_inline(p * freq);
    amp *= omega;
    freq *= lambda;
  }
  return sum;
}

Vec3 vector_turbulence(const Vec3& p, int octaves, double lambda, double omega) {
#if RTS_NOISE_AVX
  static const bool avx = cpu_has_avx();
  if (avx) return vector_turbulence_avx(p, std::clamp(octaves, 1, kMaxOctaves), lambda, omega);
#endif
  return vector_turbulence_portable(p, octaves, lambda, omega);
}

double cells(const Vec3& p) {
  if (!usable(p)) return 0.0;
  return unit(cell_hash(static_cast<int64_t>(std::floor(p.x)), static_cast<int64_t>(std::floor(p.y)),
                        static_cast<int64_t>(std::floor(p.z))));
}

void worley2(const Vec3& p, double& f1, double& f2) {
  f1 = f2 = 0.0;
  if (!usable(p)) return;
  const double fx = std::floor(p.x), fy = std::floor(p.y), fz = std::floor(p.z);
  const int64_t cx = static_cast<int64_t>(fx), cy = static_cast<int64_t>(fy), cz = static_cast<int64_t>(fz);
  const Vec3 local = p - Vec3(fx, fy, fz);
  double d1 = 1e30, d2 = 1e30;   // squared distances
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const uint64_t h = cell_hash(cx + dx, cy + dy, cz + dz);
        const Vec3 feature(dx + unit(mix64(h ^ 1)), dy + unit(mix64(h ^ 2)), dz + unit(mix64(h ^ 3)));
        const Vec3 d = feature - local;
        const double d2c = glm::dot(d, d);
        if (d2c < d1) {
          d2 = d1;
          d1 = d2c;
        } else if (d2c < d2) {
          d2 = d2c;
        }
      }
  f1 = std::sqrt(d1);
  f2 = std::sqrt(d2);
}

double worley(const Vec3& p) {
  double f1, f2;
  worley2(p, f1, f2);
  return f1;
}

}  // namespace rts::render::pattern
