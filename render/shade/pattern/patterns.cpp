// POV-Ray's patterns: see patterns.hpp for each one's meaning.
#include "render/shade/pattern/patterns.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/geometry/function/compiled_function.hpp"
#include "render/geometry/function/noise.hpp"

namespace rts::render::pattern {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// POV-Ray's scalar Turbulence(): noise01(p) + sum_{i>=1} omega^i * noise01(lambda^i p),
// unnormalised (about 1 on average for omega 0.5), which marble and agate add to their index.
double pov_turbulence(const glm::dvec3& p, int octaves, double lambda, double omega) {
  octaves = std::clamp(octaves, 1, kMaxOctaves);
  double value = noise01(p), l = lambda, o = omega;
  for (int i = 2; i <= octaves; ++i) {
    value += o * noise01(p * l);
    l *= lambda;
    o *= omega;
  }
  return value;
}

double frac(double v) {
  if (!std::isfinite(v)) return 0.0;
  const double f = v - std::floor(v);
  return f >= 1.0 ? 0.0 : f;
}

// Ten wave centres for ripples and waves on the unit sphere around the origin, as POV-Ray's are
// (it draws their directions from its noise; any spread-out set of directions gives the look).
constexpr glm::dvec3 kWaveDirections[10] = {
    {0.42, -0.21, 0.33},  {-0.37, 0.48, -0.12}, {0.05, 0.31, 0.57},  {-0.55, -0.36, 0.19}, {0.29, 0.52, -0.44},
    {-0.18, -0.61, -0.27}, {0.63, 0.08, -0.16},  {-0.46, 0.13, 0.51}, {0.14, -0.44, -0.58}, {-0.07, 0.66, 0.24}};
struct WaveSources {
  glm::dvec3 centre[10];
  WaveSources() {
    for (int i = 0; i < 10; ++i) centre[i] = glm::normalize(kWaveDirections[i]);
  }
};
const WaveSources kWaveSources;
// `waves` gives each source its own frequency factor; these are the ten POV-Ray 3.7 uses (its
// fixed generator's values in [0.01, 1.01], rounded), so the slow, large swells weigh as
// POV-Ray's do: each wave's amplitude is 1 / its factor.
constexpr double kWaveFactors[10] = {0.9191, 0.96, 0.4332, 0.7093, 0.6892, 0.9914, 0.783, 0.4007, 0.2297, 0.1685};

// POV-Ray's ripples: the mean of ten sines of the distance to each centre, `frequency` waves
// per unit, mapped to [0, 1].
double ripples(const glm::dvec3& p, double frequency, double phase) {
  double sum = 0.0;
  for (const glm::dvec3& c : kWaveSources.centre) {
    const double r = glm::length(p - c);
    sum += std::sin(kTwoPi * (r * frequency + phase));
  }
  return 0.5 + 0.5 * sum / 10.0;
}

// POV-Ray's waves: each centre's sine at frequency * its factor, weighted by 1 / its factor.
// As a color (height false) POV-Ray's scaling, 0.5 + 0.2 * the mean, whose swings (up to
// +-0.45) the color map's frequency can push over a wrap: POV-Ray's hard-edged bands. As a
// bump's height, the weighted mean over the weights' sum, a smooth value in [0, 1].
double waves(const glm::dvec3& p, double frequency, double phase, bool height) {
  double sum = 0.0, weights = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double r = glm::length(p - kWaveSources.centre[i]);
    sum += std::sin(kTwoPi * (r * frequency * kWaveFactors[i] + phase)) / kWaveFactors[i];
    weights += 1.0 / kWaveFactors[i];
  }
  return height ? 0.5 + 0.5 * sum / weights : 0.5 + 0.2 * sum / 10.0;
}

}  // namespace

