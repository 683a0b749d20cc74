// Writing a render's images: the format follows the output's extension (.png, .pfm, .exr),
// never another's bytes under a name. AOVs go beside the image (OUT.normal.png) or, in EXR,
// into the same file as extra layers.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "render/image/image.hpp"

namespace rts::render {

enum class ImageFormat { Png, Pfm, Exr };

struct OutputSpec {
  ImageFormat format = ImageFormat::Png;
  int bits = 8;             // png: 8 or 16; exr: 16 (half) or 32 (float); pfm: 32
  bool linear = false;      // png: store linear values instead of sRGB (float formats always are)
  bool aov_files = false;   // exr: AOVs as separate files instead of layers of the one file
  // The color image's values are raised to this power before they are written (settings'
  // numeric output_gamma: POV-Ray's assumed_gamma); AOVs are data and stay as they are.
  double power = 1.0;
};

// The format named by `path`'s extension (any case), or nullopt for any other name.
std::optional<ImageFormat> format_for_path(const std::string& path);

// The spec for `path` with `bits` (0: the format's default), or an error message for the user
// (a device or pipe without an extension, such as /dev/stdout, is written as PNG)
// ("unknown output format '.jpg' (use .png, .pfm or .exr)", "--bits 8 is not available for .exr").
struct OutputSpecResult {
  std::optional<OutputSpec> spec;
  std::string error;
};
OutputSpecResult output_spec(const std::string& path, int bits, bool linear, bool aov_files);

// OUT.NAME.EXT beside OUT.EXT.
std::string aov_path(const std::string& out, const std::string& name);

// Writes `color` (linear) to `path` and each AOV (data, stored linear) as `spec` says; returns
// the paths written. Every file is written atomically. Throws RenderError.
std::vector<std::string> write_images(const std::string& path, const OutputSpec& spec, const Image& color,
                                      const std::map<std::string, Image>& aovs);

}  // namespace rts::render
