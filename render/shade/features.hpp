// What a placed scene actually uses, found after evaluation (flattening) and before tracing:
// primitive kinds, material channels, light kinds, shadows, area-light sampling, depth of
// field, antialiasing and AOVs. A channel at zero strength (reflect = 0, an area light of
// intensity 0...) counts as unused. The renderer picks the path specialised to this set, and
// `--stats` reports it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/accel/flatten.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

enum class Feature : uint8_t {
  // primitive kinds, in ShapeGeometry's order (a shape's feature is its variant index; its
  // name is its block kind's): checked below
  Sphere, Plane, Triangle, Box, Cylinder, Cone, Disc, Mesh, Quad, Torus, Superellipsoid, Isosurface, Blob, HeightField, Sor, Lathe, Prism,
  Poly,
  // material channels
  Reflection, Transmission, Glossiness, Fresnel, Texture, ImageTexture, Pattern, Emission, Specular, Ambient,
  // lights
  PointLight, SpotLight, DirectionalLight, AreaLight, Shadows, TransmissiveShadows, AreaSampling,
  // camera and image
  DepthOfField, Antialiasing, Aovs,
  // constructive solid geometry (any union, intersection, difference or merge block)
  Csg,
  // acceleration
  Bvh,
  Instancing,  // groups placed several times share one BVH (render/accel/flatten.hpp)
  // atmosphere
  Fog,
  SkySphere,   // the environment is a sky_sphere (layered patterns on the direction)
  Media,       // a participating medium: in a transmissive material, or around the objects
  Count
};

inline constexpr std::size_t kFeatureCount = static_cast<std::size_t>(Feature::Count);

// The feature of shape kind `kind` (a ShapeGeometry index).
constexpr Feature shape_feature(std::size_t kind) { return static_cast<Feature>(kind); }
static_assert(static_cast<std::size_t>(Feature::Reflection) == kShapeKindCount,
              "one shape Feature per ShapeGeometry alternative");
static_assert(Feature::Sphere == shape_feature(shape_index<Sphere>()) &&
                  Feature::Plane == shape_feature(shape_index<Plane>()) &&
                  Feature::Triangle == shape_feature(shape_index<Triangle>()) &&
                  Feature::Box == shape_feature(shape_index<Box>()) &&
                  Feature::Cylinder == shape_feature(shape_index<Cylinder>()) &&
                  Feature::Cone == shape_feature(shape_index<Cone>()) &&
                  Feature::Disc == shape_feature(shape_index<Disc>()) &&
                  Feature::Mesh == shape_feature(shape_index<MeshRef>()) &&
                  Feature::Quad == shape_feature(shape_index<Quad>()) &&
                  Feature::Torus == shape_feature(shape_index<Torus>()) &&
                  Feature::Superellipsoid == shape_feature(shape_index<Superellipsoid>()) &&
                  Feature::Isosurface == shape_feature(shape_index<Isosurface>()) &&
                  Feature::Blob == shape_feature(shape_index<Blob>()) &&
                  Feature::HeightField == shape_feature(shape_index<HeightField>()) &&
                  Feature::Sor == shape_feature(shape_index<Sor>()) &&
                  Feature::Lathe == shape_feature(shape_index<Lathe>()) &&
                  Feature::Prism == shape_feature(shape_index<Prism>()) &&
                  Feature::Poly == shape_feature(shape_index<Poly>()),
              "the shape Features follow ShapeGeometry's order");

// "sphere", "reflection", "area_light"... (the names --stats and the JSON report use).
std::string_view feature_name(Feature f);

struct FeatureSet {
  uint64_t bits = 0;
  bool has(Feature f) const { return bits >> static_cast<unsigned>(f) & 1u; }
  void add(Feature f) { bits |= uint64_t{1} << static_cast<unsigned>(f); }
  void remove(Feature f) { bits &= ~(uint64_t{1} << static_cast<unsigned>(f)); }
  std::vector<std::string_view> used() const;
  std::vector<std::string_view> left_out() const;
};

// The Whitted integrator's template flags (render/shade/integrator.*): each compiled path is
// specialised to one combination, so an unused feature costs neither a branch nor a loop per
// ray. Features set them through the table in features.cpp (FeatureRule::trace_flags).
// kGeneric (--no-specialize) is everything on, every light kept, and shadow rays through glass
// re-walking the scene with closest-hit steps.
namespace trace_flags {
inline constexpr unsigned kSecondary = 1;            // reflection or transmission rays
inline constexpr unsigned kTexture = 2;              // texture lookups (else constant colors)
inline constexpr unsigned kSpecular = 4;             // Phong highlights
inline constexpr unsigned kRandom = 8;               // area-light sampling loops, glossy rays
inline constexpr unsigned kTransmissiveShadows = 16; // shadow rays multiply through glass
inline constexpr unsigned kAll = 31;
inline constexpr unsigned kGeneric = 32;             // --no-specialize
// Every flag doubles the compiled variants (32 now, each a copy of the whole shading path): a
// new feature sets an existing flag, or none, unless a profile shows its own flag pays.
static_assert(kAll == 31, "a sixth template flag doubles the integrator's 32 variants: see above");
// The flags of the features in `features` (the OR of their table rows' flags).
unsigned for_features(const FeatureSet& features);
}  // namespace trace_flags

// What the renderer is told beyond the scene.
struct FeatureContext {
  int samples = 1;           // per pixel, after command-line overrides
  int max_depth = 5;
  bool aovs = false;
};

// Does this light send any light (color * intensity not zero)?
bool light_emits(const LightDesc& light);
// Does this material reflect / transmit at all (a zero weight is no reflection)?
bool reflects(const MaterialDesc& m);
// transmits(MaterialDesc) is render/scene/scene.hpp's.

// The features the placed scene uses. `bvh` is decided by the World (see World::uses_bvh) and
// added by the caller.
FeatureSet analyze_features(const SceneDesc& scene, const FlatScene& flat, const FeatureContext& ctx);
// The same in two steps, so that a prepared scene reads its shapes once and may then release
// them: what the placed shapes use (their kinds, the Shape rules on their materials, CSG),
// which depends on the render only through whether secondary rays are possible (max_depth > 0:
// index 1, else 0); then that with the lights' and the scene's rules for a render's context.
std::array<FeatureSet, 2> shape_features(const SceneDesc& scene, const FlatScene& flat);
FeatureSet analyze_features(const SceneDesc& scene, const FeatureSet& shapes, const std::vector<LightDesc>& lights,
                            const FeatureContext& ctx);

// Which textures placed materials refer to (by TextureId): the others are never loaded.
std::vector<bool> used_textures(const SceneDesc& scene, const FlatScene& flat);

}  // namespace rts::render