namespace {
// POV-Ray's distance patterns: 1 at the centre falling to 0 at distance 1, and 0 beyond (a
// negative distance cannot occur; POV-Ray's 1 for it is kept).
double clip_density(double r) { return r < 0.0 ? 1.0 : r > 1.0 ? 0.0 : 1.0 - r; }
// 0 at whole numbers, 1 half-way: POV-Ray's triangle wave.
double triangle_wave(double v) {
  const double f = v - std::floor(v);
  return f <= 0.5 ? 2.0 * f : 2.0 - 2.0 * f;
}
}  // namespace

double raw_value(const PatternDesc& d, const glm::dvec3& q, bool height) {
  glm::dvec3 p = q;
  const bool warp = d.turbulence != glm::dvec3(0.0) && d.kind != PatternKind::Marble &&
                    d.kind != PatternKind::Agate && d.kind != PatternKind::Spiral1 && d.kind != PatternKind::Spiral2;
  if (warp) p += d.turbulence * vector_turbulence(p, d.octaves, d.lambda, d.omega);
  switch (d.kind) {
    case PatternKind::Bozo:
    case PatternKind::Spotted:
    case PatternKind::Bumps: return noise01(p);
    case PatternKind::Dents: {
      const double n = noise01(p);
      return n * n * n;
    }
    case PatternKind::Granite: {
      double value = 0.0, freq = 1.0;
      // POV-Ray sums |0.5 - Noise|; its Noise spreads about twice as wide as noise01, so the
      // signed noise (|gradient_noise| = 2 |0.5 - noise01|) gives granite POV-Ray's contrast.
      // POV-Ray's sum never exceeds 1; at twice the spread this one can (rarely), and the
      // ramp wave would wrap those peaks to the map's first color: clamp them instead.
      for (int i = 0; i < 6; ++i, freq *= 2.0) value += std::fabs(gradient_noise(p * (4.0 * freq))) / freq;
      return std::min(1.0, value);
    }
    case PatternKind::Marble:
      return p.x + d.turbulence.x * pov_turbulence(p, d.octaves, d.lambda, d.omega);
    case PatternKind::Wood: return std::sqrt(p.x * p.x + p.y * p.y);
    case PatternKind::Agate: {
      const double t = d.agate_turb * pov_turbulence(p, d.octaves, d.lambda, d.omega);
      const double v = 0.5 * (std::sin(kTwoPi * (1.3 * t + 1.1 * p.z)) + 1.0);
      return std::pow(std::clamp(v, 0.0, 1.0), 0.77);
    }
    case PatternKind::Onion: return glm::length(p);
    case PatternKind::Leopard: {
      const double t = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
      return t * t;
    }
    case PatternKind::Wrinkles: return std::min(1.0, 0.5 * pov_turbulence(p, 10, 2.0, 0.5));
    case PatternKind::Crackle: {
      double f1, f2;
      worley2(p, f1, f2);
      return std::min(1.0, f2 - f1);
    }
    case PatternKind::Cells: return cells(p);
    case PatternKind::Ripples: return ripples(p, d.frequency, d.phase);
    case PatternKind::Waves: return waves(p, d.frequency, d.phase, height);
    case PatternKind::Function: return d.function ? d.function->eval(p) : 0.0;
    case PatternKind::Gradient: return p[d.axis < 0 || d.axis > 2 ? 1 : d.axis];
    case PatternKind::Radial:
      // A quarter turn from the +x side, once around y (POV-Ray's radial; on the axis 1/4).
      if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
      return 0.25 + (std::atan2(p.x, p.z) + std::numbers::pi) / kTwoPi;
    case PatternKind::Spiral1:
    case PatternKind::Spiral2: {
      // Around the z axis: the distance plus the arms' share of the angle from -y, climbing
      // with z; turbulence (its x) added inside, as marble's. Spiral2 folds both (two crossed
      // families of arms).
      const double rad = std::sqrt(p.x * p.x + p.y * p.y);
      const double phi = rad == 0.0 ? 0.0 : p.x < 0.0 ? 1.5 * std::numbers::pi - std::asin(p.y / rad)
                                                       : 0.5 * std::numbers::pi + std::asin(p.y / rad);
      const double turb = d.turbulence.x != 0.0 ? d.turbulence.x * pov_turbulence(p, d.octaves, d.lambda, d.omega) : 0.0;
      const double v = p.z + rad + d.arms * phi / kTwoPi + turb;
      if (d.kind == PatternKind::Spiral1) return v;
      return triangle_wave(rad) + triangle_wave(v);
    }
    case PatternKind::Boxed: return clip_density(std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
    case PatternKind::Cylindrical: return clip_density(std::sqrt(p.x * p.x + p.z * p.z));
    case PatternKind::Planar: return clip_density(std::fabs(p.y));
    case PatternKind::Spherical: return clip_density(glm::length(p));
  }
  return 0.0;
}

double wave(const PatternDesc& d, double value, bool height) {
  // Ripples and waves take frequency and phase inside, for their rings; as colors POV-Ray
  // applies both a second time here, as for every pattern (so at frequency 2 the value wraps
  // where it crosses 0.5: the hard-edged bands POV-Ray shows). A bump's height would turn
  // those edges into creases, so heights take them once (POV-Ray's normals have their own,
  // smooth ripples and waves).
  const bool inside = height && (d.kind == PatternKind::Ripples || d.kind == PatternKind::Waves);
  const double v = inside ? value : value * d.frequency + d.phase;
  if (!std::isfinite(v)) return 0.0;
  switch (d.wave) {
    case WaveKind::Ramp: return v >= 0.0 && v <= 1.0 ? v : frac(v);
    case WaveKind::Triangle: {
      const double f = frac(v);
      return f <= 0.5 ? 2.0 * f : 2.0 - 2.0 * f;
    }
    case WaveKind::Sine: return 0.5 * (std::sin(kTwoPi * v) + 1.0);
    case WaveKind::Scallop: return std::fabs(std::sin(std::numbers::pi * v));
    case WaveKind::Cubic: {
      const double f = v >= 0.0 && v <= 1.0 ? v : frac(v);
      return f * f * (3.0 - 2.0 * f);
    }
    case WaveKind::Clamp: return std::clamp(v, 0.0, 1.0);
  }
  return 0.0;
}

MapSpan map_span(const std::vector<ColorMapEntry>& map, double t) {
  if (!(t > map.front().value)) return {};   // also NaN
  if (t >= map.back().value) return {map.size() - 1, map.size() - 1, 0.0};
  std::size_t i = 1;
  while (map[i].value < t) ++i;   // map[i-1].value < t <= map[i].value
  const double span = map[i].value - map[i - 1].value;
  if (!(span > 0.0)) return {i, i, 0.0};
  return {i - 1, i, (t - map[i - 1].value) / span};
}

glm::dvec3 color_map_lookup(const std::vector<ColorMapEntry>& map, double t) {
  if (map.empty()) return glm::dvec3(t);
  const MapSpan s = map_span(map, t);
  if (s.a == s.b) return map[s.a].color;
  return map[s.a].color + (map[s.b].color - map[s.a].color) * s.w;
}

double transmit_lookup(const std::vector<ColorMapEntry>& map, double t) {
  if (map.empty()) return 0.0;
  const MapSpan s = map_span(map, t);
  if (s.a == s.b) return map[s.a].transmit;
  return map[s.a].transmit + (map[s.b].transmit - map[s.a].transmit) * s.w;
}

glm::dvec3 pattern_color(const PatternDesc& d, const glm::dvec3& q, bool height) {
  return color_map_lookup(d.color_map, wave(d, raw_value(d, q, height), height));
}

glm::dvec4 pattern_color_transmit(const PatternDesc& d, const glm::dvec3& q) {
  const double t = wave(d, raw_value(d, q));
  return glm::dvec4(color_map_lookup(d.color_map, t), transmit_lookup(d.color_map, t));
}

}  // namespace rts::render::pattern
