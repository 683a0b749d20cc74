// Portable float maps (PFM, "PF" colour): linear float images without clamping, for
// references and error images that 8/16-bit PNGs would quantise.
#pragma once

#include <string>

#include "render/image.hpp"

namespace rts::render {

// Writes atomically (temporary file renamed over `path`). Throws RenderError.
void write_pfm(const std::string& path, const Image& image);

// Reads a colour ("PF") or grey ("Pf") PFM of either byte order into linear RGB. Throws
// RenderError on a malformed or truncated file, non-finite values, or an absurd size.
Image read_pfm(const std::string& path);

}  // namespace rts::render
