// What a material is at one surface point: channel textures, per-vertex material values, and
// bump or normal maps applied to a MaterialDesc before the integrator shades with it. Kept
// apart from the integrator so its recursion reads as Whitted's algorithm only.
#pragma once

#include <new>
#include <type_traits>
#include <vector>

#include "render/shade/lights.hpp"
#include "render/shade/texture.hpp"
#include "render/accel/world.hpp"

namespace rts::render {

// Where a texture is looked up for a hit (object point, and uv when the surface has them).
// With `want_uv` false the uv is left 0 (has_uv still says whether the surface has them):
// for textures that do not read it (CompiledTexture::uses_uv).
TexturePoint texture_point(const World& world, const WorldHit& hit, bool want_uv = true);
// The point for looking up `texture`: its uv only when it reads them.
inline TexturePoint texture_point(const World& world, const WorldHit& hit, const CompiledTexture& texture) {
  return texture_point(world, hit, texture.uses_uv());
}

// The material a hit on a surface with material `id` shows: for a material chosen by pattern
// (MaterialDesc::choice_pattern), the choice its pattern's luminance picks at the hit (equal
// ranges of [0, 1], the first for the darkest); for a layered material (MaterialDesc::layered),
// its base, where the caller does not shade its layers (render/shade/layers.hpp); else `id`
// itself. One test when nothing is chosen.
MaterialId choose_material_at(MaterialId id, const std::vector<MaterialDesc>& materials, const World& world,
                              const WorldHit& hit, const std::vector<CompiledTexture>& textures);
inline MaterialId surface_material_id(MaterialId id, const std::vector<MaterialDesc>& materials, const World& world,
                                      const WorldHit& hit, const std::vector<CompiledTexture>& textures) {
  // A nested choice chooses again (the builder bounds the depth; the loop bound is a guard).
  for (int depth = 0; id < materials.size() && materials[id].choice_count > 0 && depth < kMaxChoiceDepth; ++depth)
    id = choose_material_at(id, materials, world, hit, textures);
  return id;
}
// Which of `count` choices a luminance picks (NaN and below 0: the first; 1 and above: the last).
inline uint32_t choice_for(double luminance, uint32_t count) {
  if (!(luminance > 0.0)) return 0;
  const double k = luminance * static_cast<double>(count);
  return k >= static_cast<double>(count) ? count - 1 : static_cast<uint32_t>(k);
}

// True when `m` has anything to evaluate per point (a channel texture).
inline bool has_channel_textures(const MaterialDesc& m) {
  return m.diffuse_texture != kNoId || m.specular_texture != kNoId || m.reflect_texture != kNoId ||
         m.transmit_texture != kNoId || m.emission_texture != kNoId;
}

// Room for the MaterialDesc a hit's varying material is written into (varying_material), left
// unset until then. Not std::optional: libstdc++'s optional<MaterialDesc> zeroes its 256 bytes
// when constructed, which GCC does with a `rep stos`; profile finding (perf, the pattern race
// scene): that and WorldHit's initialisation were 40% of Integrator::shade's own samples, on
// every shaded hit, for a slot that is empty unless a channel texture or per-vertex values vary.
class MaterialScratch {
 public:
  MaterialScratch() noexcept {}   // value_ stays unset
  MaterialDesc& emplace(const MaterialDesc& m) { return *::new (static_cast<void*>(&value_)) MaterialDesc(m); }

 private:
  static_assert(std::is_trivially_destructible_v<MaterialDesc>, "MaterialScratch never destroys its value");
  union {
    MaterialDesc value_;
  };
};

// `m` itself when nothing varies over the surface; otherwise `scratch`, a copy with the
// channel textures evaluated and the mesh's per-vertex values interpolated into it.
// `diffuse_color`: the color the diffuse term uses (diffuse texture, else the albedo given).
// `scratch` is filled only when needed, so the common case costs two inline tests.
const MaterialDesc& varying_material(const MaterialDesc& m, const World& world, const WorldHit& hit,
                                     const std::vector<CompiledTexture>& textures,
                                     MaterialScratch& scratch);
inline const MaterialDesc& shading_material(const MaterialDesc& m, const World& world, const WorldHit& hit,
                                            const std::vector<CompiledTexture>& textures,
                                            MaterialScratch& scratch) {
  if (!has_channel_textures(m) && !world.has_vertex_material(hit)) return m;
  return varying_material(m, world, hit, textures, scratch);
}

// The diffuse term's color: `diffuse_texture` when set, else `albedo` (color or texture).
Rgb textured_diffuse(const MaterialDesc& m, const World& world, const WorldHit& hit,
                     const std::vector<CompiledTexture>& textures);
inline Rgb diffuse_color(const MaterialDesc& m, const Rgb& albedo, const World& world, const WorldHit& hit,
                         const std::vector<CompiledTexture>& textures) {
  if (m.diffuse_texture == kNoId) return albedo;
  return textured_diffuse(m, world, hit, textures);
}

// The shading normal `n` perturbed by the material's bump or normal map (unit, on n's side
// of the surface); `n` itself when the material has neither.
Vec3 perturbed_normal(const MaterialDesc& m, const World& world, const WorldHit& hit, const Vec3& n,
                      const std::vector<CompiledTexture>& textures);
inline Vec3 detail_normal(const MaterialDesc& m, const World& world, const WorldHit& hit, const Vec3& n,
                          const std::vector<CompiledTexture>& textures) {
  if (m.bump == kNoId && m.normal_map == kNoId) return n;
  return perturbed_normal(m, world, hit, n, textures);
}

}  // namespace rts::render
