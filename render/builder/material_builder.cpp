// SceneBuilder's materials: an ordinary material's properties (checked and defaulted), the
// materials that choose among others by a pattern or stack them in layers (with their nesting
// bounds), and the participating media a material or the settings describe. The rest of the
// builder is in scene_builder.cpp and scene_nodes.cpp.
#include "render/builder/scene_builder.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/builder/scene_builder_detail.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

using builder_detail::names_of_block;
using builder_detail::reference;
using builder_detail::second_word;

namespace {

const std::vector<std::string_view> kMaterialNames = names_of_block("material");

// How deep and how wide a material made of `members` (a chooser's choices, a layered
// material's layers) nests: MaterialDesc::choice_depth and choice_leaves of `m`, each bound
// checked at `property`. A member made of members of its own keeps pointing at them, stored
// before it, so its counts carry over.
void nest_bounds(ParamSet& ps, const std::vector<MaterialDesc>& materials, const std::vector<MaterialId>& members,
                 std::string_view property, std::string_view nesting, std::string_view through, MaterialDesc& m) {
  uint64_t leaves = 0;
  int depth = 0;
  for (MaterialId id : members) {
    const bool made = id < materials.size() && materials[id].choice_count > 0;
    leaves += made ? materials[id].choice_leaves : 1;
    if (made) depth = std::max(depth, static_cast<int>(materials[id].choice_depth));
  }
  if (depth + 1 > kMaxChoiceDepth)
    ps.fail(*ps.find(property), fmt::format("{} nest at most {} deep", nesting, kMaxChoiceDepth));
  if (leaves > kMaxChoiceLeaves)
    ps.fail(*ps.find(property),
            fmt::format("this material reaches {} materials through its {}; at most {}", leaves, through,
                        kMaxChoiceLeaves));
  m.choice_leaves = static_cast<uint32_t>(leaves);
  m.choice_depth = static_cast<uint8_t>(depth + 1);
}

}  // namespace

MaterialId SceneBuilder::material(ParamSet& ps) {
  if (ps.has("layers")) return layered_material(ps);
  if (ps.has("pattern") || ps.has("materials")) return chosen_material(ps);
  return ordinary_material(ps, nullptr);
}

