// rts-imgdiff EXPECTED.png ACTUAL.png [DIFF.png]: compares two PNGs with the golden-image
// rule, prints the statistics, optionally writes the amplified difference. Exit 0 when they
// match, 1 when they differ, 2 on usage or read errors.
#include <exception>
#include <iostream>
#include <string>

#include "render/image/image.hpp"
#include "tests/images/image_diff.hpp"

namespace {
constexpr double kDiffGain = 16.0;
constexpr int kExitDiffer = 1, kExitUsage = 2;
}

int main(int argc, char** argv) {
  using namespace rts;
  if (argc < 3 || argc > 4) {
    std::cerr << "usage: rts-imgdiff EXPECTED.png ACTUAL.png [DIFF.png]\n";
    return kExitUsage;
  }
  try {
    const auto expected = render::read_png(argv[1], {}, render::Encoding::Linear);
    const auto actual = render::read_png(argv[2], {}, render::Encoding::Linear);
    const images::DiffThresholds thresholds;
    const auto stats = images::diff_images(expected, actual, thresholds.channel_tolerance);
    std::cout << images::describe(stats, thresholds);
    if (argc == 4) {
      const auto picture = images::amplified_difference(expected, actual, kDiffGain);
      if (!picture.rgb.empty()) render::write_png(argv[3], picture, 8, render::Encoding::Linear);
    }
    const bool match = images::images_match(stats, thresholds);
    std::cout << (match ? "match\n" : "DIFFER\n");
    return match ? 0 : kExitDiffer;
  } catch (const std::exception& e) {
    std::cerr << "rts-imgdiff: " << e.what() << "\n";
    return kExitUsage;
  }
}
