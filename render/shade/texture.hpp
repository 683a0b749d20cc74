// Texture evaluation. compile_textures() turns the scene's TextureDescs into samplers once
// (loading image files), then the integrator asks each for a color at a surface point.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "render/image/image.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// What a texture needs to know about the surface point being shaded.
struct TexturePoint {
  Vec3 object_point;     // hit point in the shape's object space
  glm::dvec2 uv{0.0};    // surface parameterisation, when has_uv
  bool has_uv = false;
};

class CompiledTexture {
 public:
  // images: one for Image and LatLong textures, six (+x, -x, +y, -y, +z, -z) for CubeMap.
  CompiledTexture(const TextureDesc& desc, std::vector<std::shared_ptr<const Image>> images);
  // One image, or none (null) for procedural kinds.
  CompiledTexture(const TextureDesc& desc, std::shared_ptr<const Image> image)
      : CompiledTexture(desc, image ? std::vector<std::shared_ptr<const Image>>{std::move(image)}
                                    : std::vector<std::shared_ptr<const Image>>{}) {}
  Color eval(const TexturePoint& p) const;
  // The texture as a bump's height: eval(), except that ripples and waves stay smooth (see
  // render/shade/pattern/patterns.hpp).
  Color eval_height(const TexturePoint& p) const;
  // Bytes of decoded image data this texture holds (0 for procedural ones).
  std::size_t image_bytes() const {
    std::size_t bytes = 0;
    for (const auto& image : images_) bytes += image ? image->rgb.size() * sizeof(float) : 0;
    return bytes;
  }
  // Environment lookup along a world direction (need not be unit length); any texture kind
  // answers, procedural ones at the point `direction` itself.
  Color eval_direction(const Vec3& direction) const;
  bool is_environment() const {
    return desc_.kind == TextureKind::LatLong || desc_.kind == TextureKind::CubeMap;
  }
  bool is_sky_sphere() const { return desc_.kind == TextureKind::SkySphere; }
  // A procedural texture as one of a sky_sphere's layers: its color and (w) its transmit at
  // point p (the direction in the sky's space); only pattern color maps have a transmit.
  glm::dvec4 eval_layer(const Vec3& p) const;
  // eval() with (w) the colour map's transmit at a surface point: a pattern's, 0 for other kinds
  // (a layered material's coat, render/shade/layers.hpp).
  glm::dvec4 eval_with_transmit(const TexturePoint& p) const;
  // SkySphere: its compiled layers (bottom first) and the settings' background, which shows
  // where every layer lets light through (compile_textures calls this).
  void set_sky(std::vector<CompiledTexture> layers, const Color& background) {
    sky_layers_ = std::move(layers);
    sky_background_ = background;
  }
  // Pattern with a pigment_map: the compiled texture of each entry that holds one, in the
  // order of the color map (null for entries without one). They point into the vector
  // compile_textures returns (entries are built before their map; the vector never grows),
  // so a map of maps shares its entries instead of copying them.
  void set_map_entries(std::vector<const CompiledTexture*> entries) { map_entries_ = std::move(entries); }
  // The size of one texel in uv units (0 for procedural textures), for bump-map differences.
  double texel_size() const;
  // Whether eval() reads TexturePoint::uv (an image with `mapping = "uv"`); every other kind
  // reads the point alone, so the caller need not compute a sphere's uv (two libm inverse
  // trigonometric calls) for it.
  bool uses_uv() const { return uses_uv_; }

 private:
  Color sample(const Image& image, double u, double v) const;
  Color lookup_direction(const Vec3& texture_space_direction) const;
  Color eval_sky(const Vec3& direction) const;   // render/shade/sky_sphere.cpp
  // A pigment_map's color and (w) transmit at texture-space point q: the entries on either
  // side of the pattern's index, each a color or its texture evaluated at q, blended.
  glm::dvec4 eval_map_entries(const Vec3& q) const;

  TextureDesc desc_;
  Mat4 inverse_;                                       // object space → texture space
  std::vector<std::shared_ptr<const Image>> images_;   // image kinds only (linear RGB)
  std::vector<CompiledTexture> sky_layers_;            // SkySphere only, bottom first
  std::vector<const CompiledTexture*> map_entries_;    // Pattern with textures in its map only
  Color sky_background_{0.0};                          // SkySphere: behind every layer
  bool uses_uv_ = false;
};

// Loads each distinct image once. Throws RenderError located at the texture's SourceRef when
// an image is missing or unreadable. With `used` (by TextureId), images no placed material
// refers to are never opened (their CompiledTexture has no image and is never evaluated).
// `max_memory` (--max-memory, 0: no limit): each image file is checked against it from its
// header before its pixels are decoded.
// Color maps whose entries are textures (pigment_map) nest at most this deep: each level is a
// call in the evaluation (and the stack's depth), so a chain built by a loop stops with a
// located error instead.
inline constexpr int kMaxColorMapNesting = 32;
// The textures hold pointers into the returned vector (color map entries): keep it, move it,
// but do not copy it apart from its elements' owners.
std::vector<CompiledTexture> compile_textures(const SceneDesc& scene, const std::vector<bool>* used = nullptr,
                                              std::size_t max_memory = 0);

}  // namespace rts::render
