// Perlin's improved noise ("Improving Noise", SIGGRAPH 2002): a quintic fade, twelve edge
// gradients picked by a permutation of 0..255. The permutation is built at compile time by a
// Fisher-Yates shuffle driven by a fixed integer hash, so it is the same on every platform.
#include "render/geometry/function/noise.hpp"

#include <algorithm>
#include <array>
#include <cmath>

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

// Perlin's 12 edge gradients (16 cases, four repeated), as in his reference code, as a table:
// a dot product instead of his branches, which mispredict on every other corner.
constexpr double kGrad[16][3] = {{1, 1, 0},  {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1},  {-1, 0, 1},
                                 {1, 0, -1}, {-1, 0, -1}, {0, 1, 1},  {0, -1, 1}, {0, 1, -1}, {0, -1, -1},
                                 {1, 1, 0},  {0, -1, 1}, {-1, 1, 0}, {0, -1, -1}};
double grad(int hash, double x, double y, double z) {
  const double* g = kGrad[hash & 15];
  return g[0] * x + g[1] * y + g[2] * z;
}

// Beyond this magnitude a double has no fractional part left: the noise is 0 there (as at a
// lattice point), and the integer conversions below cannot overflow.
constexpr double kMaxCoordinate = 4.0e15;

bool usable(const Vec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::fabs(p.x) < kMaxCoordinate &&
         std::fabs(p.y) < kMaxCoordinate && std::fabs(p.z) < kMaxCoordinate;
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
  const double u = fade(x), v = fade(y), w = fade(z);
  const int A = kPerm[X] + Y, AA = kPerm[A] + Z, AB = kPerm[A + 1] + Z;
  const int B = kPerm[X + 1] + Y, BA = kPerm[B] + Z, BB = kPerm[B + 1] + Z;
  const double r = lerp(w,
                        lerp(v, lerp(u, grad(kPerm[AA], x, y, z), grad(kPerm[BA], x - 1, y, z)),
                             lerp(u, grad(kPerm[AB], x, y - 1, z), grad(kPerm[BB], x - 1, y - 1, z))),
                        lerp(v, lerp(u, grad(kPerm[AA + 1], x, y, z - 1), grad(kPerm[BA + 1], x - 1, y, z - 1)),
                             lerp(u, grad(kPerm[AB + 1], x, y - 1, z - 1), grad(kPerm[BB + 1], x - 1, y - 1, z - 1))));
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

Vec3 vector_noise(const Vec3& p) {
  // One walk of the lattice for all three components (a third of the work of three noise
  // calls, which is what turbulence warps spend their time on): each corner's hash picks three
  // gradients, the second and third through the permutation again at fixed offsets.
  if (!usable(p)) return Vec3(0.0);
  const double fx = fast_floor(p.x), fy = fast_floor(p.y), fz = fast_floor(p.z);
  const int X = lattice(fx), Y = lattice(fy), Z = lattice(fz);
  const double x = p.x - fx, y = p.y - fy, z = p.z - fz;
  const double u = fade(x), v = fade(y), w = fade(z);
  const int A = kPerm[X] + Y, AA = kPerm[A] + Z, AB = kPerm[A + 1] + Z;
  const int B = kPerm[X + 1] + Y, BA = kPerm[B] + Z, BB = kPerm[B + 1] + Z;
  const int corner[8] = {kPerm[AA], kPerm[BA], kPerm[AB], kPerm[BB], kPerm[AA + 1], kPerm[BA + 1], kPerm[AB + 1], kPerm[BB + 1]};
  Vec3 out;
  for (int c = 0; c < 3; ++c) {
    int h[8];
    for (int i = 0; i < 8; ++i) h[i] = c == 0 ? corner[i] : kPerm[(corner[i] + kComponentOffset[c]) & 255];
    const double r = lerp(w,
                          lerp(v, lerp(u, grad(h[0], x, y, z), grad(h[1], x - 1, y, z)),
                               lerp(u, grad(h[2], x, y - 1, z), grad(h[3], x - 1, y - 1, z))),
                          lerp(v, lerp(u, grad(h[4], x, y, z - 1), grad(h[5], x - 1, y, z - 1)),
                               lerp(u, grad(h[6], x, y - 1, z - 1), grad(h[7], x - 1, y - 1, z - 1))));
    out[c] = std::clamp(r, -1.0, 1.0);
  }
  return out;
}

Vec3 vector_turbulence(const Vec3& p, int octaves, double lambda, double omega) {
  octaves = std::clamp(octaves, 1, kMaxOctaves);
  Vec3 sum(0.0);
  double amp = 1.0, freq = 1.0;
  for (int i = 0; i < octaves; ++i) {
    sum += amp * vector_noise(p * freq);
    amp *= omega;
    freq *= lambda;
  }
  return sum;
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
