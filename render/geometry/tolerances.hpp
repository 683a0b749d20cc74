// Every numeric tolerance the renderer uses, in one place, with the reason for each value.
// Geometry is intersected in double precision; mesh vertices are stored as float relative to
// the mesh's own centre (MeshData::origin, a double), so storage error is relative to the
// mesh's size, not to its distance from the world origin.
#pragma once

namespace rts::render::tol {

// Spawned rays start off the surface by the hit point's own rounding error bound (see
// offset_ray_origin in render/geometry/ray.hpp), times this safety factor: the bound covers the hit
// point, the factor covers the rounding of the next intersection test from the new origin
// (pbrt-v4 instead re-checks t against a bound in each test). 16 keeps offsets ~1e-14
// relative, invisible at any scale, and the stability suite finds no acne with it.
inline constexpr double kOffsetErrorScale = 16.0;
// Rounded operations counted for p = o + t d including t's own computation.
inline constexpr int kRayPointOps = 8;
// A hit computed exactly (error bound 0, e.g. at the origin) still moves off by this, the
// smallest normal double: a ray starting exactly on a surface could hit it at t = 0+.
inline constexpr double kMinRayOffset = 2.2250738585072014e-308;

// Isosurface normals are central differences of f over this fraction of the container's
// size: far above the doubles' rounding of f (1e-16 relative, so the difference keeps ~10
// digits) and far below any detail a function resolves at a render's scale.
inline constexpr double kIsoNormalStep = 1e-6;

// A blob's quartic along a ray loses its leading terms when they vanish against the others
// by this much (a ray along a cylinder component's axis: the body's distance is then constant):
// the degree drops so poly_roots never divides by a rounding residue.
inline constexpr double kBlobLeadingCoefficient = 1e-14;

// A height field skips a block or cell when the ray's height over it misses the block's height
// range by more than this (relative to the heights compared): a root on the block's edge, where
// the ray's height is rounded, is never skipped.
inline constexpr double kHeightFieldCellMargin = 1e-9;

// A height-field root is the quotient of plane equations whose terms are of the grid's size in
// cells: its point carries this relative rounding per cell of the grid (generous: 64 ulp).
inline constexpr double kHeightFieldRootRelative = 1.4e-14;

// Two prism points are the same (one closes its sub-polygon) when both coordinates differ by
// less than this: POV-Ray's EPSILON for the same test, so its point lists split alike.
inline constexpr double kPrismSamePoint = 1e-10;

// A spline segment's bounds (lathe, prism) are its ends and turning points, the turning points
// rounded: they are padded by this much of the segment's coefficients' size, far above that
// rounding (~1e-16) and far below anything visible.
inline constexpr double kSplineBoundPad = 1e-9;

// A lathe spline segment against a ray whose direction's y (unit length) is below this is
// solved as a horizontal ray first (the heights where h(t) meets the ray, then the circle
// there) and polished onto the true ray: the general sextic divides the ray's horizontal reach
// by its climb, so its coefficients lose ~(1/dy)^2 of their digits, ~1e-8 of 1e-16 here.
inline constexpr double kLatheFlatRay = 1e-4;

// A lathe spline crossing is first looked for this far beyond the segment's [0, 1] (in t), and
// kept only once polished onto the ray inside [0, 1): a horizontal ray's first guess at a
// crossing near a joint may fall just outside its own segment.
inline constexpr double kLatheSplineSearchPad = 0.05;

// Lengths (edges, radii, a transform's entries) between these are used as given; outside,
// the tests whose terms reach the third or fourth power of a length (a triangle's depth and
// degeneracy test, a quad's dual basis, a torus's quartic, a transform's cofactors and
// determinant) first rescale them by an exact power of two, since those powers leave doubles'
// normal range past about 1e77 (or 1e-77). Inside, nothing is rescaled and every result keeps
// its bits; the fourth power of either bound (1e120) is far inside doubles' range.
inline constexpr double kUnscaledLengthMin = 1e-30;
inline constexpr double kUnscaledLengthMax = 1e30;

// A ray parallel to a plane/disc/cap within this cosine is treated as missing it.
inline constexpr double kParallelCosine = 1e-14;

// Triangles whose determinant (in units of |e1 x e2| |d|) is below this are edge-on or
// degenerate (zero area): they are never hit, so they can never produce NaN normals.
inline constexpr double kTriangleDeterminant = 1e-14;

// Two hits whose t differ by less than this (relative to t and to the ray origin's distance
// from the world origin, over |d|) are treated as coincident surfaces: the lower instance
// index wins (World::intersect), and CSG crossings that close are one batch. Rounding of t is
// a few units of 1e-16 of those scales: measured on one plane's faces made five ways (plane,
// turned box, disc, triangle, CSG face, all under a rotation and its inverse) and seen from 45
// down to 0.01 degrees, 1e-16 speckles and 1e-15 does not (tests/stability/test_coincident.cpp);
// 1e-14 keeps a tenfold margin. Smaller is better far from the origin: the tie is this times
// the origin's distance, so at 1e-12 (until 2026-12-01) a unit scene 1e11 away merged surfaces
// 0.1 apart (a die's pips and a bowl's hollow vanished); at 1e-14 it is 1e-3 there, ten times
// the coordinates' own rounding.
inline constexpr double kCoincidentRelative = 1e-14;

// A CSG leaf whose box the ray meets only farther than this many coincidence ties
// (kCoincidentRelative, as World::intersect_csg scales it) outside the span where its state
// can matter is left out (render/geometry/csg/csg_prune.hpp): a crossing that far away can
// never share a batch of the sweep with a kept one unless several leaves chain crossings
// closer than a tie across the gap, and the box's own rounding is ~1e-2 of a tie.
inline constexpr double kCsgPruneTies = 4.0;

// A closed mesh in CSG lists at most kMaxLeafCrossings crossings per sweep; a ray whose first
// surface lies beyond them sweeps again from there (World::trace_csg). This many sweeps, about
// 4000 crossings of one mesh along one ray, bound the work a pathological mesh can ask of one
// ray; beyond them the ray is taken to see no surface of the block.
inline constexpr int kCsgMaxPasses = 1024;

// Camera `up` counts as parallel to the view direction when |up x forward| is below this
// fraction of |up|: the image would have no defined "up".
inline constexpr double kParallelVectors = 1e-12;

// Building a perpendicular vector by crossing with a reference axis: the axis is used only
// when the vector's component along it is below this, so the cross product is well scaled.
inline constexpr double kReferenceAxisCosine = 0.9;

// An instance transform whose 3x3 determinant, taken with its entries scaled near 1
// (render/geometry/transform_inverse.hpp), is below this (e.g. `scale 0`) cannot be
// inverted: flatten_scene reports it as a located RenderError (World also skips such an
// instance, as a last guard).
inline constexpr double kSingularDeterminant = 1e-300;

// Lengths below this are treated as zero (degenerate axes, zero radii, null vectors).
inline constexpr double kTinyLength = 1e-300;

// A poly's polynomial along a ray (render/geometry/shapes/poly.hpp) has its roots isolated
// inside Cauchy's bound. A leading coefficient that is tiny but not zero (often rounding noise
// of top-degree terms that cancel along the ray) is kept: its far roots are then far away, and
// the crossings stay consistent with the polynomial's sign, as CSG's parity needs (dropping
// it made a lower-degree polynomial with roots of its own). Only a bound beyond this, where the
// isolation's powers of the bound would overflow, drops the leading term.
inline constexpr double kPolyFarthestRoot = 1e250;

// A shadow ray stops this far (relative to the light distance) before a point light, so the
// light's own position never counts as an occluder. Towards an emitter's surface (the path
// tracer) it is measured from the ray's offset origin and less the rounding of the emitter's
// own hit, kOffsetErrorScale point bounds (path_integrator.cpp, shadow_end).
inline constexpr double kShadowEndRelative = 1e-9;

// The box around every shadow segment from one shading point to an area light (World::
// occluder_candidates) grows by this much relative to its largest coordinate (plus the
// origin's offset): the segments' end points are rounded sums of the light's corners and
// the ray direction, ~1e-16 relative away from the exact hull. Too large only costs a
// candidate more; too small could drop an occluder.
inline constexpr double kShadowHullPadRelative = 1e-9;

// Shadow rays pass through at most this many transmissive surfaces before giving up (and
// treating the light as blocked): bounds the cost of stacked glass.
inline constexpr int kMaxShadowSurfaces = 64;

// A path whose remaining weight is below this in every channel contributes nothing visible
// in an 8- or 16-bit image: recursion stops.
inline constexpr double kMinPathWeight = 1e-4;

// max_depth above this is capped (with a located warning): the bounce loop is iterative, so
// depth costs only time, and between two perfect mirrors every extra level is one more ray
// per pixel. 10,000 bounces are a few seconds for a small image; 1e9 would never finish.
inline constexpr int kMaxDepth = 10000;

// Transmissive objects a path can be inside at once (the medium stack of nested dielectrics).
// Deeper nesting keeps refracting with the innermost tracked media.
inline constexpr int kMaxNestedMedia = 8;

// Radiance, light power and path weights saturate here: far below double's overflow, so sums
// over lights, samples and bounces stay finite, and below float's 3.4e38 so the stored image
// holds it. A light of intensity 1e300 then renders as the brightest possible light, not as
// infinity times zero (NaN, black).
inline constexpr double kMaxRadiance = 1e30;

// Group nesting deeper than this is treated as a cycle in the scene graph.
inline constexpr int kMaxGroupDepth = 1024;

// Bump maps take the slope of a procedural height texture by finite differences this far
// apart (in uv units, or scene units without uvs): small beside a texture's features, large
// beside double rounding. Image textures step one texel instead.
inline constexpr double kBumpDifference = 1e-4;

// Path tracing: a cosine between a direction and a shading normal below this counts as
// grazing (the BSDF falls back to the geometric normal, densities stay finite): 1e-7 is a
// tenth of a micro-radian from the tangent plane, far below what a pixel resolves.
inline constexpr double kGrazingCosine = 1e-7;

// Path tracing: GGX roughness below this is sampled as this (alpha 1e-4 is a mirror to any
// image; smaller ones make D overflow at the peak).
inline constexpr double kMinMicrofacetAlpha = 1e-4;

// Path tracing: an emitter whose area (or solid angle) is below this is not sampled by next-
// event estimation (its density, pick / area with pick <= 1, would overflow); rays that hit
// it still see its emission. A lamp of a scene modelled at 1e-150 units has an area near
// 1e-300, and is sampled.
inline constexpr double kMinEmitterArea = 1e-306;

// Path tracing: a point closer to an emissive sphere's centre than (1 + this) times its
// radius samples the sphere by area, not by the cone it subtends: a point on the sphere
// itself (a shading point of the light, or inside it) sees no cone, and rounding may put it
// just outside.
inline constexpr double kSphereConeMargin = 1e-6;

// Path tracing: a rectangular quad light whose solid angle from the shading point is below
// this (steradians) is sampled by area instead: the solid angle is a sum of four angles less
// 2 pi, which loses relative precision as it shrinks (about 1e-15 * 2 pi absolute, so 1e-8
// relative here), and so far away 1/r^2 barely varies over the light, area sampling is as good.
inline constexpr double kMinSphericalRectAngle = 1e-6;

// Path tracing: quad edges count as orthogonal (a rectangle, sampled by solid angle) when
// |cos| of the angle between them is below this; a skewed parallelogram is sampled by area.
inline constexpr double kRectangleCosine = 1e-9;

// Ground fog: a ray whose direction's height component (unit direction) is below this is
// treated as level, its optical depth the density at its height times its length. The closed
// form divides a difference of heights by it, which for steeper rays loses at most ~1e-16 / 1e-9
// of its value to rounding.
inline constexpr double kFogLevelRay = 1e-9;

// Media: tentative collisions one free-flight walk through a heterogeneous medium may take
// (about majorant x length of them are expected). A ray that would take more, through a thick
// medium's empty regions or to infinity through a patterned atmosphere, ends there (its light
// is lost: biased, and only beyond what any scene resolves).
inline constexpr int kMaxMediumCollisions = 100000;

// Media: surfaces that only let light through (pass-through containers of media) one ray may
// cross before it is ended, like kMaxShadowSurfaces for glass on shadow rays.
inline constexpr int kMaxPassThrough = 64;

// Media in the Whitted integrator: an infinite ray segment through a heterogeneous medium is
// marched over the length whose optical depth at the majorant is this (e^-20 ~ 2e-9 of the
// light would be left at density 1); beyond it the medium is taken as empty.
inline constexpr double kMediaMarchDepth = 20.0;

}  // namespace rts::render::tol
