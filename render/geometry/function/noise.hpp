// Noise for procedural patterns: Perlin's improved gradient noise (2002), sums of it (fbm,
// turbulence), a vector-valued variant for turbulence warps, and cellular (Worley) noise.
//
// Deterministic across platforms, builds and thread counts: the lattice hash is Perlin's fixed
// permutation table and integer arithmetic, there is no platform RNG and no state; the same
// point gives bit-identical values everywhere IEEE doubles round the same way.
//
// Ranges (tests/render/test_noise.cpp checks each):
//  - gradient_noise(p) in [-1, 1], 0 at every integer lattice point, mean 0, smooth (C2);
//    its gradient's length is at most kNoiseGradientBound (isosurfaces step by it).
//  - noise01(p) = 0.5 + 0.5 * gradient_noise(p), in [0, 1]: POV-Ray's Noise() convention.
//  - fbm(p, octaves, lambda, omega) = sum_i omega^i * gradient_noise(lambda^i * p), divided by
//    sum_i omega^i: in [-1, 1].
//  - turbulence(p, ...) = the same sum of |gradient_noise|: in [0, 1].
//  - vector_noise(p): three gradient noises in one lattice walk: x is gradient_noise(p), y and
//    z pick other gradients at each corner (re-hashed), so the three are uncorrelated.
//  - cells(p): one value in [0, 1) per unit cube (POV-Ray's `cells` pattern).
//  - worley(p): distance from p to the nearest feature point (one per unit cube), F1 in
//    [0, sqrt(3)]; worley2 gives F1 and F2 (crackle uses F2 - F1).
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace rts::render::pattern {

using Vec3 = glm::dvec3;

// A bound on |grad gradient_noise| (a Lipschitz constant). Measured, not proven: the largest
// slope found over 2 * 10^7 random points of the 256-periodic lattice plus a local search
// around the worst one is 3.39; 4 leaves 18% margin (the gradient-bound test checks it). An
// isosurface of k * noise can march in steps of |f| / (k * kNoiseGradientBound).
inline constexpr double kNoiseGradientBound = 4.0;

// Octave limits the builder and built-ins enforce (more octaves add nothing visible below
// a double's precision and cost time).
inline constexpr int kMaxOctaves = 16;

double gradient_noise(const Vec3& p);
inline double noise01(const Vec3& p) { return 0.5 + 0.5 * gradient_noise(p); }
double fbm(const Vec3& p, int octaves, double lambda, double omega);
double turbulence(const Vec3& p, int octaves, double lambda, double omega);
Vec3 vector_noise(const Vec3& p);
// sum_i omega^i * vector_noise(lambda^i * p), unnormalised (POV-Ray's DTurbulence): the
// displacement a `turbulence` warp scales.
Vec3 vector_turbulence(const Vec3& p, int octaves, double lambda, double omega);
// The same sum by the SSE2 code every x86-64 CPU runs; vector_turbulence takes an AVX form of
// it where the CPU has AVX, which must give the same bits (the tests compare the two).
Vec3 vector_turbulence_portable(const Vec3& p, int octaves, double lambda, double omega);
double cells(const Vec3& p);
double worley(const Vec3& p);
void worley2(const Vec3& p, double& f1, double& f2);

}  // namespace rts::render::pattern
