// The property tables of block_properties.hpp. Types, defaults and meanings are written as
// docs/rendering.md writes them; a property added to the builder is added here first (the
// builder's name lists come from these tables).
#include "render/builder/block_properties.hpp"

#include <array>

#include "render/geometry/shapes/shape_kinds.hpp"

namespace rts::render {

namespace {

constexpr PropertyInfo kSettings[] = {
    {"width", "whole number > 0", "`640`", "Image width in pixels."},
    {"height", "whole number > 0", "`480`", "Image height in pixels."},
    {"samples", "whole number ≥ 1", "`1`", "Samples per pixel (antialiasing, soft effects)."},
    {"max_depth", "whole number ≥ 0", "`5`", "Reflection/refraction bounces (capped at 10,000)."},
    {"background", "color", "`rgb(0)`", "The color of rays that hit nothing."},
    {"ambient_light", "color", "`rgb(1)`", "Multiplies every material's `ambient` term."},
    {"seed", "whole number ≥ 0", "`0`", "Seed for every random decision."},
    {"sampler", "string", "`\"sobol\"`", "How samples are placed: \"random\", \"stratified\" or \"sobol\"."},
    {"environment", "texture", "none", "What rays that leave the scene see: a latlong_map, cube_map, sky_sphere or any texture."},
    {"environment_ambient", "bool", "`false`", "Also light the ambient term with the environment."},
    {"frames", "whole number ≥ 1", "`1`", "An animation's frame count; 1 is a still."},
    {"integrator", "string", "`\"whitted\"`", "\"whitted\" or \"path\" (the physically based path tracer)."},
    {"light_falloff", "string", "`\"inverse_square\"`", "Path mode: \"attenuation\" makes point, spot and area lights fall off by their `attenuation`, as in Whitted mode and POV-Ray (not physical; `rts import` writes it)."},
    {"fog_distance", "number ≥ 0", "`0` (no fog)", "Constant fog: at this distance 37% of the light is left."},
    {"fog_color", "color", "`rgb(0)`", "The fog's colour."},
    {"fog_filter", "number in [0, 1]", "`0`", "Light through the fog is tinted by its colour by this much (POV-Ray's fog colour filter): it keeps (1 - f) + f * fog_color."},
    {"fog_transmit", "number in [0, 1]", "`0`", "The fog lets at least this much of the light through, however far (POV-Ray's fog colour transmit)."},
    {"fog_offset", "number", "`0`", "Ground fog: the height of its top."},
    {"fog_altitude", "number ≥ 0", "`0`", "Above 0: ground fog, thinning above `fog_offset`."},
    {"fog_turbulence", "number or vector ≥ 0", "`0` (none)", "Turbulent fog: scales the point where the noise is read (POV-Ray's fog turbulence)."},
    {"fog_turb_depth", "number ≥ 0", "`0.5`", "Turbulent fog: how much the noise thins the fog."},
    {"fog_octaves", "whole number 1 to 16", "`6`", "Turbulent fog: octaves of noise."},
    {"fog_omega", "number", "`0.5`", "Turbulent fog: each octave's weight against the last."},
    {"fog_lambda", "number", "`2`", "Turbulent fog: each octave's frequency against the last."},
    {"output_gamma", "string or number", "`\"srgb\"`", "\"linear\": PNG output stores the linear values (`--linear` in the scene). A number g: the image's values are raised to g before they are written (POV-Ray's assumed_gamma g)."},
    {"aov", "string", "none", "Auxiliary images to write beside the output, as --aov (\"normal,depth\")."},
    {"depth_range", "vector", "none", "Depth AOV: the distances mapped to black and white, as --depth-range."},
    {"depth_miss", "number", "`0`", "Depth AOV value where nothing is hit, as --depth-miss."},
    {"normal_miss", "number", "`0`", "Normal AOV value where nothing is hit, as --normal-miss."},
    {"clamp", "number ≥ 0", "`0` (off)", "Path mode: the most one camera sample may add to a pixel (biased)."},
    {"media_absorption", "color ≥ 0", "`rgb(0)`", "Medium around the objects: light absorbed per unit length (POV-Ray's media absorption)."},
    {"media_scattering", "color ≥ 0", "`rgb(0)`", "Medium around the objects: light scattered per unit length (POV-Ray's scattering color)."},
    {"media_emission", "color ≥ 0", "`rgb(0)`", "Medium around the objects: light given off per unit length."},
    {"media_eccentricity", "number in (-1, 1)", "`0`", "Medium around the objects: the phase function's mean cosine (Henyey-Greenstein; 0 isotropic, > 0 forward)."},
    {"media_density", "texture", "none", "Medium around the objects: scales the three above by the texture's value (mean channel, clamped to [0, 1]) at each world point."},
    {"media_samples", "whole number ≥ 1", "`16`", "Whitted mode: points marched per ray segment in a medium."},
};

constexpr PropertyInfo kCamera[] = {
    {"projection", "string", "`\"perspective\"`", "\"perspective\" or \"orthographic\"; or POV-Ray's \"fisheye\", \"ultra_wide_angle\", \"omnimax\", \"panoramic\", \"cylinder1\" to \"cylinder4\", \"spherical\" (docs/rendering.md#cameras)."},
    {"position", "vector", "`<0, 0, -5>`", "The eye (perspective) or the centre of the view (orthographic)."},
    {"look_at", "vector", "`<0, 0, 0>`", "The point at the image centre; must differ from `position`."},
    {"up", "vector", "`<0, 1, 0>`", "Which way is up in the image."},
    {"fov", "number in (0, 180)", "`60`", "Perspective: field of view in degrees, across `fov_axis`. POV-Ray's projections: their `angle`, up to 360 (default 90; spherical 360)."},
    {"vertical_fov", "number in (0, 360]", "half of `fov`", "Spherical projection: the vertical sweep in degrees (POV-Ray's second angle; default 180 without `fov`)."},
    {"fov_axis", "string", "`\"horizontal\"`", "\"horizontal\" or \"vertical\": which side `fov` spans."},
    {"handedness", "string", "`\"left\"`", "\"left\" or \"right\" (OpenGL's, the courses')."},
    {"view_width", "number > 0", "`4`", "Orthographic: width of the view in scene units."},
    {"aperture", "number ≥ 0", "`0`", "Lens diameter; above 0, depth of field."},
    {"focus_distance", "number ≥ 0", "`0`", "Distance to the plane in focus; 0 is the distance to `look_at`."},
    {"direction", "vector", "none", "The view direction (instead of look_at), as the courses write it."},
    {"right", "vector", "none", "The image's right edge direction (POV-Ray's right), with direction."},
};

constexpr PropertyInfo kMaterial[] = {
    {"color", "color, or a texture", "`rgb(0.8)`", "Base (diffuse) color."},
    {"texture", "texture", "none", "Replaces `color` by the texture's color at each point."},
    {"emission", "color, or a texture", "`rgb(0)`", "Light the surface gives off towards the camera."},
    {"ambient", "number or color ≥ 0", "`0.1`", "Weight of `settings.ambient_light`; a color weighs each channel (POV-Ray's `ambient rgb <...>`)."},
    {"diffuse", "number ≥ 0, or a texture", "`0.7`", "Lambertian weight."},
    {"specular", "number or color ≥ 0, or a texture", "`0`", "Phong highlight weight."},
    {"shininess", "number ≥ 0", "`32`", "Phong exponent: higher is a smaller, sharper highlight."},
    {"reflect", "number or color ≥ 0, or a texture", "`0`", "Mirror reflection weight, per channel."},
    {"transmit", "number or color ≥ 0, or a texture", "`0`", "Transmission (refraction) weight, per channel."},
    {"ior", "number > 0", "`1`", "Index of refraction of the inside (1.5 glass, 1.33 water)."},
    {"fresnel", "bool", "`false`", "Angle-dependent reflection (Schlick's approximation with `ior`)."},
    {"roughness", "number ≥ 0", "`0`", "Above 0, blurred (glossy) reflections."},
    {"ior_relative", "bool", "`false`", "`ior` is the ratio to the medium around the object."},
    {"bump", "texture", "none", "A height field that perturbs the normal."},
    {"bump_scale", "number", "`1`", "The height of `bump`'s white."},
    {"normal_map", "texture", "none", "A tangent-space normal map."},
    {"highlight", "string", "`\"phong\"`", "The highlight's lobe: \"phong\" (R·V) or \"blinn\" (N·H)."},
    {"brilliance", "number ≥ 0", "`1`", "Whitted: the diffuse term is (N·L)^brilliance, a steeper fall-off above 1 (POV-Ray's brilliance; path mode: Lambert)."},
    {"metallic", "number ≥ 0", "`0`", "Whitted: tints the highlight with the surface color, less at grazing light (POV-Ray's metallic; 1 in full)."},
    {"reflect_metallic", "number ≥ 0", "`0`", "Whitted: tints the reflection with the surface color, less at grazing angles (POV-Ray's reflection { metallic }; 1 in full)."},
    {"reflect_min", "color ≥ 0", "none", "Whitted: the reflection head-on, rising to `reflect` at grazing angles (by Fresnel's factor with `fresnel`, else by (1 − cos)^reflect_falloff): POV-Ray's reflection { min, max }."},
    {"reflect_falloff", "number ≥ 0", "`1`", "Whitted, with `reflect_min` and no `fresnel`: the exponent of (1 − cos) that blends reflect_min into reflect (POV-Ray's reflection falloff)."},
    {"media_absorption", "color ≥ 0", "`rgb(0)`", "Medium inside (needs `transmit`): light absorbed per unit length (POV-Ray's media absorption)."},
    {"media_scattering", "color ≥ 0", "`rgb(0)`", "Medium inside (needs `transmit`): light scattered per unit length (POV-Ray's scattering color)."},
    {"media_emission", "color ≥ 0", "`rgb(0)`", "Medium inside (needs `transmit`): light given off per unit length."},
    {"media_eccentricity", "number in (-1, 1)", "`0`", "Medium inside (needs `transmit`): the phase function's mean cosine (Henyey-Greenstein; 0 isotropic, > 0 forward)."},
    {"fade_distance", "number > 0", "none", "POV-Ray's interior fade (needs `transmit`): light crossing a distance d of the inside keeps fade_color + (1 - fade_color) / (1 + (d / fade_distance)^fade_power); with fade_power ≥ 1000, exp(-(1 - fade_color) d / fade_distance)."},
    {"fade_power", "number ≥ 0", "`0`", "With `fade_distance`: how fast the fade falls with distance (1 linear, 2 quadratic; 1000 and more exponential)."},
    {"fade_color", "color in [0, 1]", "`rgb(0)`", "With `fade_distance`: what the fade tends to at great distances (each channel)."},
    {"media_density", "texture", "none", "Medium inside (needs `transmit`): scales the three above by the texture's value (mean channel, clamped to [0, 1]) at each world point."},
    {"pattern", "texture", "none", "With `materials`: the texture whose luminance (0 to 1) picks the material at each point; nothing else may be given."},
    {"materials", "list of materials", "none", "With `pattern`: the materials chosen among, in equal ranges of the luminance, the first for the darkest (POV-Ray's texture checker, texture_map)."},
    {"layers", "list of materials", "none", "Layered material: the base first, each later material a coat over those before; a coat's transmit (its colour map's or its own) shows what lies below (POV-Ray's layered textures); other properties given with it change the top layer (POV-Ray's modifiers of a layered texture)."},
};

// The properties every light takes, in the order the builder has always listed them (which
// decides between equally close "did you mean" suggestions).
#define RTS_LIGHT_COLOR                                                \
  {"color", "color ≥ 0", "`rgb(1)`", "The light's color."},           \
      {"intensity", "number ≥ 0", "`1`", "Multiplies the color."}
#define RTS_LIGHT_ATTENUATION                                                                       \
  {"attenuation", "vector ≥ 0", "`<1, 0, 0>`", "<c, l, q>: the light is divided by c + l·d + q·d²."}, \
      {"attenuation_clamp", "bool", "`false`", "Caps the attenuation factor at 1."}
#define RTS_LIGHT_SHADOWS {"shadows", "bool", "`true`", "Cast shadows (false lights through everything, cheaper)."}

constexpr PropertyInfo kPointLight[] = {
    {"position", "vector", "*required*", "Where the light is."},
    RTS_LIGHT_COLOR,
    RTS_LIGHT_ATTENUATION,
    RTS_LIGHT_SHADOWS,
};
constexpr PropertyInfo kSpotLight[] = {
    {"position", "vector", "*required*", "Where the light is."},
    {"point_at", "vector", "*required*", "The point the cone's axis goes through."},
    {"radius", "degrees in [0, 90]", "`30`", "Full intensity within this half-angle (90: the whole half-space in front; 0: the falloff cone alone)."},
    {"falloff", "degrees, radius to 90", "`45`", "Zero intensity from this half-angle."},
    RTS_LIGHT_COLOR,
    RTS_LIGHT_ATTENUATION,
    RTS_LIGHT_SHADOWS,
};
constexpr PropertyInfo kDirectionalLight[] = {
    {"direction", "vector", "*required*", "The direction the light travels (the sun)."},
    RTS_LIGHT_COLOR,
    RTS_LIGHT_SHADOWS,
};
constexpr PropertyInfo kAreaLight[] = {
    {"position", "vector", "*required*", "The centre of the rectangle."},
    {"u", "vector", "*required*", "One edge of the rectangle."},
    {"v", "vector", "*required*", "The other edge."},
    {"samples", "whole number ≥ 1", "`16`", "Stratified points per shading point (soft shadows)."},
    {"disc", "bool", "`false`", "An ellipse inscribed in the rectangle instead."},
    {"point_at", "vector", "—", "Makes it a spot: the cone's axis from `position` goes through this point."},
    {"radius", "degrees in [0, 90]", "`30`", "With `point_at`: full intensity within this half-angle."},
    {"falloff", "degrees, radius to 90", "`45`", "With `point_at`: zero intensity from this half-angle."},
    RTS_LIGHT_COLOR,
    {"attenuation", "vector ≥ 0", "`<1, 0, 0>`", "<c, l, q>: the light is divided by c + l·d + q·d²."},
    RTS_LIGHT_SHADOWS,
    {"attenuation_clamp", "bool", "`false`", "Caps the attenuation factor at 1."},
};
#undef RTS_LIGHT_COLOR
#undef RTS_LIGHT_ATTENUATION
#undef RTS_LIGHT_SHADOWS

constexpr PropertyInfo kChecker[] = {
    {"color1", "color", "`rgb(1)`", "The color of even cells."},
    {"color2", "color", "`rgb(0)`", "The color of odd cells."},
    {"scale", "number > 0", "`1`", "The side of a cell."},
};
constexpr PropertyInfo kStripes[] = {
    {"color1", "color", "`rgb(1)`", "The first half of each period."},
    {"color2", "color", "`rgb(0)`", "The second half."},
    {"scale", "number > 0", "`1`", "The period."},
    {"axis", "\"x\", \"y\", \"z\" or 0, 1, 2", "`\"x\"`", "The axis the pattern varies along."},
};
constexpr PropertyInfo kImageTexture[] = {
    {"file", "string", "*required*", "An image file (PNG, BMP, JPEG, TGA or Radiance HDR)."},
    {"mapping", "string", "`\"uv\"`", "How points map to the image."},
    {"color_space", "string", "`\"srgb\"`", "\"srgb\" or \"linear\" (normal maps)."},
    {"filter", "string", "`\"bilinear\"`", "\"bilinear\" or \"nearest\"."},
};
constexpr PropertyInfo kLatLong[] = {
    {"file", "string", "*required*", "A latitude-longitude environment image."},
    {"color_space", "string", "`\"srgb\"`", "\"srgb\" or \"linear\"."},
    {"filter", "string", "`\"bilinear\"`", "\"bilinear\" or \"nearest\"."},
};
constexpr PropertyInfo kCubeMap[] = {
    {"directory", "string", "*required*", "A folder of six face images."},
    {"color_space", "string", "`\"srgb\"`", "\"srgb\" or \"linear\"."},
    {"filter", "string", "`\"bilinear\"`", "\"bilinear\" or \"nearest\"."},
    {"orientation", "string", "none", "How the six faces are read (\"mit\": MIT 6.837's layout)."},
};
constexpr PropertyInfo kSkySphere[] = {
    {"layers", "list of textures and colors", "*required*",
     "POV-Ray's sky_sphere pigments, bottom first: procedural textures evaluated on the view direction, each "
     "showing those below where its color map's transmit lets them through."},
};
constexpr PropertyInfo kCsg[] = {
    {"material", "material", "none", "The material of the parts that have none of their own."},
    {"inverse", "bool", "`false`", "Swap inside and outside."},
    {"casts_shadow", "bool", "`true`", "`false`: the block casts no shadow (POV-Ray's no_shadow)."},
};

constexpr PropertyInfo kGroup[] = {
    {"material", "material", "none", "The material of the members that have none of their own (POV-Ray's texture on a union)."},
    {"casts_shadow", "bool", "`true`", "`false`: no member casts a shadow (POV-Ray's no_shadow on a union)."},
};

constexpr PropertyInfo kText[] = {
    {"font", "string", "*required*", "A TrueType or OpenType font file: beside the scene file, else by name in the system's font folders and POV-Ray's library folder."},
    {"string", "string", "*required*", "The characters to write (UTF-8)."},
    {"thickness", "number > 0", "`1`", "How far the letters reach along z, from 0."},
    {"offset", "vector", "`<0, 0, 0>`", "Added to the position after each character, beside its advance width."},
    {"material", "material", "none", "Every letter's material."},
    {"casts_shadow", "bool", "`true`", "`false`: the letters cast no shadow (POV-Ray's no_shadow)."},
};

constexpr BlockInfo kBlocks[] = {
    {"settings", "Image size, samples, background, integrator and other render settings.", kSettings},
    {"camera", "Where the image is seen from.", kCamera},
    {"material", "How a surface reflects, transmits and emits light.", kMaterial},
    {"checker", "A 3D checker texture.", kChecker},
    {"stripes", "A texture of slabs across an axis.", kStripes},
    {"gradient", "A texture ramping from color1 to color2 along an axis.", kStripes},
    {"image_texture", "An image file as a texture.", kImageTexture},
    {"latlong_map", "A latitude-longitude environment map.", kLatLong},
    {"cube_map", "An environment map of six face images.", kCubeMap},
    {"sky_sphere", "A background of pattern layers on the direction (POV-Ray's sky_sphere).", kSkySphere},
    {"point_light", "Light from one point: hard shadows.", kPointLight},
    {"spot_light", "A point light limited to a cone.", kSpotLight},
    {"directional_light", "Parallel light (the sun): no position, no attenuation.", kDirectionalLight},
    {"area_light", "A rectangular (or disc) light: soft shadows.", kAreaLight},
    {"union", "CSG: the shapes together (inner surfaces kept).", kCsg},
    {"intersection", "CSG: what is inside every shape.", kCsg},
    {"difference", "CSG: the first shape minus the others.", kCsg},
    {"merge", "CSG: the shapes together, inner surfaces removed.", kCsg},
    {"clip", "The first shape's surface where it lies inside the others (POV-Ray's clipped_by).", kCsg},
    {"text", "Letters of a font, extruded along z (POV-Ray's text).", kText},
    {"group", "Objects placed together (any shapes, meshes, lights, CSG).", kGroup},
};

constexpr PropertyInfo kShapeMaterial{"material", "material", "none", "The shape's material."};
constexpr PropertyInfo kShapeCastsShadow{"casts_shadow", "bool", "`true`",
                                         "`false`: shadow rays pass the shape; the camera and reflections still see "
                                         "it (POV-Ray's no_shadow)."};

// Shapes: `material`, their descriptor's properties and `casts_shadow`, built once.
struct ShapeBlocks {
  std::array<std::vector<PropertyInfo>, kShapeKindCount> props;
  std::array<BlockInfo, kShapeKindCount> infos;
  ShapeBlocks() {
    for (std::size_t k = 0; k < kShapeKindCount; ++k) {
      props[k].push_back(kShapeMaterial);
      for (const PropertyInfo& p : kShapeInfos[k].properties) props[k].push_back(p);
      props[k].push_back(kShapeCastsShadow);
      infos[k] = BlockInfo{kShapeInfos[k].name, "A shape (docs/shapes.md).", props[k]};
    }
  }
};

}  // namespace

std::span<const BlockInfo> block_infos() { return kBlocks; }

const BlockInfo* find_block_info(std::string_view kind) {
  for (const BlockInfo& b : kBlocks)
    if (b.kind == kind) return &b;
  static const ShapeBlocks shapes;
  for (const BlockInfo& b : shapes.infos)
    if (b.kind == kind) return &b;
  return nullptr;
}

std::vector<std::string_view> property_names(std::span<const PropertyInfo> properties) {
  std::vector<std::string_view> names;
  names.reserve(properties.size());
  for (const PropertyInfo& p : properties) names.push_back(p.name);
  return names;
}

}  // namespace rts::render
