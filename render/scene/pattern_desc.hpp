// The description of a procedural pattern texture (marble, wood, bozo, ..., or a user function),
// as the scene builder fills it and render/shade/pattern/patterns.cpp evaluates it.
// POV-Ray's names and meanings; docs/textures.md shows each.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

namespace rts::render {

class CompiledFunction;

// POV-Ray's pattern keywords. Bumps, Dents, Ripples, Waves and Wrinkles are POV-Ray's normal
// patterns; as rts textures they are height fields a material's `bump` turns into normals.
enum class PatternKind : uint8_t {
  Bozo, Spotted, Granite, Marble, Wood, Agate, Onion, Leopard, Wrinkles, Crackle, Cells,
  Bumps, Dents, Ripples, Waves, Function,
  Gradient,   // `gradient` with a color_map: the point's coordinate along `axis` (POV-Ray's gradient)
  // POV-Ray's geometric patterns: the angle around y, spirals around z (`arms` of them), and
  // the distance-based boxed, cylindrical, planar and spherical (1 at the centre, 0 from 1 out).
  Radial, Spiral1, Spiral2, Boxed, Cylindrical, Planar, Spherical,
};

// How the pattern's value (times frequency, plus phase) becomes the color map's index:
// Ramp repeats [0, 1) (POV-Ray's default; values already in [0, 1] pass unchanged), Triangle
// goes up and back down once per unit (marble's and wood's default), Sine is
// (sin(2 pi v) + 1) / 2, Scallop |sin(pi v)|, Cubic a smoothstep of the ramp, Clamp clamps to
// [0, 1] (a user function's default).
enum class WaveKind : uint8_t { Ramp, Triangle, Sine, Scallop, Cubic, Clamp };

struct ColorMapEntry {
  double value = 0.0;
  glm::dvec3 color{0.0};   // linear rgb
  // POV-Ray's `transmit` (rgbt's t): how much of what lies behind shows through. Only a
  // sky_sphere's layers (render/shade/sky_sphere.hpp) and a layered material's coats
  // (render/shade/layers.hpp) look at it; other surfaces ignore it.
  double transmit = 0.0;
  // POV-Ray's pigment_map: the entry is a texture (a TextureId built before this one; the
  // maximum uint32_t, scene.hpp's kNoId, when the entry is the plain `color`), evaluated at the
  // same texture-space point as the map's own pattern, after its own transform.
  uint32_t texture = 0xffffffffu;
};

struct PatternDesc {
  PatternKind kind = PatternKind::Bozo;
  // Turbulence: a warp p += turbulence * vector_turbulence(p) before the pattern (per axis);
  // marble and agate add the scalar turbulence inside the pattern as POV-Ray does.
  glm::dvec3 turbulence{0.0};
  int octaves = 6;
  double lambda = 2.0;
  double omega = 0.5;
  WaveKind wave = WaveKind::Ramp;
  double frequency = 1.0;
  double phase = 0.0;
  double agate_turb = 1.0;   // agate's own turbulence scale (POV-Ray's agate_turb)
  int axis = 1;              // Gradient: 0 = x, 1 = y, 2 = z
  double arms = 1.0;         // Spiral1, Spiral2: how many arms wind around the axis
  // Ascending values; below the first entry the first color, above the last the last,
  // linear interpolation between. Never empty once built (the builder supplies color1→color2).
  std::vector<ColorMapEntry> color_map;
  std::shared_ptr<const CompiledFunction> function;   // Function: value = f(x, y, z)
};

}  // namespace rts::render
