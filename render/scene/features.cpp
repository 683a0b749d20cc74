#include "render/scene/features.hpp"

#include <array>

namespace rts::render {
namespace {

// The features after the shapes, in Feature's order.
constexpr std::string_view kOtherNames[] = {
    "reflection",  "transmission",
    "glossiness",  "fresnel",       "texture",           "image_texture", "emission",
    "specular",    "ambient",       "point_light",       "spot_light",  "directional_light",
    "area_light",  "shadows",       "transmissive_shadows", "area_sampling", "depth_of_field",
    "antialiasing", "aovs",         "bvh"};
static_assert(kShapeKindCount + std::size(kOtherNames) == kFeatureCount, "a name for every Feature");

// Shape features are named after their block kinds.
constexpr std::array<std::string_view, kFeatureCount> kNames = [] {
  std::array<std::string_view, kFeatureCount> names{};
  for (std::size_t i = 0; i < kShapeKindCount; ++i) names[i] = kShapeInfos[i].name;
  for (std::size_t i = 0; i < std::size(kOtherNames); ++i) names[kShapeKindCount + i] = kOtherNames[i];
  return names;
}();

bool nonzero(const Color& c) { return c.r != 0.0 || c.g != 0.0 || c.b != 0.0; }

const MaterialDesc* material_of(const SceneDesc& scene, const ShapeDesc& shape) {
  return shape.material < scene.materials.size() ? &scene.materials[shape.material] : nullptr;
}

}  // namespace

std::string_view feature_name(Feature f) { return kNames[static_cast<std::size_t>(f)]; }

std::vector<std::string_view> FeatureSet::used() const {
  std::vector<std::string_view> out;
  for (std::size_t i = 0; i < kFeatureCount; ++i)
    if (has(static_cast<Feature>(i))) out.push_back(kNames[i]);
  return out;
}

std::vector<std::string_view> FeatureSet::left_out() const {
  std::vector<std::string_view> out;
  for (std::size_t i = 0; i < kFeatureCount; ++i)
    if (!has(static_cast<Feature>(i))) out.push_back(kNames[i]);
  return out;
}

bool light_emits(const LightDesc& l) { return l.intensity != 0.0 && nonzero(l.color); }
bool reflects(const MaterialDesc& m) { return nonzero(m.reflect) || m.reflect_texture != kNoId; }
bool transmits(const MaterialDesc& m) {
  return m.transmit.r > 0.0 || m.transmit.g > 0.0 || m.transmit.b > 0.0 || m.transmit_texture != kNoId;
}

// Every texture a material may evaluate (its color and each channel, bump and normal maps).
template <class F>
void for_each_texture(const MaterialDesc& m, F&& f) {
  for (TextureId t : {m.texture, m.diffuse_texture, m.specular_texture, m.reflect_texture, m.transmit_texture,
                      m.emission_texture, m.bump, m.normal_map})
    if (t != kNoId) f(t);
}

// The mesh a shape traces, when it is one with per-vertex material values.
const MeshData* vertex_material_mesh(const SceneDesc& scene, const ShapeDesc& shape) {
  const MeshRef* r = std::get_if<MeshRef>(&shape.geometry);
  if (!r || r->mesh >= scene.meshes.size() || !scene.meshes[r->mesh]) return nullptr;
  const MeshData& mesh = *scene.meshes[r->mesh];
  return mesh.has_vertex_material() ? &mesh : nullptr;
}

FeatureSet analyze_features(const SceneDesc& scene, const FlatScene& flat, const FeatureContext& ctx) {
  FeatureSet f;
  // Ambient light reaches a surface only when both the material's and the scene's are on; the
  // default material (no material given) has the MaterialDesc defaults.
  const MaterialDesc default_material;
  bool ambient_light = nonzero(scene.settings.ambient_light);
  bool secondary_possible = ctx.max_depth > 0;
  for (const FlatShape& fs : flat.shapes) {
    const ShapeDesc& shape = scene.shapes[fs.shape];
    f.add(shape_feature(shape.geometry.index()));
    const MaterialDesc* mp = material_of(scene, shape);
    const MaterialDesc& m = mp ? *mp : default_material;
    bool r = reflects(m), t = transmits(m);
    if (r && secondary_possible) f.add(Feature::Reflection);
    if (t) {
      f.add(Feature::TransmissiveShadows);
      if (secondary_possible) f.add(Feature::Transmission);
    }
    if (r && m.roughness > 0.0 && secondary_possible) f.add(Feature::Glossiness);
    if ((r || t) && m.fresnel && secondary_possible) f.add(Feature::Fresnel);
    for_each_texture(m, [&](TextureId t) {
      if (t >= scene.textures.size()) return;
      f.add(Feature::Texture);
      if (scene.textures[t].kind == TextureKind::Image) f.add(Feature::ImageTexture);
    });
    if (nonzero(m.emission) || m.emission_texture != kNoId) f.add(Feature::Emission);
    const MeshData* vm = vertex_material_mesh(scene, shape);
    if (m.specular != 0.0 || m.specular_texture != kNoId || (vm && !vm->specular.empty())) f.add(Feature::Specular);
    if (m.ambient != 0.0 && ambient_light) f.add(Feature::Ambient);
  }
  for (const LightDesc& l : flat.lights) {
    if (!light_emits(l)) continue;  // sends nothing: costs nothing
    switch (l.kind) {
      case LightKind::Point: f.add(Feature::PointLight); break;
      case LightKind::Spot: f.add(Feature::SpotLight); break;
      case LightKind::Directional: f.add(Feature::DirectionalLight); break;
      case LightKind::Area: f.add(Feature::AreaLight); f.add(Feature::AreaSampling); break;
    }
    if (l.shadows) f.add(Feature::Shadows);
  }
  if (!f.has(Feature::Shadows)) f.bits &= ~(uint64_t{1} << static_cast<unsigned>(Feature::TransmissiveShadows));
  if (scene.has_camera && scene.camera.aperture > 0.0)
    f.add(Feature::DepthOfField);
  if (ctx.samples > 1) f.add(Feature::Antialiasing);
  if (ctx.aovs) f.add(Feature::Aovs);
  return f;
}

std::vector<bool> used_textures(const SceneDesc& scene, const FlatScene& flat) {
  std::vector<bool> used(scene.textures.size(), false);
  for (const FlatShape& fs : flat.shapes) {
    const MaterialDesc* m = material_of(scene, scene.shapes[fs.shape]);
    if (m) for_each_texture(*m, [&](TextureId t) { if (t < used.size()) used[t] = true; });
  }
  if (scene.settings.environment < used.size()) used[scene.settings.environment] = true;
  return used;
}

}  // namespace rts::render
