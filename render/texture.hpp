// Texture evaluation. compile_textures() turns the scene's TextureDescs into samplers once
// (loading image files), then the integrator asks each for a color at a surface point.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "render/image.hpp"
#include "render/scene.hpp"

namespace rts::render {

// What a texture needs to know about the surface point being shaded.
struct TexturePoint {
  Vec3 object_point;     // hit point in the shape's object space
  glm::dvec2 uv{0.0};    // surface parameterisation, when has_uv
  bool has_uv = false;
};

class CompiledTexture {
 public:
  CompiledTexture(const TextureDesc& desc, std::shared_ptr<const Image> image);
  Color eval(const TexturePoint& p) const;
  // Bytes of decoded image data this texture holds (0 for procedural ones).
  std::size_t image_bytes() const { return image_ ? image_->rgb.size() * sizeof(float) : 0; }

 private:
  TextureDesc desc_;
  Mat4 inverse_;                         // object space → texture space
  std::shared_ptr<const Image> image_;   // Image textures only (linear RGB)
};

// Loads each distinct image once. Throws RenderError located at the texture's SourceRef when
// an image is missing or unreadable. With `used` (by TextureId), images no placed material
// refers to are never opened (their CompiledTexture has no image and is never evaluated).
std::vector<CompiledTexture> compile_textures(const SceneDesc& scene, const std::vector<bool>* used = nullptr);

}  // namespace rts::render
