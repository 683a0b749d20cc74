#include "render/image/tile_payload.hpp"

#include <cstring>
#include <type_traits>

#include <fmt/format.h>

#include "render/scene/source_ref.hpp"

namespace rts::render {
namespace {

static_assert(std::is_trivially_copyable_v<RayCounters>, "ray counts travel as bytes");

// Bytes per pixel for this frame's layout.
std::size_t pixel_bytes(const Frame& f) {
  std::size_t n = 3 * sizeof(float) + (f.variance ? 3 * sizeof(float) : 0) + sizeof(uint32_t);
  if (f.normal) n += 3 * sizeof(float);
  if (f.albedo) n += 3 * sizeof(float);
  if (!f.depth.empty()) n += sizeof(float) + 1;
  return n;
}

std::size_t tile_bytes(const Frame& f, const TileRect& r) {
  return sizeof(RayCounters) + static_cast<std::size_t>(r.x1 - r.x0) * (r.y1 - r.y0) * pixel_bytes(f);
}

struct Writer {
  unsigned char* p;
  void put(const void* src, std::size_t n) {
    std::memcpy(p, src, n);
    p += n;
  }
};
struct Reader {
  const unsigned char* p;
  void get(void* dst, std::size_t n) {
    std::memcpy(dst, p, n);
    p += n;
  }
};

}  // namespace

void pack_tile(const Frame& frame, const TileRect& rect, const RayCounters& counters, std::vector<unsigned char>& out) {
  out.resize(tile_bytes(frame, rect));
  Writer w{out.data()};
  w.put(&counters, sizeof counters);
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x) {
      const std::size_t i = frame.index(x, y);
      w.put(frame.color->at(x, y), 3 * sizeof(float));
      if (frame.variance) w.put(&(*frame.variance)[i * 3], 3 * sizeof(float));
      w.put(&(*frame.taken)[i], sizeof(uint32_t));
      if (frame.normal) w.put(frame.normal->at(x, y), 3 * sizeof(float));
      if (frame.albedo) w.put(frame.albedo->at(x, y), 3 * sizeof(float));
      if (!frame.depth.empty()) {
        w.put(&frame.depth[i], sizeof(float));
        w.put(&frame.depth_bounded[i], 1);
      }
    }
}

void unpack_tile(Frame& frame, const TileRect& rect, const std::vector<unsigned char>& in, RayCounters& counters) {
  if (in.size() != tile_bytes(frame, rect))
    throw RenderError({}, fmt::format("a tile of {} bytes does not fit a {}x{} tile of this image ({} bytes)", in.size(),
                                      rect.x1 - rect.x0, rect.y1 - rect.y0, tile_bytes(frame, rect)));
  Reader r{in.data()};
  r.get(&counters, sizeof counters);
  for (int y = rect.y0; y < rect.y1; ++y)
    for (int x = rect.x0; x < rect.x1; ++x) {
      const std::size_t i = frame.index(x, y);
      r.get(frame.color->at(x, y), 3 * sizeof(float));
      if (frame.variance) r.get(&(*frame.variance)[i * 3], 3 * sizeof(float));
      r.get(&(*frame.taken)[i], sizeof(uint32_t));
      if (frame.normal) r.get(frame.normal->at(x, y), 3 * sizeof(float));
      if (frame.albedo) r.get(frame.albedo->at(x, y), 3 * sizeof(float));
      if (!frame.depth.empty()) {
        r.get(&frame.depth[i], sizeof(float));
        r.get(&frame.depth_bounded[i], 1);
      }
    }
}

}  // namespace rts::render
