// Images: linear RGB float pixels in memory; PNG reading and atomic PNG writing.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "render/scene/scene.hpp"
#include "render/scene/source_ref.hpp"

namespace rts::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // 3 floats per pixel, row-major, top row first

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0.0f) {}
  float* at(int x, int y) { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
  const float* at(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

enum class Encoding { SRGB, Linear };

// Writes `path` atomically: to a temporary file in the same directory, renamed over `path`
// only once complete, so a failure never leaves a partial file nor replaces a good one.
// bits: 8 or 16. Values are clamped to [0,1] after encoding. Throws RenderError.
void write_png(const std::string& path, const Image& image, int bits = 8,
               Encoding encoding = Encoding::SRGB);

// Reads any PNG (gray, gray+alpha, RGB, RGBA, palette, 8 or 16 bit) into linear RGB: sRGB
// values are decoded to linear when `encoding` is SRGB. Throws RenderError at `where`, also
// when decoding the image would take the process past `max_memory` bytes (0: no limit;
// checked from the header, before the pixels are allocated).
Image read_png(const std::string& path, SourceRef where = {}, Encoding encoding = Encoding::SRGB,
               std::size_t max_memory = 0);

// Reads PNG (through read_png), BMP, JPEG, TGA or Radiance HDR, told apart by their content,
// not their names. 8-bit data are decoded from sRGB when `encoding` is SRGB; HDR is linear.
// Throws RenderError at `where` (as read_png, `max_memory` included).
Image read_image(const std::string& path, SourceRef where = {}, Encoding encoding = Encoding::SRGB,
                 std::size_t max_memory = 0);

// The RenderError for an image whose decoding needs `bytes` more than `max_memory` allows.
RenderError image_over_memory(const std::string& path, SourceRef where, long long width, long long height,
                              std::size_t bytes, std::size_t max_memory);

float srgb_to_linear(float v);
float linear_to_srgb(float v);

}  // namespace rts::render
