// libFuzzer harness: the PNG reader behind image textures. Every input reads into an image of
// the size it claims with finite linear values, or fails with a RenderError.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "render/image/image.hpp"

// The CLI always reads images under --max-memory (half the RAM by default); the harness gives a
// limit that fits libFuzzer's 2 GB RSS bound with the sanitizers' overhead, so an image that is
// valid but large is refused as the CLI would refuse it on a smaller machine.
constexpr std::size_t kHarnessMaxMemory = std::size_t(768) << 20;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string path = rts::fuzz::write_input("fuzz.png", data, size);
  for (auto encoding : {rts::render::Encoding::SRGB, rts::render::Encoding::Linear}) {
    try {
      rts::render::Image image = rts::render::read_png(path, {}, encoding, kHarnessMaxMemory);
      if (image.width <= 0 || image.height <= 0) std::abort();
      if (image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) std::abort();
      for (float v : image.rgb)
        if (!std::isfinite(v) || v < 0.0f || v > 1.0f + 1e-6f) std::abort();  // 1e-6: pow() rounding at 1
    } catch (const rts::render::RenderError& e) {
      if (std::string(e.what()).empty()) std::abort();
    }
    if (size > 0 && (data[0] & 1)) break;  // half the inputs also try the linear encoding
  }
  return 0;
}
