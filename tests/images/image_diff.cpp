#include "tests/images/image_diff.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace rts::images {

namespace {
constexpr double kCodesPer8Bit = 255.0;   // to print values as familiar 0-255 codes
}

DiffStats diff_images(const Image& expected, const Image& actual, double channel_tolerance) {
  DiffStats s;
  s.width = expected.width;
  s.height = expected.height;
  if (expected.width != actual.width || expected.height != actual.height ||
      expected.rgb.size() != actual.rgb.size()) {
    s.same_size = false;
    return s;
  }
  s.pixels = static_cast<std::size_t>(expected.width) * expected.height;
  double sum_abs = 0.0;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const float* e = expected.at(x, y);
      const float* a = actual.at(x, y);
      double pixel_max = 0.0;
      for (int c = 0; c < 3; ++c) {
        // NaN never comes out of a PNG, but a NaN must count as a difference, not hide one.
        double d = std::fabs(static_cast<double>(e[c]) - a[c]);
        if (std::isnan(d)) d = 1.0;
        sum_abs += d;
        pixel_max = std::max(pixel_max, d);
      }
      if (pixel_max > channel_tolerance) ++s.differing_pixels;
      if (pixel_max > s.max_abs) {
        s.max_abs = pixel_max;
        s.worst_x = x;
        s.worst_y = y;
        std::copy(e, e + 3, s.worst_expected);
        std::copy(a, a + 3, s.worst_actual);
      }
    }
  }
  if (s.pixels > 0) {
    s.differing_fraction = static_cast<double>(s.differing_pixels) / s.pixels;
    s.mean_abs = sum_abs / (3.0 * s.pixels);
  }
  return s;
}

bool images_match(const DiffStats& s, const DiffThresholds& t) {
  return s.same_size && s.differing_fraction <= t.max_differing_fraction &&
         s.mean_abs <= t.max_mean_abs;
}

std::string describe(const DiffStats& s, const DiffThresholds& t) {
  if (!s.same_size) return "images have different sizes\n";
  auto code = [](float v) { return v * kCodesPer8Bit; };
  std::string out = fmt::format(
      "differing pixels: {} of {} ({:.3f}%, limit {:.3f}%; a pixel differs beyond {:.2f}/255)\n",
      s.differing_pixels, s.pixels, 100.0 * s.differing_fraction,
      100.0 * t.max_differing_fraction, t.channel_tolerance * kCodesPer8Bit);
  out += fmt::format("mean |difference|: {:.3f}/255 (limit {:.3f}/255)\n",
                     s.mean_abs * kCodesPer8Bit, t.max_mean_abs * kCodesPer8Bit);
  if (s.worst_x >= 0) {
    out += fmt::format(
        "worst pixel: ({}, {}) expected ({:.1f}, {:.1f}, {:.1f}) got ({:.1f}, {:.1f}, {:.1f})\n",
        s.worst_x, s.worst_y, code(s.worst_expected[0]), code(s.worst_expected[1]),
        code(s.worst_expected[2]), code(s.worst_actual[0]), code(s.worst_actual[1]),
        code(s.worst_actual[2]));
  }
  return out;
}

Image amplified_difference(const Image& expected, const Image& actual, double gain) {
  if (expected.width != actual.width || expected.height != actual.height ||
      expected.rgb.size() != actual.rgb.size()) {
    return {};
  }
  Image out(expected.width, expected.height);
  for (std::size_t i = 0; i < expected.rgb.size(); ++i) {
    const double d = std::fabs(static_cast<double>(expected.rgb[i]) - actual.rgb[i]) * gain;
    out.rgb[i] = static_cast<float>(std::isnan(d) ? 1.0 : std::min(d, 1.0));
  }
  return out;
}

}  // namespace rts::images
