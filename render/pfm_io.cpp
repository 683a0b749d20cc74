#include "render/pfm_io.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>

namespace rts::render {
namespace {

// Larger images are refused rather than allocated (a corrupt header must not eat memory).
constexpr uint64_t kMaxPfmPixels = 100'000'000;

bool host_is_little_endian() {
  const uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

float byte_swapped(float v) {
  unsigned char b[4];
  std::memcpy(b, &v, 4);
  std::swap(b[0], b[3]);
  std::swap(b[1], b[2]);
  std::memcpy(&v, b, 4);
  return v;
}

}  // namespace

void write_pfm(const std::string& path, const Image& image) {
  namespace fs = std::filesystem;
  const std::string temp = path + ".tmp-rts";
  {
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw RenderError({}, fmt::format("cannot write '{}'", path));
    // Negative scale: little-endian. PFM rows run bottom to top.
    out << "PF\n" << image.width << " " << image.height << "\n" << (host_is_little_endian() ? "-1.0" : "1.0") << "\n";
    for (int y = image.height - 1; y >= 0; --y)
      out.write(reinterpret_cast<const char*>(image.at(0, y)),
                static_cast<std::streamsize>(sizeof(float) * 3 * static_cast<std::size_t>(image.width)));
    if (!out.flush()) {
      std::error_code ec;
      fs::remove(temp, ec);
      throw RenderError({}, fmt::format("cannot write '{}': write failed", path));
    }
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw RenderError({}, fmt::format("cannot write '{}': {}", path, ec.message()));
  }
}

Image read_pfm(const std::string& path) {
  auto fail = [&](const std::string& why) {
    return RenderError({}, fmt::format("cannot read image '{}': {}", path, why));
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fail(std::strerror(errno));
  std::string magic;
  long long w = 0, h = 0;
  double scale = 0;
  if (!(in >> magic >> w >> h >> scale) || (magic != "PF" && magic != "Pf"))
    throw fail("not a PFM file (expected a 'PF' or 'Pf' header)");
  if (w < 1 || h < 1 || static_cast<uint64_t>(w) * static_cast<uint64_t>(h) > kMaxPfmPixels)
    throw fail(fmt::format("bad image size {}x{}", w, h));
  if (!std::isfinite(scale) || scale == 0) throw fail("bad scale in the header");
  in.get();  // the single whitespace character before the data
  const int channels = magic == "PF" ? 3 : 1;
  const std::size_t count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * channels;
  std::vector<float> data(count);
  if (!in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(count * sizeof(float))))
    throw fail("truncated data");
  const bool swap = (scale < 0) != host_is_little_endian();
  Image image(static_cast<int>(w), static_cast<int>(h));
  for (long long y = 0; y < h; ++y)
    for (long long x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        std::size_t src = (static_cast<std::size_t>(h - 1 - y) * w + x) * channels + (channels == 3 ? c : 0);
        float v = swap ? byte_swapped(data[src]) : data[src];
        if (!std::isfinite(v)) throw fail(fmt::format("non-finite value at pixel ({}, {})", x, y));
        image.at(static_cast<int>(x), static_cast<int>(y))[c] = v;
      }
  return image;
}

}  // namespace rts::render
