// Texture image files in any format the scene may name: PNG goes through libpng (16-bit
// precision kept), BMP, JPEG, TGA and Radiance HDR through stb_image (Debian's libstb-dev).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include <fmt/format.h>
#include <stb_image.h>

#include "render/image/image.hpp"
#include "render/scene/resource_limits.hpp"

namespace rts::render {

namespace {

// The same bound as the PNG reader: a hostile header must not make us allocate gigabytes.
constexpr long long kMaxReadPixels = 100'000'000;
constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

struct StbFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

}  // namespace

Image read_image(const std::string& path, SourceRef where, Encoding encoding, std::size_t max_memory) {
  auto fail = [&](const std::string& why) {
    return RenderError(where, fmt::format("cannot read image '{}': {}", path, why));
  };
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) throw fail(std::strerror(errno));
  unsigned char head[8] = {};
  std::size_t got = std::fread(head, 1, sizeof head, file);
  if (got == sizeof head && std::memcmp(head, kPngSignature, sizeof head) == 0) {
    std::fclose(file);
    return read_png(path, where, encoding, max_memory);
  }
  std::rewind(file);
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_file(file, &w, &h, &channels)) {
    std::fclose(file);
    throw fail(fmt::format("not a PNG, BMP, JPEG, TGA or HDR image ({})", stbi_failure_reason()));
  }
  if (w <= 0 || h <= 0 || static_cast<long long>(w) * h > kMaxReadPixels) {
    std::fclose(file);
    throw fail(fmt::format("image too large ({}x{})", w, h));
  }
  std::rewind(file);
  const bool hdr = stbi_is_hdr_from_file(file);
  // stb's decoded pixels (bytes, or floats for HDR) and the float image, before either is made.
  const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const std::size_t needed = pixels * 3 * ((hdr ? sizeof(float) : 1) + sizeof(float));
  if (!memory_fits(max_memory, needed)) {
    std::fclose(file);
    throw image_over_memory(path, where, w, h, needed, max_memory);
  }
  std::rewind(file);
  Image image(w, h);
  if (hdr) {
    // Radiance HDR stores linear radiance: no decoding, whatever the color space says.
    std::rewind(file);
    std::unique_ptr<float, StbFree> px(stbi_loadf_from_file(file, &w, &h, &channels, 3));
    std::fclose(file);
    if (!px) throw fail(stbi_failure_reason());
    std::memcpy(image.rgb.data(), px.get(), image.rgb.size() * sizeof(float));
    return image;
  }
  std::rewind(file);
  std::unique_ptr<unsigned char, StbFree> px(stbi_load_from_file(file, &w, &h, &channels, 3));
  std::fclose(file);
  if (!px) throw fail(stbi_failure_reason());
  float lut[256];  // 256 decodes instead of one per sample
  for (int i = 0; i < 256; ++i) {
    float v = static_cast<float>(i) / 255.0f;
    lut[i] = encoding == Encoding::SRGB ? srgb_to_linear(v) : v;
  }
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = lut[px.get()[i]];
  return image;
}

}  // namespace rts::render
