#include "render/shade/shading.hpp"

#include <cmath>

#include "render/geometry/shapes/disc.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {
namespace {

Rgb rgb(const Color& c) { return Rgb(c.r, c.g, c.b); }
double luminance(const Color& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

bool valid(TextureId id, const std::vector<CompiledTexture>& textures) { return id < textures.size(); }

// Unit tangent and bitangent at the hit, perpendicular to n: along dp/du and dp/dv when the
// surface has them, else an arbitrary (but consistent) frame.
void tangent_frame(const WorldHit& hit, const Vec3& n, Vec3& t, Vec3& b) {
  Vec3 u = hit.dpdu - n * glm::dot(n, hit.dpdu);
  const double len = glm::length(u);
  t = len > tol::kTinyLength && std::isfinite(len) ? u / len : any_perpendicular(n);
  b = glm::cross(n, t);
  // Keep the frame's handedness that of the parameterisation (rts is left-handed; uv may be
  // either way round): the bitangent points along dp/dv.
  if (glm::dot(b, hit.dpdv) < 0.0) b = -b;
}

}  // namespace

TexturePoint texture_point(const World& world, const WorldHit& hit, bool want_uv) {
  TexturePoint p;
  p.object_point = hit.object_point;
  p.has_uv = hit.has_uv;
  if (p.has_uv && want_uv) p.uv = world.surface_uv(hit);
  return p;
}

MaterialId choose_material_at(MaterialId id, const std::vector<MaterialDesc>& materials, const World& world,
                              const WorldHit& hit, const std::vector<CompiledTexture>& textures) {
  const MaterialDesc& m = materials[id];
  // A layered material shows its base wherever layers are not shaded one by one (layers.hpp).
  if (m.layered) return m.first_choice < materials.size() ? m.first_choice : id;
  double v = 0.0;
  if (valid(m.choice_pattern, textures)) {
    const CompiledTexture& pattern = textures[m.choice_pattern];
    v = luminance(pattern.eval(texture_point(world, hit, pattern)));
  }
  const MaterialId chosen = m.first_choice + choice_for(v, m.choice_count);
  return chosen < materials.size() ? chosen : id;
}

const MaterialDesc& varying_material(const MaterialDesc& m, const World& world, const WorldHit& hit,
                                     const std::vector<CompiledTexture>& textures,
                                     MaterialScratch& slot) {
  VertexMaterial vm;
  const bool per_vertex = world.vertex_material(hit, vm);
  if (!per_vertex && !has_channel_textures(m)) return m;
  MaterialDesc& scratch = slot.emplace(m);
  if (per_vertex) {
    if (vm.has_color) {
      scratch.color = vm.color;
      scratch.texture = kNoId;   // the vertex colors are the surface's color
    }
    if (vm.has_diffuse) scratch.diffuse = std::max(0.0, vm.diffuse);
    if (vm.has_specular) {
      // The vertex value is the whole highlight, weight and tint: 1 times its color.
      scratch.specular = 1.0;
      scratch.specular_color = Color(std::max(0.0, vm.specular.r), std::max(0.0, vm.specular.g),
                                     std::max(0.0, vm.specular.b));
    }
    if (vm.has_shininess) scratch.shininess = std::max(0.0, vm.shininess);
  }
  if (has_channel_textures(m)) {
    auto reads_uv = [&](TextureId id) { return valid(id, textures) && textures[id].uses_uv(); };
    const TexturePoint p = texture_point(world, hit, reads_uv(m.specular_texture) || reads_uv(m.reflect_texture) ||
                                                         reads_uv(m.transmit_texture) || reads_uv(m.emission_texture));
    auto eval = [&](TextureId id) { return textures[id].eval(p); };
    if (valid(m.specular_texture, textures)) {
      // The texture is the highlight's color, channel by channel (UW's map() on specular).
      const Color c = eval(m.specular_texture);
      scratch.specular_color = Color(m.specular_color.r * c.r, m.specular_color.g * c.g, m.specular_color.b * c.b);
    }
    if (valid(m.reflect_texture, textures)) scratch.reflect = eval(m.reflect_texture);
    if (valid(m.transmit_texture, textures)) scratch.transmit = eval(m.transmit_texture);
    if (valid(m.emission_texture, textures)) scratch.emission = eval(m.emission_texture);
  }
  return scratch;
}

Rgb textured_diffuse(const MaterialDesc& m, const World& world, const WorldHit& hit,
                     const std::vector<CompiledTexture>& textures) {
  if (!valid(m.diffuse_texture, textures)) return Rgb(0.0);
  // The texture is the diffuse color itself: the builder sets `diffuse` to 1, so the
  // integrator's diffuse * color * (N·L) becomes texture * (N·L).
  const CompiledTexture& texture = textures[m.diffuse_texture];
  return rgb(texture.eval(texture_point(world, hit, texture)));
}

Vec3 perturbed_normal(const MaterialDesc& m, const World& world, const WorldHit& hit, const Vec3& n,
                      const std::vector<CompiledTexture>& textures) {
  const bool bump = valid(m.bump, textures), normal_map = valid(m.normal_map, textures);
  if (!bump && !normal_map) return n;
  Vec3 t, b;
  tangent_frame(hit, n, t, b);
  TexturePoint p = texture_point(world, hit, textures[normal_map ? m.normal_map : m.bump]);
  Vec3 out = n;
  if (normal_map) {
    // Tangent-space normal stored as rgb = (n + 1) / 2 (read the file with color_space "linear").
    const Color c = textures[m.normal_map].eval(p);
    const Vec3 local(2.0 * c.r - 1.0, 2.0 * c.g - 1.0, 2.0 * c.b - 1.0);
    out = local.x * t + local.y * b + local.z * n;
  } else {
    const CompiledTexture& height = textures[m.bump];
    const double texel = height.texel_size();
    const double step = texel > 0.0 ? texel : tol::kBumpDifference;
    const double h = luminance(height.eval_height(p));
    // The height's slope along u and v: image textures on uv surfaces by moving in uv, others
    // by moving the object-space point along the tangent frame (procedural textures live in
    // object space).
    TexturePoint pu = p, pv = p;
    if (p.has_uv && texel > 0.0) {
      pu.uv.x += step;
      pv.uv.y += step;
    } else {
      pu.object_point += step * t;
      pv.object_point += step * b;
    }
    const double hu = (luminance(height.eval_height(pu)) - h) / step;
    const double hv = (luminance(height.eval_height(pv)) - h) / step;
    // pbrt's bump mapping with the displacement along n: the displaced surface's tangents are
    // dp/du + bump_scale * dh/du * n; with unit tangents this is n - scale * (hu t + hv b).
    out = n - m.bump_scale * (hu * t + hv * b);
  }
  const double len = glm::length(out);
  if (!(len > tol::kTinyLength) || !std::isfinite(len)) return n;
  out /= len;
  return glm::dot(out, n) > 0.0 ? out : n;   // never turn the normal below the surface
}

}  // namespace rts::render
