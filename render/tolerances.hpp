// Every numeric tolerance the renderer uses, in one place, with the reason for each value.
// Geometry is intersected in double precision; mesh vertices are stored as float but are
// converted exactly to double, so errors come from the arithmetic, not from storage.
#pragma once

namespace rts::render::tol {

// Spawned rays start a little off the surface (pbrt's "offset ray origin"): the offset scales
// with the magnitude of the hit point and the distance travelled, since the rounding error of
// p = o + t*d grows with both. The absolute floor covers hits at the origin.
inline constexpr double kRayOffsetRelative = 1e-9;
inline constexpr double kRayOffsetAbsolute = 1e-9;

// A ray parallel to a plane/disc/cap within this cosine is treated as missing it.
inline constexpr double kParallelCosine = 1e-14;

// Triangles whose determinant (in units of |e1 x e2| |d|) is below this are edge-on or
// degenerate (zero area): they are never hit, so they can never produce NaN normals.
inline constexpr double kTriangleDeterminant = 1e-14;

// Camera `up` counts as parallel to the view direction when |up x forward| is below this
// fraction of |up|: the image would have no defined "up".
inline constexpr double kParallelVectors = 1e-12;

// Building a perpendicular vector by crossing with a reference axis: the axis is used only
// when the vector's component along it is below this, so the cross product is well scaled.
inline constexpr double kReferenceAxisCosine = 0.9;

// An instance transform whose 3x3 determinant is below this (e.g. `scale 0`) cannot be
// inverted: flatten_scene reports it as a located RenderError (World also skips such an
// instance, as a last guard).
inline constexpr double kSingularDeterminant = 1e-300;

// Lengths below this are treated as zero (degenerate axes, zero radii, null vectors).
inline constexpr double kTinyLength = 1e-300;

// A shadow ray stops this far (relative to the light distance) before a point light, so the
// light's own position never counts as an occluder.
inline constexpr double kShadowEndRelative = 1e-9;

// Shadow rays pass through at most this many transmissive surfaces before giving up (and
// treating the light as blocked): bounds the cost of stacked glass.
inline constexpr int kMaxShadowSurfaces = 64;

// A path whose remaining weight is below this in every channel contributes nothing visible
// in an 8- or 16-bit image: recursion stops.
inline constexpr double kMinPathWeight = 1e-4;

// Group nesting deeper than this is treated as a cycle in the scene graph.
inline constexpr int kMaxGroupDepth = 1024;

// Bump maps take the slope of a procedural height texture by finite differences this far
// apart (in uv units, or scene units without uvs): small beside a texture's features, large
// beside double rounding. Image textures step one texel instead.
inline constexpr double kBumpDifference = 1e-4;

}  // namespace rts::render::tol
