#include "render/shade/layers.hpp"

#include <algorithm>

#include "render/shade/material.hpp"

namespace rts::render {
namespace {

// The coat's colour at the hit and what it lets through: a pattern's colour map gives both;
// any other texture its colour, with the coat's own transmit alone.
MaterialDesc& coat_colour(const MaterialDesc& layer, const World& world, const WorldHit& hit,
                          const std::vector<CompiledTexture>& textures, MaterialScratch& scratch, Rgb& through) {
  MaterialScratch varying;
  MaterialDesc& c = scratch.emplace(shading_material(layer, world, hit, textures, varying));
  through = to_rgb(c.transmit);
  if (c.texture < textures.size()) {
    const CompiledTexture& t = textures[c.texture];
    const glm::dvec4 rgba = t.eval_with_transmit(texture_point(world, hit, t));
    c.color = Color(rgba.x, rgba.y, rgba.z);
    c.texture = kNoId;
    through += Rgb(rgba.w);
  }
  through = glm::clamp(through, 0.0, 1.0);
  c.transmit = Color(0.0);
  c.transmit_texture = kNoId;
  c.medium = kNoId;
  return c;
}

}  // namespace

const MaterialDesc& coat_at(const MaterialDesc& layer, const World& world, const WorldHit& hit,
                            const std::vector<CompiledTexture>& textures, MaterialScratch& scratch, Rgb& through) {
  MaterialDesc& c = coat_colour(layer, world, hit, textures, scratch, through);
  const double cover = 1.0 - max_channel(through);
  c.diffuse *= cover;
  c.ambient *= cover;
  c.emission = Color(c.emission.r * cover, c.emission.g * cover, c.emission.b * cover);
  return c;
}

MaterialId layered_at(MaterialId id, const std::vector<MaterialDesc>& materials, const World& world,
                      const WorldHit& hit, const std::vector<CompiledTexture>& textures) {
  for (int depth = 0; id < materials.size() && materials[id].choice_count > 0 && depth < kMaxChoiceDepth; ++depth) {
    if (materials[id].layered) return id;
    id = choose_material_at(id, materials, world, hit, textures);
  }
  return kNoId;
}

const MaterialDesc& path_layer(MaterialId id, const std::vector<MaterialDesc>& materials, const World& world,
                               const WorldHit& hit, const std::vector<CompiledTexture>& textures, double u,
                               MaterialScratch& scratch, const MaterialDesc& fallback, MaterialId& picked) {
  for (int depth = 0; id < materials.size() && materials[id].choice_count > 0 && depth < kMaxChoiceDepth; ++depth) {
    const MaterialDesc& m = materials[id];
    if (!m.layered) {
      id = choose_material_at(id, materials, world, hit, textures);
      continue;
    }
    // From the top coat down: coat k shows `left` (what the coats above let through) times its
    // cover; u falls in one share, or past all of them in the base's.
    double left = 1.0;
    for (uint32_t k = m.choice_count; k-- > 1;) {
      const MaterialId coat_id = surface_material_id(m.first_choice + k, materials, world, hit, textures);
      if (coat_id >= materials.size()) continue;
      Rgb through;
      MaterialDesc& c = coat_colour(materials[coat_id], world, hit, textures, scratch, through);
      // The coat shows its diffuse by its cover and its gloss (highlight and mirror) whole, as
      // in Whitted mode; as a mixture the two together take a share of at most 1, and the
      // picked coat's weights are divided by it.
      const double cover = 1.0 - max_channel(through);
      const double gloss = std::max(c.specular, 0.0) + max_channel(to_rgb(c.reflect));
      const double a = std::min(1.0, cover + gloss);
      const double share = left * a;
      if (u < share) {
        picked = coat_id;
        c.diffuse *= cover / a;
        c.ambient *= cover / a;
        c.emission = Color(c.emission.r * cover / a, c.emission.g * cover / a, c.emission.b * cover / a);
        c.specular /= a;
        c.reflect = Color(c.reflect.r / a, c.reflect.g / a, c.reflect.b / a);
        return c;
      }
      u -= share;
      left *= 1.0 - a;
    }
    u = left > 0.0 ? std::min(u / left, 1.0) : 0.0;  // spread over the base's share again
    id = m.first_choice;  // the base (itself perhaps chosen or layered: resolved on)
  }
  picked = id;
  return id < materials.size() ? materials[id] : fallback;
}

}  // namespace rts::render