MaterialId SceneBuilder::ordinary_material(ParamSet& ps, const MaterialDesc* start) {
  MaterialDesc m = start ? *start : MaterialDesc{};
  m.loc = ps.loc();
  for (const Param& p : ps.params())
    if (auto* t = std::get_if<TextureRef>(&p.value); t && t->id < scene_.textures.size() &&
                                                      scene_.textures[t->id].kind == TextureKind::SkySphere)
      ps.fail(p, fmt::format("property '{}' of material holds a sky_sphere: a sky is the background, set it as "
                             "settings {{ environment = ... }}",
                             p.name));
  if (const ParamValue* c = ps.value("color")) {
    if (auto* t = std::get_if<TextureRef>(c))
      m.texture = t->id;
    else
      m.color = ps.color("color", m.color);
  }
  if (const TextureRef* ref = reference<TextureRef>(ps, "texture", "material", "texture")) m.texture = ref->id;
  // A channel holding a texture takes its value from the texture at each point.
  auto channel_texture = [&](std::string_view name, TextureId& id) {
    const ParamValue* v = ps.value(name);
    if (auto* t = v ? std::get_if<TextureRef>(v) : nullptr) {
      id = t->id;
      return true;
    }
    return false;
  };
  if (!channel_texture("emission", m.emission_texture)) {
    m.emission = ps.color("emission", m.emission);
    non_negative_color(ps, "emission", m.emission);
  }
  // A weight, or a colour that weighs each channel: weight 1, that colour.
  auto weight_or_color = [&](std::string_view name, const ParamValue& v, double& weight, Color& color) {
    if (const double* d = std::get_if<double>(&v)) {
      weight = non_negative(ps, name, *d);
    } else {
      weight = 1.0;
      color = ps.color(name, color);
      non_negative_color(ps, name, color);
    }
  };
  // POV-Ray's `ambient rgb <...>` (golds.inc).
  if (const ParamValue* av = ps.value("ambient")) weight_or_color("ambient", *av, m.ambient, m.ambient_color);
  if (channel_texture("diffuse", m.diffuse_texture))
    m.diffuse = 1.0;
  else
    m.diffuse = non_negative(ps, "diffuse", ps.number("diffuse", m.diffuse));
  if (channel_texture("specular", m.specular_texture)) {
    m.specular = 1.0;
  } else if (const ParamValue* sv = ps.value("specular")) {
    weight_or_color("specular", *sv, m.specular, m.specular_color);  // a colour: the courses' `specularColor`
  }
  m.shininess = non_negative(ps, "shininess", ps.number("shininess", m.shininess));
  if (ps.has("highlight")) m.blinn = second_word(ps, "highlight", "phong", "blinn");
  m.brilliance = non_negative(ps, "brilliance", ps.number("brilliance", m.brilliance));
  m.metallic = non_negative(ps, "metallic", ps.number("metallic", m.metallic));
  m.reflect_metallic = non_negative(ps, "reflect_metallic", ps.number("reflect_metallic", m.reflect_metallic));
  if (ps.has("reflect_min")) {
    m.has_reflect_min = true;
    m.reflect_min = ps.color("reflect_min", m.reflect_min);
    non_negative_color(ps, "reflect_min", m.reflect_min);
  }
  m.reflect_falloff = non_negative(ps, "reflect_falloff", ps.number("reflect_falloff", m.reflect_falloff));
  if (!channel_texture("reflect", m.reflect_texture)) {
    m.reflect = ps.color("reflect", m.reflect);
    non_negative_color(ps, "reflect", m.reflect);
  }
  if (!channel_texture("transmit", m.transmit_texture)) {
    m.transmit = ps.color("transmit", m.transmit);
    non_negative_color(ps, "transmit", m.transmit);
  } else {
    // Where the texture is black the surface is opaque, but shadow rays must still test it.
    m.transmit = Color(1.0);
  }
  if (const TextureRef* b = reference<TextureRef>(ps, "bump", "material", "texture")) m.bump = b->id;
  m.bump_scale = ps.number("bump_scale", m.bump_scale);
  if (!std::isfinite(m.bump_scale)) require(ps, "bump_scale", false, "finite", m.bump_scale);
  if (const TextureRef* n = reference<TextureRef>(ps, "normal_map", "material", "texture")) m.normal_map = n->id;
  if (m.bump != kNoId && m.normal_map != kNoId) ps.fail_block("material takes 'bump' or 'normal_map', not both");
  m.ior = positive(ps, "ior", ps.number("ior", m.ior));
  m.ior_relative = ps.boolean("ior_relative", m.ior_relative);
  m.fresnel = ps.boolean("fresnel", m.fresnel);
  m.roughness = non_negative(ps, "roughness", ps.number("roughness", m.roughness));
  m.medium = medium(ps);
  if (m.medium != kNoId && !transmits(m))
    scene_.warnings.push_back({scene_.media[m.medium].loc,
                               "this material's medium is never seen: no light enters an object whose material has "
                               "no 'transmit' (rgb(1) with ior = 1 and diffuse = 0 makes a clear container)"});
  ps.check_unused(kMaterialNames);
  scene_.materials.push_back(std::move(m));
  return static_cast<MaterialId>(scene_.materials.size() - 1);
}

