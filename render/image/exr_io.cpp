// OpenEXR writing (to memory, then atomically to the file) and reading, with Debian's
// libopenexr. Channels are ZIP-compressed (lossless), in scanline order.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <fmt/format.h>

#include "render/image/atomic_file.hpp"
#include "render/image/float_image_io.hpp"

namespace rts::render {
namespace {

// The largest finite half-float: larger values would become infinities.
constexpr float kHalfMax = 65504.0f;

// Collects the encoded file in memory (OpenEXR seeks back to write its offset table, so it
// cannot stream straight into a pipe; the atomic writer then handles files and devices alike).
class MemoryStream : public Imf::OStream {
 public:
  MemoryStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (pos_ + static_cast<std::size_t>(n) > bytes_.size()) bytes_.resize(pos_ + static_cast<std::size_t>(n));
    std::memcpy(bytes_.data() + pos_, c, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
  }
  uint64_t tellp() override { return pos_; }
  void seekp(uint64_t pos) override { pos_ = static_cast<std::size_t>(pos); }
  std::vector<unsigned char>& bytes() { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
  std::size_t pos_ = 0;
};

float storable(float v, bool as_half) {
  if (std::isnan(v)) return 0.0f;
  const float limit = as_half ? kHalfMax : std::numeric_limits<float>::max();
  return std::clamp(v, -limit, limit);
}

}  // namespace

void write_exr(const std::string& path, const std::vector<ExrLayer>& layers, bool as_half) {
  if (layers.empty() || layers[0].image == nullptr)
    throw RenderError({}, fmt::format("cannot write '{}': no image", path));
  const int w = layers[0].image->width, h = layers[0].image->height;
  if (w <= 0 || h <= 0) throw RenderError({}, fmt::format("cannot write '{}': invalid image", path));
  // Sanitised copies (in the file's channel type: OpenEXR converts types when reading, not
  // when writing); the frame buffer points into them until writePixels returns.
  std::vector<std::vector<float>> floats;
  std::vector<std::vector<Imath::half>> halves;
  for (const ExrLayer& l : layers) {
    if (l.image == nullptr || l.image->width != w || l.image->height != h)
      throw RenderError({}, fmt::format("cannot write '{}': layer '{}' has another size", path, l.name));
    if (as_half) {
      std::vector<Imath::half>& d = halves.emplace_back(l.image->rgb.size());
      for (std::size_t i = 0; i < d.size(); ++i) d[i] = Imath::half(storable(l.image->rgb[i], true));
    } else {
      std::vector<float>& d = floats.emplace_back(l.image->rgb);
      for (float& v : d) v = storable(v, false);
    }
  }
  try {
    Imf::Header header(w, h);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer fb;
    const Imf::PixelType type = as_half ? Imf::HALF : Imf::FLOAT;
    const std::size_t value_size = as_half ? sizeof(Imath::half) : sizeof(float);
    const std::size_t xstride = 3 * value_size, ystride = xstride * static_cast<std::size_t>(w);
    for (std::size_t i = 0; i < layers.size(); ++i) {
      const std::string prefix = layers[i].name.empty() ? "" : layers[i].name + ".";
      const char* names[3] = {"R", "G", "B"};
      char* base = as_half ? reinterpret_cast<char*>(halves[i].data()) : reinterpret_cast<char*>(floats[i].data());
      for (int c = 0; c < (layers[i].single ? 1 : 3); ++c) {
        std::string channel = prefix + (layers[i].single ? "Y" : names[c]);
        header.channels().insert(channel, Imf::Channel(type));
        fb.insert(channel, Imf::Slice(type, base + c * value_size, xstride, ystride));
      }
    }
    MemoryStream stream;
    {
      Imf::OutputFile file(stream, header, 1);
      file.setFrameBuffer(fb);
      file.writePixels(h);
    }  // the destructor finishes the file (its line offset table)
    write_file_atomically(path, stream.bytes());
  } catch (const RenderError&) {
    throw;
  } catch (const std::exception& e) {
    throw RenderError({}, fmt::format("cannot write '{}': {}", path, e.what()));
  }
}

Image read_exr(const std::string& path, const std::string& prefix, SourceRef where) {
  try {
    Imf::InputFile file(path.c_str(), 1);
    const Imath::Box2i dw = file.header().dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    if (w <= 0 || h <= 0 || static_cast<long long>(w) * h > 100'000'000LL)
      throw RenderError(where, fmt::format("cannot read EXR '{}': bad size {}x{}", path, w, h));
    Image img(w, h);
    const std::size_t xstride = 3 * sizeof(float), ystride = xstride * static_cast<std::size_t>(w);
    // The slice base is offset so that the data window's first pixel lands at index 0.
    char* base = reinterpret_cast<char*>(img.rgb.data()) -
                 static_cast<std::ptrdiff_t>(dw.min.x * static_cast<long>(xstride) + dw.min.y * static_cast<long>(ystride));
    Imf::FrameBuffer fb;
    const bool gray = file.header().channels().findChannel(prefix + "Y") != nullptr &&
                      file.header().channels().findChannel(prefix + "R") == nullptr;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < (gray ? 1 : 3); ++c) {
      std::string channel = prefix + (gray ? "Y" : names[c]);
      if (file.header().channels().findChannel(channel) == nullptr)
        throw RenderError(where, fmt::format("cannot read EXR '{}': no channel '{}'", path, channel));
      fb.insert(channel, Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xstride, ystride));
    }
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    if (gray)  // Y was read into red: copy it to green and blue
      for (std::size_t i = 0; i < img.rgb.size(); i += 3) img.rgb[i + 1] = img.rgb[i + 2] = img.rgb[i];
    return img;
  } catch (const RenderError&) {
    throw;
  } catch (const std::exception& e) {
    throw RenderError(where, fmt::format("cannot read EXR '{}': {}", path, e.what()));
  }
}

}  // namespace rts::render
