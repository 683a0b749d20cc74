#include "render/shade/features.hpp"

#include <array>
#include <iterator>
#include <optional>
#include <variant>

#include "render/scene/csg_leaves.hpp"

namespace rts::render {
namespace {

bool nonzero(const Color& c) { return c.r != 0.0 || c.g != 0.0 || c.b != 0.0; }


}  // namespace

bool light_emits(const LightDesc& l) { return l.intensity != 0.0 && nonzero(l.color); }
bool reflects(const MaterialDesc& m) { return nonzero(m.reflect) || m.reflect_texture != kNoId; }

// Every texture a material may evaluate (its color and each channel, bump and normal maps).
template <class F>
void for_each_texture(const MaterialDesc& m, F&& f) {
  for (TextureId t : {m.texture, m.diffuse_texture, m.specular_texture, m.reflect_texture, m.transmit_texture,
                      m.emission_texture, m.bump, m.normal_map, m.choice_pattern})
    if (t != kNoId) f(t);
}

// The mesh a shape traces, when it is one with per-vertex material values.
const MeshData* vertex_material_mesh(const SceneDesc& scene, const ShapeDesc& shape) {
  const MeshRef* r = shape_if<MeshRef>(shape.geometry);
  if (!r || r->mesh >= scene.meshes.size() || !scene.meshes[r->mesh]) return nullptr;
  const MeshData& mesh = *scene.meshes[r->mesh];
  return mesh.has_vertex_material() ? &mesh : nullptr;
}

namespace {

// What a rule looks at: the placed shape with its material (Shape rules), a placed light that
// sends light (Light rules), or only the scene and context (Scene rules).
struct FeatureProbe {
  const SceneDesc& scene;
  const FeatureContext& ctx;
  const ShapeDesc* shape = nullptr;
  const MaterialDesc* material = nullptr;  // the shape's, or the defaults
  const LightDesc* light = nullptr;
  bool secondary_possible() const { return ctx.max_depth > 0; }
};

enum class Scope : uint8_t { Shape, Light, Scene };

// One row per feature after the shapes (whose rows are derived from the shape kinds): its
// name, where it is looked for and the rule that finds it, the integrator flags it turns on,
// and a feature it is void without.
struct FeatureRule {
  Feature feature;
  std::string_view name;
  Scope scope;
  bool (*used)(const FeatureProbe&);
  unsigned trace_flags = 0;
  Feature only_with = Feature::Count;  // Count: none
};

bool any_texture(const FeatureProbe& p, bool image_only) {
  bool found = false;
  for_each_texture(*p.material, [&](TextureId t) {
    if (t < p.scene.textures.size() && (!image_only || p.scene.textures[t].kind == TextureKind::Image)) found = true;
  });
  return found;
}

bool any_pattern(const FeatureProbe& p) {
  bool found = false;
  for_each_texture(*p.material, [&](TextureId t) {
    if (t < p.scene.textures.size() && p.scene.textures[t].kind == TextureKind::Pattern) found = true;
  });
  return found;
}

// The leave-out table (docs/leave-out.md describes each row). A channel at zero strength is
// unused; a light that sends nothing is not looked at.
constexpr FeatureRule kRules[] = {
    {Feature::Reflection, "reflection", Scope::Shape,
     [](const FeatureProbe& p) { return reflects(*p.material) && p.secondary_possible(); }, trace_flags::kSecondary},
    {Feature::Transmission, "transmission", Scope::Shape,
     [](const FeatureProbe& p) { return transmits(*p.material) && p.secondary_possible(); }, trace_flags::kSecondary},
    {Feature::Glossiness, "glossiness", Scope::Shape,
     [](const FeatureProbe& p) {
       return reflects(*p.material) && p.material->roughness > 0.0 && p.secondary_possible();
     },
     trace_flags::kRandom},
    {Feature::Fresnel, "fresnel", Scope::Shape,
     [](const FeatureProbe& p) {
       return (reflects(*p.material) || transmits(*p.material)) && p.material->fresnel && p.secondary_possible();
     }},
    {Feature::Texture, "texture", Scope::Shape, [](const FeatureProbe& p) { return any_texture(p, false); },
     trace_flags::kTexture},
    {Feature::ImageTexture, "image_texture", Scope::Shape, [](const FeatureProbe& p) { return any_texture(p, true); }},
    {Feature::Pattern, "pattern", Scope::Shape, [](const FeatureProbe& p) { return any_pattern(p); }},
    {Feature::Emission, "emission", Scope::Shape,
     [](const FeatureProbe& p) { return nonzero(p.material->emission) || p.material->emission_texture != kNoId; }},
    {Feature::Specular, "specular", Scope::Shape,
     [](const FeatureProbe& p) {
       const MeshData* vm = vertex_material_mesh(p.scene, *p.shape);
       return p.material->specular != 0.0 || p.material->specular_texture != kNoId || (vm && !vm->specular.empty());
     },
     trace_flags::kSpecular},
    {Feature::Ambient, "ambient", Scope::Shape,
     [](const FeatureProbe& p) { return p.material->ambient != 0.0 && nonzero(p.scene.settings.ambient_light); }},
    {Feature::PointLight, "point_light", Scope::Light,
     [](const FeatureProbe& p) { return p.light->kind == LightKind::Point; }},
    {Feature::SpotLight, "spot_light", Scope::Light, [](const FeatureProbe& p) { return p.light->kind == LightKind::Spot; }},
    {Feature::DirectionalLight, "directional_light", Scope::Light,
     [](const FeatureProbe& p) { return p.light->kind == LightKind::Directional; }},
    {Feature::AreaLight, "area_light", Scope::Light, [](const FeatureProbe& p) { return p.light->kind == LightKind::Area; }},
    {Feature::Shadows, "shadows", Scope::Light, [](const FeatureProbe& p) { return p.light->shadows; }},
    {Feature::TransmissiveShadows, "transmissive_shadows", Scope::Shape,
     [](const FeatureProbe& p) { return transmits(*p.material); }, trace_flags::kTransmissiveShadows, Feature::Shadows},
    {Feature::AreaSampling, "area_sampling", Scope::Light,
     [](const FeatureProbe& p) { return p.light->kind == LightKind::Area; }, trace_flags::kRandom},
    {Feature::DepthOfField, "depth_of_field", Scope::Scene,
     [](const FeatureProbe& p) { return p.scene.has_camera && p.scene.camera.aperture > 0.0; }},
    {Feature::Antialiasing, "antialiasing", Scope::Scene, [](const FeatureProbe& p) { return p.ctx.samples > 1; }},
    {Feature::Aovs, "aovs", Scope::Scene, [](const FeatureProbe& p) { return p.ctx.aovs; }},
    // Any CSG block placed (analyze_features adds it; its leaves count as shapes).
    {Feature::Csg, "csg", Scope::Scene, [](const FeatureProbe&) { return false; }},
    // Decided by the World (World::uses_bvh) and added by the renderer.
    {Feature::Bvh, "bvh", Scope::Scene, [](const FeatureProbe&) { return false; }},
    // Decided by flattening (instanced_groups) and added by the renderer.
    {Feature::Instancing, "instancing", Scope::Scene, [](const FeatureProbe&) { return false; }},
    {Feature::Fog, "fog", Scope::Scene, [](const FeatureProbe& p) { return p.scene.settings.fog_distance > 0.0; }},
    {Feature::SkySphere, "sky_sphere", Scope::Scene,
     [](const FeatureProbe& p) {
       const TextureId env = p.scene.settings.environment;
       return env < p.scene.textures.size() && p.scene.textures[env].kind == TextureKind::SkySphere;
     }},
    // A medium light can reach: around the objects, or inside a placed object that lets light
    // in (a medium behind an opaque surface is never seen, and costs nothing).
    {Feature::Media, "media", Scope::Shape,
     [](const FeatureProbe& p) {
       return p.scene.settings.medium != kNoId || (p.material->medium != kNoId && transmits(*p.material));
     }},
};

constexpr bool rules_in_feature_order() {
  for (std::size_t i = 0; i < std::size(kRules); ++i)
    if (static_cast<std::size_t>(kRules[i].feature) != kShapeKindCount + i) return false;
  return kShapeKindCount + std::size(kRules) == kFeatureCount;
}
static_assert(rules_in_feature_order(), "one leave-out rule per Feature after the shapes, in Feature's order");

// Shape features are named after their block kinds.
constexpr std::array<std::string_view, kFeatureCount> kNames = [] {
  std::array<std::string_view, kFeatureCount> names{};
  for (std::size_t i = 0; i < kShapeKindCount; ++i) names[i] = kShapeInfos[i].name;
  for (std::size_t i = 0; i < std::size(kRules); ++i) names[kShapeKindCount + i] = kRules[i].name;
  return names;
}();

void apply_rules(Scope scope, const FeatureProbe& probe, FeatureSet& f) {
  for (const FeatureRule& r : kRules)
    if (r.scope == scope && !f.has(r.feature) && r.used(probe)) f.add(r.feature);
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

unsigned trace_flags::for_features(const FeatureSet& f) {
  unsigned flags = 0;
  for (const FeatureRule& r : kRules)
    if (f.has(r.feature)) flags |= r.trace_flags;
  return flags;
}

namespace {
// f(group index) for each distinct group the world places as an instance.
template <class F>
void for_each_instanced_group(const FlatScene& flat, F&& f) {
  std::vector<bool> seen(flat.instanced.size(), false);
  for (const FlatGroup& g : flat.groups)
    if (g.group < seen.size() && !seen[g.group]) {
      seen[g.group] = true;
      f(g.group);
    }
}
}  // namespace

std::array<FeatureSet, 2> shape_features(const SceneDesc& scene, const FlatScene& flat) {
  std::array<FeatureSet, 2> f;
  // The default material (no material given) has the MaterialDesc defaults.
  const MaterialDesc default_material;
  // A Shape rule reads the context's max_depth alone (FeatureProbe::secondary_possible): the
  // one part of it given here, both ways.
  const FeatureContext contexts[2] = {{0, 0, false}, {0, 1, false}};
  // What a Shape rule sees of a shape: its kind, its material and its mesh (vertex materials).
  // Placed shapes mostly repeat the one before (a loop's spheres of one material), which then
  // adds nothing: a million spheres cost a million comparisons, not ten million rule calls.
  struct Seen {
    std::size_t kind;
    MaterialId material;
    MeshId mesh;
    bool operator==(const Seen&) const = default;
  };
  std::optional<Seen> last;
  auto add_shape = [&](const ShapeDesc& shape, MaterialId material) {
    const MeshRef* mesh = shape_if<MeshRef>(shape.geometry);
    const Seen seen{shape.geometry.index(), material, mesh ? mesh->mesh : kNoId};
    if (last == seen) return;
    last = seen;
    for (int s = 0; s < 2; ++s) {
      f[s].add(shape_feature(shape.geometry.index()));
      FeatureProbe probe{scene, contexts[s]};
      probe.shape = &shape;
      probe.material = material < scene.materials.size() ? &scene.materials[material] : &default_material;
      apply_rules(Scope::Shape, probe, f[s]);
      // A material chosen by pattern (its pattern is a texture of its own): what each choice uses.
      if (material < scene.materials.size() && scene.materials[material].choice_count > 0)
        for_each_material_choice(scene.materials, material, [&](MaterialId, const MaterialDesc& m) {
          probe.material = &m;
          apply_rules(Scope::Shape, probe, f[s]);
        });
    }
  };
  for (std::size_t i = 0; i < flat.shapes.size(); ++i) add_shape(scene.shapes[flat.shapes[i].shape], flat.material(scene, i));
  // An instanced group's shapes, once per group (not per placement; such a group holds no
  // group material, so each shows its own).
  for_each_instanced_group(flat, [&](uint32_t g) {
    for_each_group_shape(scene, g, [&](const ShapeDesc& s) { add_shape(s, s.material); });
  });
  // What a CSG block shows is its leaves, each with its own material or the block's (or the
  // enclosing group's).
  for (const FlatCsg& fc : flat.csgs) {
    for (FeatureSet& set : f) set.add(Feature::Csg);
    for_each_csg_leaf(scene, fc.csg, add_shape, fc.inherited);
  }
  return f;
}

FeatureSet analyze_features(const SceneDesc& scene, const FeatureSet& shapes, const std::vector<LightDesc>& lights,
                            const FeatureContext& ctx) {
  FeatureSet f = shapes;
  FeatureProbe probe{scene, ctx};
  for (const LightDesc& l : lights) {
    if (!light_emits(l)) continue;  // sends nothing: costs nothing
    probe.light = &l;
    apply_rules(Scope::Light, probe, f);
  }
  probe.light = nullptr;
  apply_rules(Scope::Scene, probe, f);
  for (const FeatureRule& r : kRules)
    if (r.only_with != Feature::Count && !f.has(r.only_with)) f.remove(r.feature);
  return f;
}

FeatureSet analyze_features(const SceneDesc& scene, const FlatScene& flat, const FeatureContext& ctx) {
  return analyze_features(scene, shape_features(scene, flat)[ctx.max_depth > 0 ? 1 : 0], flat.lights, ctx);
}

std::vector<bool> used_textures(const SceneDesc& scene, const FlatScene& flat) {
  std::vector<bool> used(scene.textures.size(), false);
  auto use_medium = [&](MediumId m) {
    if (m < scene.media.size() && scene.media[m].density < used.size()) used[scene.media[m].density] = true;
  };
  auto use_material = [&](MaterialId, const MaterialDesc& m) {
    for_each_texture(m, [&](TextureId t) { if (t < used.size()) used[t] = true; });
    use_medium(m.medium);
  };
  // Placed shapes mostly show the material of the shape before them, which adds nothing.
  MaterialId last = kNoId;
  auto use = [&](const ShapeDesc&, MaterialId id) {
    if (id >= scene.materials.size() || id == last) return;
    last = id;
    use_material(id, scene.materials[id]);  // a chooser's pattern
    if (scene.materials[id].choice_count > 0) for_each_material_choice(scene.materials, id, use_material);
  };
  for (std::size_t i = 0; i < flat.shapes.size(); ++i) use(scene.shapes[flat.shapes[i].shape], flat.material(scene, i));
  for_each_instanced_group(flat, [&](uint32_t g) {
    for_each_group_shape(scene, g, [&](const ShapeDesc& s) { use(s, s.material); });
  });
  for (const FlatCsg& fc : flat.csgs) for_each_csg_leaf(scene, fc.csg, use, fc.inherited);
  if (scene.settings.environment < used.size()) used[scene.settings.environment] = true;
  use_medium(scene.settings.medium);
  // A used texture uses its sky layers and its pigment_map's entries. They were built before it
  // (lower ids), so one pass from the top reaches entries of entries.
  for (std::size_t t = used.size(); t-- > 0;) {
    if (!used[t]) continue;
    const TextureDesc& d = scene.textures[t];
    for (TextureId layer : d.sky_layers)
      if (layer < t) used[layer] = true;
    for (const ColorMapEntry& e : d.pattern.color_map)
      if (e.texture < t) used[e.texture] = true;
  }
  return used;
}

}  // namespace rts::render