// material { pattern = P  materials = [A, B, ...] }: copies of A, B, ... stored together, then
// the material that picks among them (MaterialDesc::choice_pattern).
MaterialId SceneBuilder::chosen_material(ParamSet& ps) {
  const TextureRef* pattern = reference<TextureRef>(ps, "pattern", "material", "texture");
  const MaterialListParam* list = reference<MaterialListParam>(ps, "materials", "material", "list of materials");
  if (!pattern) ps.fail_block("a material with 'materials' needs the 'pattern' that chooses among them");
  if (!list) ps.fail_block("a material with 'pattern' needs the 'materials' it chooses among: materials = [a, b]");
  if (list->materials.size() < 2 || list->materials.size() > 256)
    ps.fail(*ps.find("materials"), fmt::format("'materials' holds 2 to 256 materials, got {}", list->materials.size()));
  for (const Param& p : ps.params())
    if (p.name != "pattern" && p.name != "materials")
      ps.fail(p, fmt::format("a material chosen by pattern takes only 'pattern' and 'materials': give '{}' to "
                             "the materials it chooses among",
                             p.name));
  MaterialDesc m;
  m.loc = ps.loc();
  m.choice_pattern = pattern->id;
  m.first_choice = static_cast<MaterialId>(scene_.materials.size());
  m.choice_count = static_cast<uint32_t>(list->materials.size());
  const MaterialDesc default_material;
  nest_bounds(ps, scene_.materials, list->materials, "materials", "materials chosen by pattern", "nested choices", m);
  m.transmit = Color(0.0);  // the most any choice transmits (MaterialDesc::choice_pattern)
  for (MaterialId id : list->materials) {
    MaterialDesc copy = id < scene_.materials.size() ? scene_.materials[id] : default_material;
    const Color& t = copy.transmit;  // a transmit texture's material holds 1 (material() above)
    m.transmit = Color(std::max(m.transmit.r, t.r), std::max(m.transmit.g, t.g), std::max(m.transmit.b, t.b));
    scene_.materials.push_back(copy);  // copied first: push_back may move the one it came from
  }
  scene_.materials.push_back(m);
  return static_cast<MaterialId>(scene_.materials.size() - 1);
}

// material { layers = [base, coat, ...] }: copies of the layers stored together, base first,
// then the layered material (MaterialDesc::layered) pointing at them.
MaterialId SceneBuilder::layered_material(ParamSet& ps) {
  const MaterialListParam* list = reference<MaterialListParam>(ps, "layers", "material", "list of materials");
  if (!list) ps.fail_block("'layers' holds the materials, base first: layers = [wood, varnish]");
  // A layered material among the layers brings its own layers, in their place.
  std::vector<MaterialId> layers;
  for (MaterialId id : list->materials) {
    if (id < scene_.materials.size() && scene_.materials[id].layered) {
      const MaterialDesc& inner = scene_.materials[id];
      for (uint32_t k = 0; k < inner.choice_count; ++k) layers.push_back(inner.first_choice + k);
    } else {
      layers.push_back(id);
    }
  }
  if (layers.empty() || layers.size() > 64)
    ps.fail(*ps.find("layers"), fmt::format("'layers' holds 1 to 64 materials (layered ones counted by their "
                                            "layers), got {}",
                                            layers.size()));
  // Other properties (`layered with { specular = 0.5 }`, POV-Ray's texture { T_Wood1 finish { ... } })
  // change the top layer, as POV-Ray's modifiers change a layered texture's top one.
  const Param* extra = nullptr;
  for (const Param& p : ps.params())
    if (p.name != "layers" && !extra) extra = &p;
  if (extra) {
    const MaterialId top = layers.back();
    if (top < scene_.materials.size() && scene_.materials[top].choice_count > 0)
      ps.fail(*extra, fmt::format("a layered material's other properties change its top layer, which is chosen by "
                                  "pattern here: give '{}' to the materials it chooses among",
                                  extra->name));
    const MaterialDesc start = top < scene_.materials.size() ? scene_.materials[top] : MaterialDesc{};
    layers.back() = ordinary_material(ps, &start);
  }
  MaterialDesc m;
  m.loc = ps.loc();
  m.layered = true;
  m.first_choice = static_cast<MaterialId>(scene_.materials.size());
  m.choice_count = static_cast<uint32_t>(layers.size());
  const MaterialDesc default_material;
  nest_bounds(ps, scene_.materials, layers, "layers", "layered and chosen materials", "layers and choices", m);
  for (MaterialId id : layers) {
    MaterialDesc copy = id < scene_.materials.size() ? scene_.materials[id] : default_material;
    scene_.materials.push_back(copy);  // copied first: push_back may move the one it came from
  }
  // What lets light through the object is the base's (a coat's transmit shows the layers
  // below it, not the inside).
  m.transmit = scene_.materials[m.first_choice].transmit;
  scene_.materials.push_back(m);
  return static_cast<MaterialId>(scene_.materials.size() - 1);
}

