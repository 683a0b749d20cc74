// Float (HDR, linear) image files: PFM (Portable Float Map, RGB 32-bit float) and OpenEXR
// (32-bit float or 16-bit half channels, extra layers for AOVs). Writing is atomic
// (write_file_atomically). Values are stored as rendered: linear, unclamped; NaN is stored as 0
// and infinities as the largest finite value, so a file never carries a non-number.
#pragma once

#include <string>
#include <vector>

#include "render/image/image.hpp"

namespace rts::render {

void write_pfm(const std::string& path, const Image& image);
// Reads an RGB ("PF") or gray ("Pf") PFM of either byte order. Throws RenderError at `where`.
Image read_pfm(const std::string& path, SourceRef where = {});

// One layer of an EXR file: `name` "" gives the R, G, B channels; "normal" gives normal.R,
// normal.G, normal.B; a `single` layer stores only its first channel, as NAME.Y.
struct ExrLayer {
  std::string name;
  const Image* image = nullptr;
  bool single = false;
};
// half: 16-bit half floats instead of 32-bit floats. Every layer has the first layer's size.
void write_exr(const std::string& path, const std::vector<ExrLayer>& layers, bool half);
// Reads the channels `prefix`R/G/B (or `prefix`Y as gray) of an EXR file into an Image.
Image read_exr(const std::string& path, const std::string& prefix = "", SourceRef where = {});

}  // namespace rts::render
