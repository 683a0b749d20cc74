#include "render/image/image_output.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <filesystem>

#include <fmt/format.h>

#include "render/image/float_image_io.hpp"

namespace rts::render {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void write_one(const std::string& path, const OutputSpec& spec, const Image& image, Encoding encoding) {
  switch (spec.format) {
    case ImageFormat::Png:
      write_png(path, image, spec.bits, encoding);
      return;
    case ImageFormat::Pfm:
      write_pfm(path, image);
      return;
    case ImageFormat::Exr:
      write_exr(path, {ExrLayer{"", &image, false}}, spec.bits == 16);
      return;
  }
}

}  // namespace

std::optional<ImageFormat> format_for_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".pfm") return ImageFormat::Pfm;
  if (ext == ".exr") return ImageFormat::Exr;
  return std::nullopt;
}

OutputSpecResult output_spec(const std::string& path, int bits, bool linear, bool aov_files) {
  OutputSpecResult r;
  std::optional<ImageFormat> format = format_for_path(path);
  // A device or pipe has no extension to go by (`-o /dev/stdout`): it gets PNG, as always.
  std::error_code ec;
  const auto type = std::filesystem::status(path, ec).type();
  if (!format && std::filesystem::path(path).extension().empty() &&
      (type == std::filesystem::file_type::character || type == std::filesystem::file_type::fifo))
    format = ImageFormat::Png;
  if (!format) {
    std::string ext = std::filesystem::path(path).extension().string();
    r.error = ext.empty() ? fmt::format("output '{}' has no extension (use .png, .pfm or .exr)", path)
                          : fmt::format("unknown output format '{}' for '{}' (use .png, .pfm or .exr)", ext, path);
    return r;
  }
  OutputSpec s;
  s.format = *format;
  s.linear = linear;
  s.aov_files = aov_files;
  switch (s.format) {
    case ImageFormat::Png:
      s.bits = bits == 0 ? 8 : bits;
      if (s.bits != 8 && s.bits != 16) r.error = fmt::format("--bits {} is not available for .png (8 or 16)", bits);
      break;
    case ImageFormat::Pfm:
      s.bits = bits == 0 ? 32 : bits;
      if (s.bits != 32) r.error = fmt::format("--bits {} is not available for .pfm (32)", bits);
      break;
    case ImageFormat::Exr:
      s.bits = bits == 0 ? 32 : bits;
      if (s.bits != 16 && s.bits != 32)
        r.error = fmt::format("--bits {} is not available for .exr (16 for half, 32 for float)", bits);
      break;
  }
  if (r.error.empty()) r.spec = s;
  return r;
}

std::string aov_path(const std::string& out, const std::string& name) {
  std::filesystem::path p(out);
  std::string ext = p.extension().string();
  p.replace_extension();
  return p.string() + "." + name + ext;
}

std::vector<std::string> write_images(const std::string& path, const OutputSpec& spec, const Image& color,
                                      const std::map<std::string, Image>& aovs) {
  std::vector<std::string> written;
  Image powered;
  if (spec.power != 1.0) {
    powered = color;
    for (float& v : powered.rgb) v = v > 0.0f ? static_cast<float>(std::pow(static_cast<double>(v), spec.power)) : 0.0f;
  }
  const Image& color_out = spec.power != 1.0 ? powered : color;
  if (spec.format == ImageFormat::Exr && !spec.aov_files) {
    // One file: the color as R, G, B; each AOV as a layer (depth as one channel, depth.Y).
    std::vector<ExrLayer> layers{ExrLayer{"", &color_out, false}};
    for (const auto& [name, image] : aovs) layers.push_back(ExrLayer{name, &image, name == "depth"});
    write_exr(path, layers, spec.bits == 16);
    written.push_back(path);
    return written;
  }
  write_one(path, spec, color_out, spec.linear ? Encoding::Linear : Encoding::SRGB);
  written.push_back(path);
  // AOVs are data (normals, depth), not colors: stored without the sRGB curve.
  for (const auto& [name, image] : aovs) {
    std::string p = aov_path(path, name);
    write_one(p, spec, image, Encoding::Linear);
    written.push_back(p);
  }
  return written;
}

}  // namespace rts::render
