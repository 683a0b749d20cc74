// libFuzzer harness: the OBJ loader (tinyobjloader + our flattening and smooth normals). Every
// input loads into a consistent mesh or fails with a SceneError.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "render/builder/obj_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string path = rts::fuzz::write_input("fuzz.obj", data, size);
  // Both shading modes: smooth computes normals when the file has none.
  for (bool smooth : {false, true}) {
    try {
      auto mesh = rts::render::load_obj(path, "fuzz.obj", smooth, {});
      if (!mesh) std::abort();
    } catch (const rts::render::SceneError& e) {
      if (std::string(e.what()).empty()) std::abort();
    }
  }
  return 0;
}
