// PFM: "PF\n<width> <height>\n<scale>\n" then float RGB rows, bottom row first; a negative
// scale means little-endian. We write little-endian, the common choice.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "render/image/atomic_file.hpp"
#include "render/image/float_image_io.hpp"

namespace rts::render {
namespace {

constexpr std::size_t kMaxPfmPixels = 100'000'000;  // a hostile header must not allocate gigabytes

float finite(float v) {
  if (std::isnan(v)) return 0.0f;
  return std::clamp(v, -std::numeric_limits<float>::max(), std::numeric_limits<float>::max());
}

uint32_t swap_bytes(uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

}  // namespace

void write_pfm(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3)
    throw RenderError({}, fmt::format("cannot write '{}': invalid image", path));
  std::string header = fmt::format("PF\n{} {}\n-1.0\n", image.width, image.height);
  std::vector<unsigned char> bytes(header.begin(), header.end());
  const std::size_t row_floats = static_cast<std::size_t>(image.width) * 3;
  bytes.reserve(bytes.size() + image.rgb.size() * 4);
  for (int y = image.height - 1; y >= 0; --y) {
    const float* row = image.at(0, y);
    for (std::size_t i = 0; i < row_floats; ++i) {
      uint32_t bits = std::bit_cast<uint32_t>(finite(row[i]));
      if constexpr (std::endian::native == std::endian::big) bits = swap_bytes(bits);
      unsigned char b[4];
      std::memcpy(b, &bits, 4);
      bytes.insert(bytes.end(), b, b + 4);
    }
  }
  write_file_atomically(path, bytes);
}

Image read_pfm(const std::string& path, SourceRef where) {
  auto fail = [&](const std::string& why) -> Image {
    throw RenderError(where, fmt::format("cannot read PFM '{}': {}", path, why));
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot open the file");
  std::string magic;
  long long w = 0, h = 0;
  double scale = 0;
  in >> magic >> w >> h >> scale;
  if (!in || (magic != "PF" && magic != "Pf")) return fail("not a PFM file");
  if (w <= 0 || h <= 0 || static_cast<unsigned long long>(w) * static_cast<unsigned long long>(h) > kMaxPfmPixels)
    return fail(fmt::format("bad size {}x{}", w, h));
  if (scale == 0 || !std::isfinite(scale)) return fail("bad scale");
  in.get();  // the single whitespace byte after the scale
  const int channels = magic == "PF" ? 3 : 1;
  const bool little = scale < 0;
  const bool swap = little != (std::endian::native == std::endian::little);
  Image img(static_cast<int>(w), static_cast<int>(h));
  std::vector<uint32_t> row(static_cast<std::size_t>(w) * channels);
  for (long long y = h - 1; y >= 0; --y) {
    if (!in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size() * 4)))
      return fail("file is truncated");
    for (long long x = 0; x < w; ++x) {
      float* px = img.at(static_cast<int>(x), static_cast<int>(y));
      for (int c = 0; c < 3; ++c) {
        uint32_t bits = row[static_cast<std::size_t>(x) * channels + (channels == 3 ? c : 0)];
        if (swap) bits = swap_bytes(bits);
        px[c] = finite(std::bit_cast<float>(bits));
      }
    }
  }
  return img;
}

}  // namespace rts::render
