// Image comparison for the golden-image tests: per-pixel difference statistics, a pass/fail
// rule, and an amplified difference picture for humans.
//
// Images are compared as stored in the PNG files (read with Encoding::Linear, so a value of
// k/255 is exactly the file's code k): tolerances are in encoded units.
#pragma once

#include <cstddef>
#include <string>

#include "render/image/image.hpp"

namespace rts::images {

using render::Image;

struct DiffThresholds {
  double channel_tolerance = 2.0 / 255.0;     // a pixel "differs" beyond this in any channel
  double max_differing_fraction = 0.005;      // fail above 0.5% differing pixels
  double max_mean_abs = 0.5 / 255.0;          // fail above this mean |a-b| over all channels
};

struct DiffStats {
  bool same_size = true;
  int width = 0, height = 0;
  std::size_t pixels = 0;
  std::size_t differing_pixels = 0;           // max channel |a-b| > channel_tolerance
  double differing_fraction = 0.0;
  double mean_abs = 0.0;                      // mean over every channel of every pixel
  double max_abs = 0.0;                       // the worst channel difference
  int worst_x = -1, worst_y = -1;             // where max_abs occurs (first such pixel)
  float worst_expected[3] = {0, 0, 0};
  float worst_actual[3] = {0, 0, 0};
};

// Statistics of `actual` against `expected`. Different sizes give same_size = false and no
// other statistics.
DiffStats diff_images(const Image& expected, const Image& actual, double channel_tolerance);

// The pass rule: same size, and neither the differing fraction nor the mean difference over
// their limits.
bool images_match(const DiffStats& stats, const DiffThresholds& thresholds);

// One line per fact: sizes, differing pixels, mean and worst difference with its position and
// both values (as 0-255 codes).
std::string describe(const DiffStats& stats, const DiffThresholds& thresholds);

// |expected - actual| per channel times `gain`, clamped to 1: black where identical.
// Sizes must match (else an empty image).
Image amplified_difference(const Image& expected, const Image& actual, double gain);

}  // namespace rts::images
