// The scene description: plain data that the runtime builds through SceneBuilder and the
// renderer compiles into acceleration structures. Knows nothing of syntax.
//
// Conventions (the same as POV-Ray, so the same scene looks the same in both):
//  - y is up; a camera at <0,0,-z> looking at the origin sees +x to its right
//    (right = normalize(cross(up, forward))): a left-handed view.
//  - rotate <a,b,c> rotates by a degrees about x, then b about y, then c about z
//    (glm::rotate's matrices; rotating <1,0,0> by 90 about y gives <0,0,-1>).
//  - Transforms compose in the order written: `s scale 2 translate <1,0,0>` scales first.
//    A Child's transform maps the child's space into its parent's space.
//  - Colors are linear RGB; the image writer encodes sRGB.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "render/scene/boxed.hpp"
#include "render/scene/child_runs.hpp"
#include "render/scene/child_transform.hpp"
#include "render/scene/chunked_vector.hpp"
#include "render/scene/pattern_desc.hpp"
#include "render/scene/sampler_kind.hpp"
#include "render/scene/source_ref.hpp"
#include "render/scene/stored_geometry.hpp"

namespace rts::render {

using Vec3 = glm::dvec3;
using Mat4 = glm::dmat4;

// The largest |component|: a vector's size without squaring it (no overflow past 1e154, no
// underflow below 1e-154). Here, beside Vec3, so every layer that sees the scene can use it.
inline double max_abs_component(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

struct Color {
  double r = 0, g = 0, b = 0;
  Color() = default;
  constexpr Color(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
  constexpr explicit Color(double gray) : r(gray), g(gray), b(gray) {}
  bool operator==(const Color&) const = default;
};

using TextureId = uint32_t;
using MaterialId = uint32_t;
using MediumId = uint32_t;
using NodeId = uint32_t;
using MeshId = uint32_t;
inline constexpr uint32_t kNoId = std::numeric_limits<uint32_t>::max();
static_assert(ColorMapEntry{}.texture == kNoId, "a plain color map entry holds no texture");

// ---- textures ---------------------------------------------------------------------------
// LatLong and CubeMap are environment maps: looked up by direction (the background, rays that
// leave the scene, image-based ambient light); on a surface they use the direction from the
// texture-space origin to the point.
// Pattern: a procedural pattern (marble, wood, ..., a user function) with a color map.
// SkySphere: POV-Ray's sky_sphere, only as the settings' environment: layers of procedural
// textures evaluated on the unit direction (after the sky's own transform), the last layer on
// top, each showing the ones below where its color map's `transmit` lets them through
// (render/shade/sky_sphere.hpp).
enum class TextureKind : uint8_t { Checker, Stripes, Gradient, Image, LatLong, CubeMap, Pattern, SkySphere };
enum class TextureFilter : uint8_t { Bilinear, Nearest };
struct TextureDesc {
  TextureKind kind = TextureKind::Checker;
  Color color1{1.0}, color2{0.0};
  double scale = 1.0;        // size of one checker cell / stripe period, in texture space
  int axis = 0;              // stripes/gradient: 0 = x, 1 = y, 2 = z
  std::string image_path;    // Image: already resolved against the scene file's directory
  // Image: how surface points map to image coordinates when the surface has no UVs:
  // "uv" (use surface UVs), "planar" (x,z → u,v), "spherical".
  std::string mapping = "uv";
  bool linear = false;       // images: the file holds linear values (not sRGB-encoded)
  TextureFilter filter = TextureFilter::Bilinear;
  // CubeMap: the faces' files in the order +x, -x, +y, -y, +z, -z, resolved like image_path.
  std::vector<std::string> face_paths;
  // CubeMap: the faces as MIT 6.837 a2's CubeMap reads them (the +x, -x and +z faces mirrored
  // left-right, +y top-bottom) instead of rts's upright, unmirrored faces.
  bool cube_mit = false;
  PatternDesc pattern;       // Pattern: which one, its turbulence, wave and color map
  // SkySphere: its layers, bottom first: a procedural texture each (kNoId: the solid
  // sky_layer_colors entry of the same index instead).
  std::vector<TextureId> sky_layers;
  std::vector<Color> sky_layer_colors;
  Mat4 transform{1.0};       // object space → texture space is inverse(transform)
  SourceRef loc;
};

// ---- materials --------------------------------------------------------------------------
// Phong: emission + ambient*color*ambient_light + sum over lights of
// diffuse*color*(n·l) + specular*specular_color*(r·v)^shininess, then reflect and transmit
// recursively.
struct MaterialDesc {
  Color color{0.8};
  TextureId texture = kNoId;   // when set, replaces `color`
  // A texture on a channel gives that channel's value at each point: emission, reflect and
  // transmit take its color; specular its color as the highlight's tint; on diffuse it is the diffuse color
  // itself (the diffuse term becomes texture * (N·L), the ambient term keeps `color`).
  TextureId diffuse_texture = kNoId;
  TextureId specular_texture = kNoId;
  TextureId reflect_texture = kNoId;
  TextureId transmit_texture = kNoId;
  TextureId emission_texture = kNoId;
  // Surface detail: a height texture (its luminance) perturbs the normal by `bump_scale` times
  // its slope; a normal map holds tangent-space normals as rgb = (n + 1) / 2.
  TextureId bump = kNoId;
  double bump_scale = 1.0;
  TextureId normal_map = kNoId;
  Color emission{0.0};
  double ambient = 0.1;
  Color ambient_color{1.0};    // `ambient = rgb(...)` weighs each channel (ambient 1, this colour)
  double diffuse = 0.7;
  double specular = 0.0;
  Color specular_color{1.0};   // tints the highlight (`specular = rgb(...)` sets it, specular = 1)
  double shininess = 32.0;
  // The highlight's lobe: Phong's (r · view)^shininess, or with `blinn` (POV-Ray's `specular`
  // + `roughness`) the half-vector's (n · h)^shininess, h = normalize(to_light + view).
  bool blinn = false;
  // POV-Ray's empirical finish terms, Whitted only: the diffuse term is (n · l)^brilliance, and
  // `metallic` tints the highlight towards the surface colour, less at grazing light
  // (render/shade/material.hpp).
  double brilliance = 1.0;
  double metallic = 0.0;
  // POV-Ray's reflection { metallic }, Whitted only: the reflection tinted by the surface
  // colour as `metallic` tints the highlight, by the viewing angle (render/shade/material.hpp).
  double reflect_metallic = 0.0;
  // POV-Ray's variable reflection, reflection { min, max }, Whitted only: with has_reflect_min
  // the reflection runs from reflect_min head-on to `reflect` at grazing angles, by Fresnel's
  // factor when `fresnel` is set, else by (1 - cos)^reflect_falloff (render/shade/material.hpp).
  bool has_reflect_min = false;
  Color reflect_min{0.0};
  double reflect_falloff = 1.0;
  Color reflect{0.0};          // mirror reflection weight per channel
  Color transmit{0.0};         // transmission weight per channel (also filters shadows)
  double ior = 1.0;            // absolute index of the inside (the medium stack pairs media)
  bool ior_relative = false;   // `ior` is the ratio to the surrounding medium instead
  bool fresnel = false;        // Schlick's approximation scales reflect/transmit
  double roughness = 0.0;      // > 0: glossy (blurred) reflection, sampled
  MediumId medium = kNoId;     // what fills the inside (render/shade/medium.hpp), or none
  // A material chosen by pattern (POV-Ray's texture { checker texture {A} texture {B} }): at
  // each point the pattern's luminance in [0, 1] picks one of `choice_count` materials stored
  // from `first_choice` on (equal ranges, the first for the darkest). Of its own values above
  // only `transmit` is set: the most any choice reached transmits (a transmit texture counts
  // as 1), so what asks whether a surface may let light through (World's transmissive
  // instances) reads it as for any material; shading always reads the choice.
  // choice_count 0: an ordinary material.
  // A choice may itself be chosen by pattern (POV-Ray's nested texture_map): `choice_depth`
  // levels in all (1 for a chooser of ordinary materials), `choice_leaves` the ordinary
  // materials reached, counted along every path; both bounded by the builder.
  // A layered material (POV-Ray's layered textures, `material { layers = [base, coat, ...] }`)
  // uses the same fields with `layered` set: its `choice_count` layers are stored from
  // `first_choice` on, the base first, each later one a coat over those before it. A coat's
  // transmit (its texture's colour map transmit at the point, plus its own `transmit`) is how
  // much of what lies below shows through it (render/shade/layers.hpp). Of its own values it
  // holds the base's `transmit` (shadows and World's transmissive instances read it).
  TextureId choice_pattern = kNoId;
  MaterialId first_choice = 0;
  uint32_t choice_count = 0;
  uint32_t choice_leaves = 0;
  uint8_t choice_depth = 0;
  bool layered = false;
  SourceRef loc;
};

// Bounds on materials chosen by pattern: how deep choices nest, and how many ordinary
// materials one reaches (what a scene-wide pass over its choices visits).
inline constexpr int kMaxChoiceDepth = 8;
inline constexpr uint32_t kMaxChoiceLeaves = 4096;

// Calls f(id, material) for what a surface with material `id` may show: the ordinary
// materials a material chosen by pattern or layered reaches through its choices and layers (at most
// kMaxChoiceLeaves calls, a material reached twice called twice), else `id` itself (ids past
// the list: the default material, not called).
template <class F>
void for_each_material_choice(const std::vector<MaterialDesc>& materials, MaterialId id, F&& f, int depth = 0) {
  if (id >= materials.size() || depth > kMaxChoiceDepth) return;
  const MaterialDesc& m = materials[id];
  if (m.choice_count == 0) {
    f(id, m);
    return;
  }
  for (uint32_t k = 0; k < m.choice_count; ++k) for_each_material_choice(materials, m.first_choice + k, f, depth + 1);
}

// Whether material `id`, or a choice or layer it reaches, is layered.
inline bool reaches_layers(const std::vector<MaterialDesc>& materials, MaterialId id, int depth = 0) {
  if (id >= materials.size() || depth > kMaxChoiceDepth) return false;
  const MaterialDesc& m = materials[id];
  if (m.layered) return true;
  for (uint32_t k = 0; k < m.choice_count; ++k)
    if (reaches_layers(materials, m.first_choice + k, depth + 1)) return true;
  return false;
}

// Does this material let light through at all (a zero weight is none; a transmit texture may)?
inline bool transmits(const MaterialDesc& m) {
  return m.transmit.r > 0.0 || m.transmit.g > 0.0 || m.transmit.b > 0.0 || m.transmit_texture != kNoId;
}

// A participating medium (POV-Ray's `media`): per unit length it absorbs `absorption`,
// scatters `scattering` (extinction = absorption + scattering) and gives off `emission`, each
// per channel and each times the density (1, or `density`'s value clamped to [0, 1] at each
// world point). Scattered light leaves by the Henyey-Greenstein phase function with mean cosine
// `eccentricity` (0: isotropic; > 0: forward). A material's medium fills its object's inside;
// settings' fills the space outside every object that has a medium or is glass.
struct MediumDesc {
  Color absorption{0.0};
  Color scattering{0.0};
  Color emission{0.0};
  double eccentricity = 0.0;
  TextureId density = kNoId;
  // POV-Ray's interior fade (an object's medium only; fade_distance 0: none): light that
  // crosses a distance d of the inside keeps fade_color + (1 - fade_color) / (1 + (d /
  // fade_distance)^fade_power) per channel, or, with fade_power >= 1000,
  // exp(-(1 - fade_color) d / fade_distance). Not multiplicative over pieces of a segment, so
  // it never combines with scattering or a density (the builder refuses both). POV-Ray's shadow
  // rays skip a fade of power 0 (measured); the Whitted integrator's do too, the path
  // tracer's take it as every other ray.
  double fade_distance = 0.0;
  double fade_power = 0.0;
  Color fade_color{0.0};
  SourceRef loc;
};

// ---- meshes -----------------------------------------------------------------------------
struct MeshData {
  // Relative to `origin` (the centre of the mesh's bounds): float storage then keeps 24 bits
  // of the mesh's own size wherever it sits, instead of losing a whole unit at 1e7.
  std::vector<glm::vec3> positions;
  Vec3 origin{0.0};
  std::vector<glm::vec3> normals;     // empty, or one per position (smooth shading)
  std::vector<glm::vec2> uvs;         // empty, or one per position
  std::vector<uint32_t> indices;      // 3 per triangle, into the arrays above
  // Per-vertex material values, each empty or one per position, interpolated across each
  // triangle with its barycentric coordinates; where present they replace the material's
  // color, diffuse, specular (the highlight's color: a number x is rgb(x)) and shininess.
  std::vector<glm::vec3> colors, specular;
  std::vector<float> diffuse, shininess;
  bool has_vertex_material() const {
    return !colors.empty() || !diffuse.empty() || !specular.empty() || !shininess.empty();
  }
  std::string source;                 // file it came from, or "" for inline meshes
};

// ---- shapes (each in its own object space) ------------------------------------------------
struct Sphere   { Vec3 center{0.0}; double radius = 1.0; };
struct Plane    { Vec3 normal{0, 1, 0}; double offset = 0.0; };          // dot(normal, p) = offset
// smooth_triangle's vertex normals, boxed: most triangles have none (72 bytes kept out of
// every shape's description).
struct TriangleNormals { Vec3 n0, n1, n2; };
struct Triangle { Vec3 v0, v1, v2; Boxed<TriangleNormals> normals; };
struct Box      { Vec3 min{-1.0}, max{1.0}; };
struct Cylinder { Vec3 from{0, 0, 0}, to{0, 1, 0}; double radius = 1.0; bool capped = true; };
struct Cone     { Vec3 from{0, 0, 0}, to{0, 1, 0}; double radius_from = 1.0, radius_to = 0.0; bool capped = true; };
struct Disc     { Vec3 center{0.0}, normal{0, 1, 0}; double radius = 1.0, inner_radius = 0.0; };
struct MeshRef  { MeshId mesh = kNoId; bool smooth = true; };
// A parallelogram corner + s*edge_u + t*edge_v, s,t in [0,1], with uv = (s, t): UW's `square`
// is the quad corner <-0.5,-0.5,0>, edges <1,0,0> and <0,1,0>.
struct Quad     { Vec3 corner{-0.5, -0.5, 0}, edge_u{1, 0, 0}, edge_v{0, 1, 0}; };
// In the x-z plane around y, centred at the origin (POV-Ray's torus): ring radius `major`,
// tube radius `minor`.
struct Torus    { double major = 1.0, minor = 0.25; };
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1, POV-Ray's superellipsoid { <e, n> }.
struct Superellipsoid { double e = 1.0, n = 1.0; };
// f(p) < threshold inside a box or sphere, POV-Ray's isosurface (render/geometry/shapes/isosurface.hpp).
struct IsoGradientMonitor;
struct IsosurfaceData {
  std::shared_ptr<const CompiledFunction> function;
  double threshold = 0.0, max_gradient = 1.1, accuracy = 0.001;
  int max_trace = 1;
  bool container_sphere = false;
  Vec3 box_min{-1.0}, box_max{1.0}, center{0.0};
  double radius = 1.0;
  std::shared_ptr<IsoGradientMonitor> monitor;  // the largest slope seen while tracing (shared by copies)
};

// The shape holds its data boxed (144 bytes; boxed.hpp says why); `->` reaches it.
struct Isosurface : BoxedShape<IsosurfaceData> {
  using BoxedShape::BoxedShape;
};

// POV-Ray's blob: components adding s (1 - d^2/r^2)^2 within r of a centre or of an axis
// segment (a cylinder with hemispherical ends); the solid is where the sum exceeds threshold.
struct BlobComponent { Vec3 a{0.0}, b{0.0}; double radius = 1.0, strength = 1.0; bool cylinder = false; };
inline constexpr std::size_t kMaxBlobComponents = 256;  // bounds the per-ray stack arrays
struct Blob { double threshold = 1.0; std::vector<BlobComponent> components; };

// POV-Ray's height_field: heights in [0, 1] sampled on an nx by nz grid over the unit square
// x, z in [0, 1] (render/geometry/shapes/height_field.hpp builds and traces it). Shared by
// every copy of the shape: a big grid is held once.
struct HeightFieldData {
  int nx = 0, nz = 0;                 // samples along x and z (at least 2 each)
  std::vector<float> height;          // nz rows of nx: height[iz * nx + ix] at x = ix / (nx - 1), z = iz / (nz - 1)
  int block = 8;                      // cells per block side (the traversal's coarse level)
  int blocks_x = 0, blocks_z = 0;
  std::vector<float> block_lo, block_hi;  // each block's height range (its cells' corners)
  std::vector<glm::vec3> normals;     // per sample, POV-Ray's averaged normals (smooth only)
  float min_height = 0.0f, max_height = 0.0f;
};
struct HeightField {
  std::shared_ptr<const HeightFieldData> data;
  bool smooth = false;
  double water_level = 0.0;           // below it nothing is drawn (the solid is filled up to it)
};

// POV-Ray's sor: about the y axis, radius^2 a cubic in the height on each segment between
// the profile's points 2 .. N-1 (render/geometry/shapes/sor.hpp fits and traces it).
struct SorSegment { double h0 = 0.0, h1 = 1.0; double c[4] = {0, 0, 0, 0}; double r2_max = 0.0; };  // r^2 = sum c_k (y - h0)^k
inline constexpr int kMaxSorPoints = 256;  // bounds the per-ray stack arrays
struct SorData {
  std::vector<Vec3> points;          // <r, h, 0> as given
  std::vector<SorSegment> segments;  // points.size() - 3 of them, bottom to top
  double radius = 0.0, h_min = 0.0, h_max = 0.0, base_r2 = 0.0, cap_r2 = 0.0;
  bool open = false;                 // no discs at the bottom and top
};
// Boxed (boxed.hpp): its 96 bytes made every shape's description 16 bytes larger.
struct Sor : BoxedShape<SorData> {
  using BoxedShape::BoxedShape;
};

// POV-Ray's splines through 2-D points (a lathe's profile, a prism's outline): linear_spline,
// quadratic_spline, cubic_spline, bezier_spline (render/geometry/shapes/spline_segments.hpp
// turns the points into segments with POV-Ray's conventions).
enum class SplineKind : uint8_t { Linear, Quadratic, Cubic, Bezier };
// One segment: x(t) = x[0] + x[1] t + x[2] t^2 + x[3] t^3 for t in [0, 1], y(t) likewise, and
// the bounds of the curve over [0, 1] (padded a little).
struct SplineSegment {
  double x[4], y[4];
  double x_lo, x_hi, y_lo, y_hi;
};

// POV-Ray's lathe: the profile's segments (straight, or spline pieces) turned about the y axis
// (render/geometry/shapes/lathe.hpp traces it).
inline constexpr int kMaxLathePoints = 4096;
struct LatheData {
  std::vector<Vec3> points;          // <r, h, 0> as given
  SplineKind spline = SplineKind::Linear;
  std::vector<SplineSegment> segments;  // the spline's pieces (r as x, h as y); empty for linear
  double radius = 0.0, h_min = 0.0, h_max = 0.0;
  bool closed = false;               // the profile ends where it starts, or both ends on the axis
  double orientation = 1.0;          // +1: the profile (closed along the axis) runs counter-clockwise
};
// Boxed, as Sor.
struct Lathe : BoxedShape<LatheData> {
  using BoxedShape::BoxedShape;
};

// POV-Ray's prism with linear_spline and linear_sweep: polygons in the x-z plane (several,
// even-odd) extruded along y (render/geometry/shapes/prism.hpp traces it).
inline constexpr int kMaxPrismPoints = 4096;
struct PrismEdge {
  double x0, z0, x1, z1;
  double outward;                    // +1 when (dz, -dx) points out of the polygon, else -1
};
struct PrismData {
  std::vector<Vec3> points;          // <x, z, 0> as given
  std::vector<PrismEdge> edges;      // the closed sub-polygons' edges (the last one closed if it was not)
  double height1 = 0.0, height2 = 1.0;
  double y_min = 0.0, y_max = 1.0, x_min = 0.0, x_max = 0.0, z_min = 0.0, z_max = 0.0;
  bool open = false;                 // no caps at the two heights
  SplineKind spline = SplineKind::Linear;
  std::vector<SplineSegment> curves;  // the outline's spline pieces (x, z as x, y); empty for linear
  std::vector<double> curve_outward;  // per curve: +1 when (dz, -dx) along it points out, else -1
  bool conic = false;                // conic_sweep: the outline scaled by y from the apex at the origin
};

// The shape holds its data boxed (176 bytes; boxed.hpp says why); `->` reaches it.
struct Prism : BoxedShape<PrismData> {
  using BoxedShape::BoxedShape;
};

// POV-Ray's poly (quartic, cubic): the surface sum c x^i y^j z^k = 0 over i + j + k <= order,
// the solid where the sum is negative. Only the terms with a non-zero coefficient are kept.
struct PolyTerm { double c = 0.0; uint8_t i = 0, j = 0, k = 0; };
struct Poly {
  int order = 4;
  std::vector<PolyTerm> terms;
};

using ShapeGeometry = std::variant<Sphere, Plane, Triangle, Box, Cylinder, Cone, Disc, MeshRef, Quad, Torus, Superellipsoid,
                                   Isosurface, Blob, HeightField, Sor, Lathe, Prism, Poly>;

// The description's own copy of the geometry (stored_geometry.hpp: the large kinds boxed).
using StoredGeometry = StoredGeometryOf<ShapeGeometry>;

// 64 bytes: 40 of geometry (a sphere's 32 and the kind), the flags beside the material in one
// word, and where it was written.
struct ShapeDesc {
  StoredGeometry geometry;
  MaterialId material = kNoId;   // kNoId: the default material (inside CSG: the block's)
  bool inverse = false;          // closed shapes in CSG: the solid is everything outside the surface
  // false: shadow rays pass it (POV-Ray's no_shadow); camera and bounced rays still see it.
  bool casts_shadow = true;
  SourceRef loc;
};
static_assert(sizeof(void*) != 8 || sizeof(ShapeDesc) <= 64, "a shape's description grew: box its bulk (stored_geometry.hpp)");

// ---- constructive solid geometry (POV-Ray's semantics) ------------------------------------
// union: every child's surface (inner ones too); merge: the union's outer surface only;
// intersection: where every child is; difference: the first child minus all the others;
// clip: the first child's surface where it lies inside all the others, whose own surfaces never
// show (POV-Ray's clipped_by: the result is open where it was cut; as a solid, the intersection).
enum class CsgOp : uint8_t { Union, Intersection, Difference, Merge, Clip };

// ---- lights (in their own space; placement transforms them) --------------------------------
enum class LightKind : uint8_t { Point, Spot, Directional, Area };
struct LightDesc {
  LightKind kind = LightKind::Point;
  Color color{1.0};
  double intensity = 1.0;
  Vec3 position{0, 10, 0};
  Vec3 direction{0, -1, 0};        // directional: the direction light travels
  Vec3 point_at{0, 0, 0};          // spot: where the spot points
  double radius = 30.0;            // spot: full-intensity half-angle, degrees
  double falloff = 45.0;           // spot: zero-intensity half-angle, degrees
  Vec3 attenuation{1, 0, 0};       // constant, linear, quadratic: I / (c + l d + q d^2)
  bool attenuation_clamp = false;  // the factor is min(1, 1 / (c + l d + q d^2)) (UW CSE 457)
  Vec3 u{1, 0, 0}, v{0, 0, 1};     // area: edge vectors (rectangle centred on position)
  bool disc = false;               // area: an ellipse inscribed in the u,v rectangle
  // area: limited to the spot cone of point_at, radius and falloff, its factor taken from the
  // centre (`position`) to the shading point for every sample: POV-Ray's spotlight with an
  // area_light (which attenuates once per light, from its centre).
  bool area_spot = false;
  int samples = 16;                // area: shadow samples per shading point
  // area: `samples` was not written. Then the light gets kAutoAreaSamplesPerPixel samples per
  // *pixel*, spread over the pixel samples (compile_lights), instead of 16 per shading point
  // times the pixel samples (a 16 spp still life cast 531M shadow rays that way).
  bool auto_samples = false;       // the scene builder sets it
  bool shadows = true;
  SourceRef loc;
};

// ---- camera and settings ----------------------------------------------------------------
// Perspective and orthographic, then POV-Ray's other camera types (render/sample/camera.cpp):
// each maps the image to directions (or origins) its own way from the camera's direction, right
// and up, with `fov` as POV-Ray's `angle`.
enum class Projection : uint8_t {
  Perspective, Orthographic, Fisheye, UltraWideAngle, Omnimax, Panoramic, Cylinder1, Cylinder2, Cylinder3,
  Cylinder4, Spherical
};
inline constexpr const char* kProjectionNames[] = {"perspective", "orthographic", "fisheye", "ultra_wide_angle",
                                                   "omnimax", "panoramic", "cylinder1", "cylinder2", "cylinder3",
                                                   "cylinder4", "spherical"};
inline const char* projection_name(Projection p) { return kProjectionNames[static_cast<int>(p)]; }
// POV-Ray's camera types beyond perspective and orthographic.
inline bool pov_projection(Projection p) { return p > Projection::Orthographic; }
struct CameraDesc {
  Projection projection = Projection::Perspective;
  Vec3 position{0, 0, -5};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov = 60.0;               // perspective: field of view, degrees, across fov_axis
  bool fov_vertical = false;       // fov spans the image's height instead of its width
  bool right_handed = false;       // right = cross(forward, up): +x to the left seen from -z
  double view_width = 4.0;         // orthographic: width of the view in scene units
  // POV-Ray's camera types (pov_projection): `fov` is POV-Ray's `angle` (the fisheye's circle,
  // the ultra wide angle's and cylinders' sweep, the spherical camera's horizontal sweep; up to
  // 360), and the spherical camera's vertical sweep is `vertical_fov` (up to 180).
  double vertical_fov = 180.0;
  double aperture = 0.0;           // > 0: depth of field (lens diameter)
  double focus_distance = 0.0;     // 0: distance to look_at
  // POV-Ray's camera: with `direction` given, the image plane is direction + x·right + y·up
  // (x, y from -1/2 to 1/2 across the image), the three vectors taken as given: not
  // orthogonalised, their lengths setting the field of view and the aspect ratio; look_at,
  // fov, fov_axis and handedness do not apply. Orthographic: right and up span the view.
  bool given_vectors = false;
  Vec3 direction{0, 0, 1};
  Vec3 right{4.0 / 3.0, 0, 0};
  SourceRef loc;
};

// Samples per pixel allowed (settings and --samples): 65536 on a 16x16 image is already
// minutes; beyond it a typo (an extra zero or three) would run for ever.
inline constexpr int kMaxSamplesPerPixel = 65536;
// Frames in one animation (settings.frames, --frames): a day of 24 fps video is 2,073,600.
inline constexpr int64_t kMaxFrames = 10'000'000;

// Which integrator renders the scene: Whitted ray tracing (the default) or the path tracer
// (render/shade/path/, docs/path-tracing.md).
enum class IntegratorKind : uint8_t { Whitted, Path };
inline const char* integrator_name(IntegratorKind k) { return k == IntegratorKind::Path ? "path" : "whitted"; }
// "whitted" or "path"; false for anything else.
inline bool parse_integrator(std::string_view name, IntegratorKind& out) {
  if (name == "whitted") out = IntegratorKind::Whitted;
  else if (name == "path") out = IntegratorKind::Path;
  else return false;
  return true;
}

struct Settings {
  int width = 640;
  int height = 480;
  int samples = 1;                 // samples per pixel (antialiasing), stratified
  int max_depth = 5;               // reflection/refraction recursion limit
  Color background{0.0};
  Color ambient_light{1.0};        // multiplies each material's ambient term
  // An environment map (LatLong or CubeMap texture): what rays that leave the scene see,
  // instead of `background`; with `environment_ambient`, also the ambient light, looked up
  // along each shading normal (times ambient_light).
  TextureId environment = kNoId;
  bool environment_ambient = false;
  // Fog (render/shade/fog.hpp): none while fog_distance is 0. fog_altitude > 0 makes it ground
  // fog, thick below fog_offset and thinning above it.
  double fog_distance = 0.0;
  Color fog_color{0.0};
  // POV-Ray's fog colour filter and transmit: light through the fog is tinted by fog_color by
  // fog_filter (it keeps (1 - filter) + filter * fog_color of itself), and the fog lets at
  // least fog_transmit of it through (Whitted; the path tracer reads the transmit alone).
  double fog_filter = 0.0;
  double fog_transmit = 0.0;
  double fog_offset = 0.0;
  double fog_altitude = 0.0;
  // Turbulent fog (POV-Ray's fog turbulence): non-zero in any component turns it on.
  Vec3 fog_turbulence{0.0};
  double fog_turb_depth = 0.5;
  int fog_octaves = 6;
  double fog_omega = 0.5, fog_lambda = 2.0;
  // The medium around the objects (settings' media_* properties), or none; media_samples is
  // the Whitted integrator's march: scattering points per ray segment in a medium.
  MediumId medium = kNoId;
  int media_samples = 16;
  uint64_t seed = 0;
  SamplerKind sampler = SamplerKind::Sobol;  // how pixel samples are placed
  // An animation's frame count: `rts render` without --frames renders frames 0..frames-1
  // (1: a still). The renderer itself draws one frame at a time.
  int64_t frames = 1;
  IntegratorKind integrator = IntegratorKind::Whitted;
  // settings { output_gamma = "linear" }: PNG output stores linear values (as --linear), the
  // way POV-Ray writes a scene without assumed_gamma 1.0. "srgb" (the default) encodes sRGB.
  bool output_linear = false;
  // settings { output_gamma = g } (a number): the image's values v are POV-Ray's with
  // assumed_gamma g, values in a space of gamma g: written as v^g, then encoded (sRGB for PNG).
  // 1: as rendered.
  double output_power = 1.0;
  // Which extra images `rts render` writes unless its command line says otherwise (--aov,
  // --depth-range, --depth-miss, --normal-miss): a course scene's images from a plain render.
  std::vector<std::string> aovs;   // "normal", "depth", "albedo", "error"
  bool has_depth_range = false;
  double depth_near = 0.0, depth_far = 1.0;
  double depth_miss = 0.0, normal_miss = 0.0;
  // Path mode: the most any one camera sample may add to a pixel (its largest channel; the
  // colour is kept). 0, the default, clamps nothing and keeps the path tracer unbiased; a
  // clamp trades bias (lost energy from bright, rare paths) for less noise. Whitted ignores it.
  double clamp = 0.0;
  // Path mode: point, spot and area lights fall off by their `attenuation` (Whitted's and
  // POV-Ray's lights: by default not at all) instead of 1/d². Not physical; for imported
  // POV-Ray scenes (`light_falloff = "attenuation"`). Whitted ignores it.
  bool light_falloff_attenuation = false;
  SourceRef loc;
};

// ---- the graph ----------------------------------------------------------------------------
enum class NodeKind : uint8_t { Shape, Light, Group, Csg };  // Csg: SceneDesc::csgs
// Where the item was written is kept by the item itself (node_loc()): a node is 8 bytes, not
// 24, and a million spheres placed by a loop do not carry their location twice.
struct Node {
  NodeKind kind = NodeKind::Shape;
  uint32_t index = 0;              // into shapes, lights, groups or csgs
};

inline Mat4 operator*(const Mat4& a, const ChildTransform& b) { return a * b.matrix(); }
inline glm::dvec4 operator*(const ChildTransform& a, const glm::dvec4& v) { return a.matrix() * v; }

struct Child {
  NodeId node = kNoId;
  ChildTransform transform;        // child space → parent space
  SourceRef loc;                   // where this instance was placed
};
static_assert(sizeof(void*) != 8 || sizeof(Child) <= 32, "a child grew: one per placed object");

struct GroupDesc {
  std::vector<Child> children;
  // The members' default (`group { ... material = m }`, POV-Ray's texture on a union): a
  // member without a material of its own shows it; kNoId: none, the enclosing one's.
  MaterialId material = kNoId;
  bool casts_shadow = true;        // false: none of its members casts a shadow
  SourceRef loc{};                 // where the group was written (node_loc)
};

struct CsgDesc {
  CsgOp op = CsgOp::Union;
  std::vector<Child> children;     // shape, CSG or group nodes (a group is a union)
  MaterialId material = kNoId;     // the children's default
  bool inverse = false;            // the solid is everything outside the result
  bool casts_shadow = true;        // false: shadow rays pass the whole block
  SourceRef loc{};                 // where the block was written (node_loc)
};

struct SceneDesc {
  Settings settings;
  CameraDesc camera;
  bool has_camera = false;

  std::vector<TextureDesc> textures;
  std::vector<MaterialDesc> materials;
  std::vector<MediumDesc> media;
  std::vector<std::shared_ptr<const MeshData>> meshes;
  // The arrays with one entry per placed object grow by chunks (chunked_vector.hpp): a
  // vector's doubling held two copies of the largest array at the end of evaluation (4M
  // spheres: the roots' 40 bytes each copied into a block twice the size as the last one was
  // placed, 170 MB more at the peak). Nothing needs them contiguous.
  ChunkedVector<ShapeDesc> shapes;
  std::vector<LightDesc> lights;
  std::vector<GroupDesc> groups;
  std::vector<CsgDesc> csgs;
  ChunkedVector<Node> nodes;
  ChildRuns<Child> roots;          // instances placed in the world (by runs: child_runs.hpp)
  std::vector<Warning> warnings;   // from building: what is skipped (not part of dump())

  // A deterministic, human-readable dump (`rts eval`); golden tests compare it.
  void dump(std::ostream& out) const;
};

// Where node's item (shape, light, group or CSG block) was written; empty for an index out of
// range (an internal error, reported at the placement instead).
inline SourceRef node_loc(const SceneDesc& scene, const Node& node) {
  switch (node.kind) {
    case NodeKind::Shape: return node.index < scene.shapes.size() ? scene.shapes[node.index].loc : SourceRef{};
    case NodeKind::Light: return node.index < scene.lights.size() ? scene.lights[node.index].loc : SourceRef{};
    case NodeKind::Group: return node.index < scene.groups.size() ? scene.groups[node.index].loc : SourceRef{};
    case NodeKind::Csg: return node.index < scene.csgs.size() ? scene.csgs[node.index].loc : SourceRef{};
  }
  return {};
}

}  // namespace rts::render
