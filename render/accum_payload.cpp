#include "render/accum_payload.hpp"

#include <cstring>
#include <type_traits>

#include <fmt/format.h>

#include "render/scene/source_ref.hpp"

namespace rts::render {
namespace {

static_assert(std::is_trivially_copyable_v<PixelAccum>, "sample sums travel as bytes");
static_assert(std::is_trivially_copyable_v<RayCounters>, "ray counts travel as bytes");

std::size_t pixel_count(const TileRect& r) {
  return static_cast<std::size_t>(r.x1 - r.x0) * static_cast<std::size_t>(r.y1 - r.y0);
}

void check_size(const std::vector<unsigned char>& in, std::size_t want, const char* what) {
  if (in.size() != want)
    throw RenderError({}, fmt::format("a tile's {} of {} bytes does not fit this image's tile ({} bytes)", what,
                                      in.size(), want));
}

}  // namespace

void pack_round_input(const std::vector<PixelAccum>& accs, const std::vector<uint32_t>& add, int width,
                      const TileRect& rect, std::vector<unsigned char>& out) {
  out.resize(pixel_count(rect) * (sizeof(PixelAccum) + sizeof(uint32_t)));
  unsigned char* p = out.data();
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      std::memcpy(p, &accs[i], sizeof(PixelAccum));
      p += sizeof(PixelAccum);
      std::memcpy(p, &add[i], sizeof(uint32_t));
      p += sizeof(uint32_t);
    }
}

void unpack_round_input(const std::vector<unsigned char>& in, const TileRect& rect, std::vector<PixelAccum>& accs,
                        std::vector<uint32_t>& add) {
  const std::size_t n = pixel_count(rect);
  check_size(in, n * (sizeof(PixelAccum) + sizeof(uint32_t)), "input");
  accs.resize(n);
  add.resize(n);
  const unsigned char* p = in.data();
  for (std::size_t k = 0; k < n; ++k) {
    std::memcpy(&accs[k], p, sizeof(PixelAccum));
    p += sizeof(PixelAccum);
    std::memcpy(&add[k], p, sizeof(uint32_t));
    p += sizeof(uint32_t);
  }
}

void pack_round_result(const RayCounters& counters, const std::vector<PixelAccum>& accs, std::vector<unsigned char>& out) {
  out.resize(sizeof(RayCounters) + accs.size() * sizeof(PixelAccum));
  std::memcpy(out.data(), &counters, sizeof counters);
  if (!accs.empty()) std::memcpy(out.data() + sizeof counters, accs.data(), accs.size() * sizeof(PixelAccum));
}

void unpack_round_result(const std::vector<unsigned char>& in, const TileRect& rect, int width,
                         std::vector<PixelAccum>& accs, RayCounters& counters) {
  check_size(in, sizeof(RayCounters) + pixel_count(rect) * sizeof(PixelAccum), "result");
  const unsigned char* p = in.data();
  std::memcpy(&counters, p, sizeof counters);
  p += sizeof counters;
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      std::memcpy(&accs[i], p, sizeof(PixelAccum));
      p += sizeof(PixelAccum);
    }
}

}  // namespace rts::render