MediumId SceneBuilder::medium(ParamSet& ps) {
  static constexpr std::string_view kNames[] = {"media_absorption", "media_scattering", "media_emission",
                                                "media_eccentricity", "media_density", "fade_distance",
                                                "fade_power", "fade_color"};
  const bool material = ps.kind() == "material";  // the fade is an object's, not the atmosphere's
  bool any = false;
  for (std::string_view n : kNames) any = any || ((material || n.rfind("fade_", 0) != 0) && ps.has(n));
  if (!any) return kNoId;
  MediumDesc d;
  d.loc = ps.loc();
  for (std::string_view n : kNames)
    if (ps.has(n)) {
      d.loc = loc_of(ps, n);  // the first media property: where a warning about the medium points
      break;
    }
  d.absorption = ps.color("media_absorption", d.absorption);
  non_negative_color(ps, "media_absorption", d.absorption);
  d.scattering = ps.color("media_scattering", d.scattering);
  non_negative_color(ps, "media_scattering", d.scattering);
  d.emission = ps.color("media_emission", d.emission);
  non_negative_color(ps, "media_emission", d.emission);
  d.eccentricity = ps.number("media_eccentricity", d.eccentricity);
  require(ps, "media_eccentricity", d.eccentricity > -1.0 && d.eccentricity < 1.0,
          "between -1 and 1 (0: isotropic, 1 would be a beam)", d.eccentricity);
  if (const TextureRef* t = reference<TextureRef>(ps, "media_density", ps.kind(), "texture")) d.density = t->id;
  auto finite = [](const Color& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); };
  if (!finite(d.absorption)) require(ps, "media_absorption", false, "finite", d.absorption.r);
  if (!finite(d.scattering)) require(ps, "media_scattering", false, "finite", d.scattering.r);
  if (!finite(d.emission)) require(ps, "media_emission", false, "finite", d.emission.r);
  if (material && (ps.has("fade_distance") || ps.has("fade_power") || ps.has("fade_color"))) {
    // POV-Ray's interior fade: light crossing the inside over a distance d keeps
    // fade_color + (1 - fade_color) / (1 + (d / fade_distance)^fade_power), or with a power of
    // 1000 and more exp(-(1 - fade_color) d / fade_distance) (MediumDesc::fade_distance).
    if (!ps.has("fade_distance"))
      ps.fail(*ps.find(ps.has("fade_power") ? "fade_power" : "fade_color"),
              "POV-Ray's fade needs its 'fade_distance' (the distance at which light is halved, for a power > 0)");
    d.fade_distance = ps.number("fade_distance", d.fade_distance);
    require(ps, "fade_distance", std::isfinite(d.fade_distance) && d.fade_distance > 0.0, "a distance > 0",
            d.fade_distance);
    d.fade_power = non_negative(ps, "fade_power", ps.number("fade_power", d.fade_power));
    if (!std::isfinite(d.fade_power)) require(ps, "fade_power", false, "finite", d.fade_power);
    d.fade_color = ps.color("fade_color", d.fade_color);
    non_negative_color(ps, "fade_color", d.fade_color);
    if (d.fade_color.r > 1.0 || d.fade_color.g > 1.0 || d.fade_color.b > 1.0)
      require(ps, "fade_color", false, "a colour from 0 to 1 per channel", std::max({d.fade_color.r, d.fade_color.g, d.fade_color.b}));
    for (std::string_view n : {"media_scattering", "media_density"})
      if (ps.has(n))
        ps.fail(*ps.find(n),
                fmt::format("'{}' does not combine with POV-Ray's fade (fade_distance): the fade is a function of "
                            "the whole distance crossed, which scattering and density split",
                            n));
  }
  scene_.media.push_back(d);
  return static_cast<MediumId>(scene_.media.size() - 1);
}

}  // namespace rts::render
