// Output formats: the extension picks PNG, PFM or EXR (an unknown one is refused), float
// formats keep values as rendered (above 1 included, never NaN), EXR half rounds as halves do,
// AOVs become EXR layers, and a failed write never replaces a good file.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <catch2/catch.hpp>

#include "render/image/float_image_io.hpp"
#include "render/image/image_output.hpp"
#include "tests/images/temp_dir.hpp"

using namespace rts::render;
using rts::images::TempDir;

namespace {

// A small image with values a PNG cannot hold: above 1, negative, tiny, and one NaN.
Image hdr_image() {
  Image img(3, 2);
  const float values[18] = {0.0f, 0.5f, 1.0f,   2.5f, 100.0f, 1e-6f,  -0.25f, 7.0f, 0.125f,
                            3.0f, 0.0f, 0.0f,   0.0f, 4.0f,   0.0f,   0.0f,   0.0f, std::nanf("")};
  std::copy(values, values + 18, img.rgb.begin());
  return img;
}

std::string head(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

}  // namespace

TEST_CASE("the output extension picks the format; others are refused", "[output]") {
  CHECK(format_for_path("a.png") == ImageFormat::Png);
  CHECK(format_for_path("dir.v2/A.PNG") == ImageFormat::Png);
  CHECK(format_for_path("a.pfm") == ImageFormat::Pfm);
  CHECK(format_for_path("a.Exr") == ImageFormat::Exr);
  CHECK_FALSE(format_for_path("a.jpg"));
  CHECK_FALSE(format_for_path("a.png.bak"));
  CHECK_FALSE(format_for_path("noext"));

  CHECK(output_spec("a.jpg", 0, false, false).error.find("unknown output format '.jpg'") != std::string::npos);
  CHECK(output_spec("a", 0, false, false).error.find("no extension") != std::string::npos);
  // Default and allowed bit depths per format.
  CHECK(output_spec("a.png", 0, false, false).spec->bits == 8);
  CHECK(output_spec("a.exr", 0, false, false).spec->bits == 32);
  CHECK(output_spec("a.exr", 16, false, false).spec->bits == 16);
  CHECK(output_spec("a.pfm", 0, false, false).spec->bits == 32);
  CHECK_FALSE(output_spec("a.png", 32, false, false).spec);
  CHECK_FALSE(output_spec("a.exr", 8, false, false).spec);
  CHECK_FALSE(output_spec("a.pfm", 16, false, false).spec);
  CHECK(aov_path("out/shot.exr", "depth") == "out/shot.depth.exr");
}

TEST_CASE("PFM keeps float values exactly; NaN is stored as 0", "[output]") {
  TempDir dir;
  const std::string path = dir.file("x.pfm");
  const Image img = hdr_image();
  write_pfm(path, img);
  CHECK(head(path, 12) == "PF\n3 2\n-1.0\n");
  CHECK(std::filesystem::file_size(path) == 12 + 3 * 2 * 3 * 4);
  const Image back = read_pfm(path);
  REQUIRE(back.width == 3);
  REQUIRE(back.height == 2);
  for (std::size_t i = 0; i + 1 < img.rgb.size(); ++i) CHECK(back.rgb[i] == img.rgb[i]);
  CHECK(back.rgb[17] == 0.0f);
}

TEST_CASE("EXR float and half, with AOVs as layers", "[output]") {
  TempDir dir;
  const Image img = hdr_image();
  Image depth(3, 2);
  for (std::size_t i = 0; i < depth.rgb.size(); ++i) depth.rgb[i] = static_cast<float>(i / 3) * 0.2f;
  Image normal(3, 2);
  for (std::size_t i = 0; i < normal.rgb.size(); ++i) normal.rgb[i] = static_cast<float>(i % 3) * 0.5f;

  OutputSpec spec;
  spec.format = ImageFormat::Exr;
  spec.bits = 32;
  const std::string path = dir.file("x.exr");
  auto written = write_images(path, spec, img, {{"depth", depth}, {"normal", normal}});
  CHECK(written == std::vector<std::string>{path});
  CHECK(head(path, 4) == std::string("\x76\x2f\x31\x01", 4));  // OpenEXR's magic number
  const Image back = read_exr(path);
  for (std::size_t i = 0; i + 1 < img.rgb.size(); ++i) CHECK(back.rgb[i] == img.rgb[i]);
  CHECK(back.rgb[17] == 0.0f);
  const Image back_depth = read_exr(path, "depth.");   // one channel, read as gray
  for (std::size_t i = 0; i < depth.rgb.size(); ++i) CHECK(back_depth.rgb[i] == depth.rgb[i / 3 * 3]);
  const Image back_normal = read_exr(path, "normal.");
  for (std::size_t i = 0; i < normal.rgb.size(); ++i) CHECK(back_normal.rgb[i] == normal.rgb[i]);

  // Half: values round to 11 significant bits; beyond 65504 they stay finite.
  Image big = img;
  big.rgb[4] = 1e6f;
  spec.bits = 16;
  write_images(path, spec, big, {});
  const Image half = read_exr(path);
  CHECK(half.rgb[1] == 0.5f);
  CHECK(half.rgb[3] == 2.5f);
  CHECK(half.rgb[4] == 65504.0f);
  CHECK(half.rgb[8] == 0.125f);

  // --aov-files: separate EXR files instead of layers.
  spec.aov_files = true;
  written = write_images(dir.file("y.exr"), spec, img, {{"depth", depth}});
  CHECK(written == std::vector<std::string>{dir.file("y.exr"), dir.file("y.depth.exr")});
  CHECK(read_exr(dir.file("y.depth.exr")).rgb[3] == Approx(0.2f).epsilon(1e-3));  // pixel 1
}

TEST_CASE("a failed float write leaves the existing file alone", "[output]") {
  TempDir dir;
  const std::string path = dir.file("keep.pfm");
  write_pfm(path, hdr_image());
  const std::string before = head(path, 1000);
  CHECK_THROWS_AS(write_pfm(path, Image()), RenderError);
  CHECK_THROWS_AS(write_exr(dir.file("missing/x.exr"), {ExrLayer{"", nullptr, false}}, false), RenderError);
  Image img = hdr_image();
  CHECK_THROWS_AS(write_pfm(dir.file("missing/x.pfm"), img), RenderError);
  CHECK(head(path, 1000) == before);
  // No temporary files left behind.
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) files += e.is_regular_file() ? 1 : 0;
  CHECK(files == 1);
}
