// The golden-image comparison rule and its statistics.
#include <catch2/catch.hpp>

#include "tests/images/image_diff.hpp"

using namespace rts::images;

namespace {

Image flat(int w, int h, float value) {
  Image image(w, h);
  for (float& v : image.rgb) v = value;
  return image;
}

constexpr float kCode = 1.0f / 255.0f;

}  // namespace

TEST_CASE("identical images match with zero statistics", "[diff]") {
  const Image a = flat(10, 10, 0.4f);
  const DiffStats s = diff_images(a, a, DiffThresholds{}.channel_tolerance);
  CHECK(s.same_size);
  CHECK(s.pixels == 100);
  CHECK(s.differing_pixels == 0);
  CHECK(s.mean_abs == 0.0);
  CHECK(s.max_abs == 0.0);
  CHECK(s.worst_x == -1);
  CHECK(images_match(s, DiffThresholds{}));
}

TEST_CASE("differences within the channel tolerance do not count as differing", "[diff]") {
  const Image a = flat(20, 20, 0.5f);
  Image b = a;
  b.at(3, 4)[1] += 2.0f * kCode;   // exactly at the tolerance: not differing
  const DiffStats s = diff_images(a, b, 2.0 / 255.0 + 1e-6);
  CHECK(s.differing_pixels == 0);
  CHECK(s.max_abs == Approx(2.0 * kCode));
  CHECK(s.worst_x == 3);
  CHECK(s.worst_y == 4);
  CHECK(s.worst_expected[1] == Approx(0.5f));
  CHECK(s.worst_actual[1] == Approx(0.5f + 2.0f * kCode));
  CHECK(images_match(s, DiffThresholds{}));
}

TEST_CASE("more than 0.5% differing pixels fails", "[diff]") {
  // 1000 pixels: 5 differing is 0.5% (passes), 6 is 0.6% (fails).
  const Image a = flat(100, 10, 0.2f);
  Image b = a;
  for (int x = 0; x < 5; ++x) b.at(x, 0)[0] = 0.2f + 10 * kCode;
  DiffThresholds t;
  t.max_mean_abs = 1.0;   // isolate the fraction rule
  DiffStats s = diff_images(a, b, t.channel_tolerance);
  CHECK(s.differing_pixels == 5);
  CHECK(s.differing_fraction == Approx(0.005));
  CHECK(images_match(s, t));
  b.at(5, 0)[0] = 0.2f + 10 * kCode;
  s = diff_images(a, b, t.channel_tolerance);
  CHECK(s.differing_pixels == 6);
  CHECK_FALSE(images_match(s, t));
}

TEST_CASE("a small shift over the whole image fails by its mean difference", "[diff]") {
  const Image a = flat(30, 30, 0.5f);
  const Image b = flat(30, 30, 0.5f + 1.0f * kCode);   // every pixel off by 1/255
  const DiffStats s = diff_images(a, b, DiffThresholds{}.channel_tolerance);
  CHECK(s.differing_pixels == 0);
  CHECK(s.mean_abs == Approx(1.0 / 255.0).epsilon(1e-4));
  CHECK_FALSE(images_match(s, DiffThresholds{}));
}

TEST_CASE("the worst pixel is the largest channel difference", "[diff]") {
  const Image a = flat(8, 8, 0.0f);
  Image b = a;
  b.at(1, 1)[0] = 0.1f;
  b.at(6, 2)[2] = 0.7f;
  b.at(7, 7)[1] = 0.3f;
  const DiffStats s = diff_images(a, b, DiffThresholds{}.channel_tolerance);
  CHECK(s.differing_pixels == 3);
  CHECK(s.worst_x == 6);
  CHECK(s.worst_y == 2);
  CHECK(s.max_abs == Approx(0.7));
  CHECK(s.mean_abs == Approx((0.1 + 0.7 + 0.3) / (3.0 * 64)));
  const std::string text = describe(s, DiffThresholds{});
  CHECK_THAT(text, Catch::Contains("(6, 2)") && Catch::Contains("3 of 64"));
}

TEST_CASE("images of different sizes never match", "[diff]") {
  const DiffStats s = diff_images(flat(4, 4, 0.f), flat(4, 5, 0.f), 0.01);
  CHECK_FALSE(s.same_size);
  CHECK_FALSE(images_match(s, DiffThresholds{}));
  CHECK_THAT(describe(s, DiffThresholds{}), Catch::Contains("different sizes"));
  CHECK(amplified_difference(flat(4, 4, 0.f), flat(5, 4, 0.f), 10).rgb.empty());
}

TEST_CASE("the difference picture amplifies and clamps", "[diff]") {
  const Image a = flat(2, 1, 0.5f);
  Image b = a;
  b.at(1, 0)[0] = 0.52f;
  b.at(1, 0)[1] = 0.0f;
  const Image d = amplified_difference(a, b, 10.0);
  CHECK(d.at(0, 0)[0] == 0.0f);
  CHECK(d.at(1, 0)[0] == Approx(0.2f).margin(1e-5));
  CHECK(d.at(1, 0)[1] == 1.0f);   // 0.5 * 10 clamped
  CHECK(d.at(1, 0)[2] == 0.0f);
}
