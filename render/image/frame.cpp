#include "render/image/frame.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#include <fmt/format.h>

namespace rts::render {

AovFlags parse_aovs(const std::vector<std::string>& names) {
  AovFlags f;
  for (const std::string& n : names) {
    if (n == "normal") f.normal = true;
    else if (n == "depth") f.depth = true;
    else if (n == "albedo") f.albedo = true;
    else if (n == "error") f.error = true;
    else if (n == "error_map") f.error_map = true;
    else throw RenderError({}, fmt::format("unknown AOV '{}' (expected normal, depth, albedo, error or error_map)", n));
  }
  return f;
}

void allocate_frame(RenderResult& result, int width, int height, AovFlags aovs, bool with_variance, SourceRef where,
                    Frame& frame) {
  with_variance = with_variance || aovs.error_map;  // its grey "unknown" needs the -1 entries
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  frame.width = width;
  frame.height = height;
  frame.aovs = aovs;
  try {
    result.color = Image(width, height);
    if (with_variance) result.stats.pixels.variance.assign(pixels * 3, -1.0f);
    result.stats.pixels.taken.assign(pixels, 0);
    // std::map lookups happen here, once: operator[] must not run concurrently in workers.
    if (aovs.normal) frame.normal = &(result.aovs["normal"] = Image(width, height));
    if (aovs.albedo) frame.albedo = &(result.aovs["albedo"] = Image(width, height));
    if (aovs.error) result.aovs["error"] = Image(width, height);
    if (aovs.error_map) result.aovs["error_map"] = Image(width, height);
    if (aovs.depth) {
      result.aovs["depth"] = Image(width, height);
      frame.depth.assign(pixels, -1.0f);
      frame.depth_bounded.assign(pixels, 0);
    }
  } catch (const std::bad_alloc&) {
    throw RenderError(where, fmt::format("out of memory for a {}x{} image", width, height));
  }
  frame.color = &result.color;
  frame.variance = with_variance ? &result.stats.pixels.variance : nullptr;
  frame.taken = &result.stats.pixels.taken;
}

namespace {

// Without bounded geometry in view, depth is scaled by this quantile of the hit distances.
constexpr double kDepthPercentile = 0.99;

// The distance that maps to 1 in the depth AOV (see finish_depth); 0 when nothing was hit.
float depth_reference(const Frame& frame) {
  float farthest_bounded = 0.0f;
  for (std::size_t i = 0; i < frame.depth.size(); ++i)
    if (frame.depth_bounded[i]) farthest_bounded = std::max(farthest_bounded, frame.depth[i]);
  if (farthest_bounded > 0.0f) return farthest_bounded;
  // Only planes (or nothing) seen: the 99th percentile, so the few pixels at the horizon,
  // whose depth grows without bound, do not set the scale.
  std::vector<float> hits;
  for (float d : frame.depth)
    if (d >= 0.0f) hits.push_back(d);
  if (hits.empty()) return 0.0f;
  auto nth = hits.begin() + static_cast<std::ptrdiff_t>(kDepthPercentile * static_cast<double>(hits.size() - 1));
  std::nth_element(hits.begin(), nth, hits.end());
  return *nth;
}

}  // namespace

void finish_depth(RenderResult& result, const Frame& frame, std::optional<std::pair<double, double>> range,
                  float miss) {
  if (!frame.aovs.depth) return;
  const float reference = range ? 0.0f : depth_reference(frame);
  Image& img = result.aovs["depth"];
  for (std::size_t i = 0; i < frame.depth.size(); ++i) {
    float d = frame.depth[i];
    float v = miss;
    if (d >= 0.0f && range) {
      // near = far (allowed: a threshold) puts everything nearer at 0, the rest at 1.
      double span = range->second - range->first;
      double t = span > 0.0 ? (d - range->first) / span : (d < range->first ? 0.0 : 1.0);
      v = static_cast<float>(std::clamp(t, 0.0, 1.0));
    } else if (d >= 0.0f) {
      v = reference > 0.0f ? std::min(1.0f, d / reference) : 1.0f;
    }
    img.rgb[i * 3] = img.rgb[i * 3 + 1] = img.rgb[i * 3 + 2] = v;
  }
}

}  // namespace rts::render

namespace rts::render {

Vec3 error_map_colour(double relative_error) {
  // Stops of the ramp, evenly spaced in log10 of the relative error from 1e-3 to 1.
  static constexpr std::array<std::array<double, 3>, 5> kStops{{{0.0, 0.0, 0.0},
                                                               {0.1, 0.15, 0.85},
                                                               {0.1, 0.75, 0.3},
                                                               {0.95, 0.85, 0.1},
                                                               {0.9, 0.1, 0.1}}};
  const double t = std::clamp((std::log10(std::max(relative_error, 1e-12)) + 3.0) / 3.0, 0.0, 1.0) * 4.0;
  const int k = std::min(3, static_cast<int>(t));
  const double f = t - k;
  Vec3 c;
  for (int i = 0; i < 3; ++i) c[i] = kStops[k][i] + f * (kStops[k + 1][i] - kStops[k][i]);
  return c;
}

void finish_error(RenderResult& result, const Frame& frame) {
  if (!frame.variance) return;  // no estimate: the error AOV stays 0
  const std::vector<float>& var = *frame.variance;
  if (frame.aovs.error) {
    Image& img = result.aovs["error"];
    for (std::size_t i = 0; i < var.size(); ++i) img.rgb[i] = var[i] > 0.0f ? std::sqrt(var[i]) : 0.0f;
  }
  if (frame.aovs.error_map) {
    Image& img = result.aovs["error_map"];
    const std::vector<float>& value = result.color.rgb;
    for (std::size_t p = 0; p * 3 < var.size(); ++p) {
      Vec3 c(0.5);
      if (var[p * 3] >= 0.0f) {
        double v = 0, m = 0;
        for (int k = 0; k < 3; ++k) {
          v += std::max(0.0f, var[p * 3 + k]);
          m += std::abs(value[p * 3 + k]);
        }
        c = error_map_colour(std::sqrt(v / 3.0) / (m / 3.0 + 0.01));
      }
      for (int k = 0; k < 3; ++k) img.rgb[p * 3 + k] = static_cast<float>(c[k]);
    }
  }
}

}  // namespace rts::render
