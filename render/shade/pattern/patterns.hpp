// POV-Ray's patterns as functions of a texture-space point: each gives a value (mostly in
// [0, 1]) that the wave function and the color map turn into a color. The meanings follow
// POV-Ray 3.7 (its pattern.cpp), with rts's own noise (render/geometry/function/noise.hpp), so the
// look matches POV-Ray's by eye, not bit for bit:
//  - bozo, spotted, bumps: noise01(p).                      dents: noise01(p)^3.
//  - granite: sum over 6 octaves of |gradient_noise(4 * 2^i * p)| / 2^i (POV-Ray's
//            |0.5 - Noise| at POV-Ray's contrast), at most 1.
//  - marble: x + turbulence_x * T(p), triangle wave (T: POV-Ray's scalar turbulence, an
//            unnormalised sum of noise01 over the octaves).
//  - wood:   sqrt(x^2 + y^2) (cylinders around z) after the turbulence warp, triangle wave.
//  - agate:  0.5 * (sin(2 pi (1.3 * agate_turb * T(p) + 1.1 z)) + 1)^0.77.
//  - onion:  |p| (spheres around the origin).       leopard: ((sin x + sin y + sin z) / 3)^2.
//  - wrinkles: half of T(p) over ten octaves (lambda 2, omega 0.5), in [0, 1].
//  - crackle: F2 - F1 of Worley noise (0 on the cell borders).   cells: one value per unit cube.
//  - ripples, waves: concentric sine waves from ten fixed centres on the unit sphere,
//            `frequency` rings per unit and `phase` (waves: each centre at its own slower
//            frequency, weighted by its inverse, as POV-Ray's). As colors the frequency and phase
//            apply again in the wave function, as in POV-Ray (hard-edged bands when frequency
//            > 1); as a bump's height (height = true) only inside, so the height stays smooth.
//  - gradient: the coordinate along its axis (a `gradient` block with a color_map).
//  - function: a user function f(x, y, z) (render/geometry/function/compiled_function.hpp).
// Every pattern but marble, wood and agate applies a non-zero `turbulence` as a warp
// p += turbulence * vector_turbulence(p) first (POV-Ray's classic turbulence).
#pragma once

#include "render/scene/pattern_desc.hpp"

namespace rts::render::pattern {

// The pattern's value at texture-space point q, before the wave function. `height`: the value
// feeds a bump's height, not a color (only ripples and waves differ).
double raw_value(const PatternDesc& d, const glm::dvec3& q, bool height = false);
// The wave function applied to value * frequency + phase (for a height from ripples or waves,
// which take frequency and phase inside the pattern, to the value itself).
double wave(const PatternDesc& d, double value, bool height = false);
// Where index t falls in a non-empty colour map (entries ascending): entries a and b and b's
// weight w; a == b at or beyond an end (NaN: the first), or between two entries at one value.
struct MapSpan {
  std::size_t a = 0, b = 0;
  double w = 0.0;
};
MapSpan map_span(const std::vector<ColorMapEntry>& map, double t);
// The color map's color at index t (entries ascending; clamped outside).
glm::dvec3 color_map_lookup(const std::vector<ColorMapEntry>& map, double t);
// All three: the color of the pattern at q (height: as a bump's height).
glm::dvec3 pattern_color(const PatternDesc& d, const glm::dvec3& q, bool height = false);
// The color map's transmit at index t, interpolated as the colors are.
double transmit_lookup(const std::vector<ColorMapEntry>& map, double t);
// The color and (w) the transmit at q, for a sky_sphere's layers.
glm::dvec4 pattern_color_transmit(const PatternDesc& d, const glm::dvec3& q);

}  // namespace rts::render::pattern
