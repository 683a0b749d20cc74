// Texture evaluation: each kind at known points, boundary robustness, texture transforms,
// image mappings with bilinear filtering and wrapping, and compile_textures' error reporting
// (unreadable images, and --max-memory reaching the decoders).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "render/scene/resource_limits.hpp"
#include "render/shade/texture.hpp"
#include "tests/images/temp_dir.hpp"

using namespace rts::render;
using rts::images::TempDir;

namespace {

const Color kWhite{1.0}, kBlack{0.0};
const Color kRed{1, 0, 0}, kGreen{0, 1, 0}, kBlue{0, 0, 1};

TextureDesc procedural(TextureKind kind, double scale = 1.0, int axis = 0) {
  TextureDesc d;
  d.kind = kind;
  d.color1 = kWhite;
  d.color2 = kBlack;
  d.scale = scale;
  d.axis = axis;
  return d;
}

Color at(const CompiledTexture& t, Vec3 p) { return t.eval(TexturePoint{p}); }

Color at_uv(const CompiledTexture& t, double u, double v) {
  TexturePoint p;
  p.uv = {u, v};
  p.has_uv = true;
  return t.eval(p);
}

void check_color(const Color& got, const Color& want, double margin = 1e-9) {
  INFO("got (" << got.r << ", " << got.g << ", " << got.b << ") want (" << want.r << ", "
               << want.g << ", " << want.b << ")");
  CHECK(got.r == Approx(want.r).margin(margin));
  CHECK(got.g == Approx(want.g).margin(margin));
  CHECK(got.b == Approx(want.b).margin(margin));
}

// 2x2 image: top row red, green; bottom row blue, white.
std::shared_ptr<const Image> quad_image() {
  auto image = std::make_shared<Image>(2, 2);
  auto set = [&](int x, int y, Color c) {
    float* p = image->at(x, y);
    p[0] = static_cast<float>(c.r);
    p[1] = static_cast<float>(c.g);
    p[2] = static_cast<float>(c.b);
  };
  set(0, 0, kRed);
  set(1, 0, kGreen);
  set(0, 1, kBlue);
  set(1, 1, kWhite);
  return image;
}

TextureDesc image_desc(const std::string& mapping) {
  TextureDesc d;
  d.kind = TextureKind::Image;
  d.mapping = mapping;
  d.image_path = "quad.png";
  return d;
}

Color average(Color a, Color b) { return {(a.r + b.r) / 2, (a.g + b.g) / 2, (a.b + b.b) / 2}; }

}  // namespace

TEST_CASE("checker alternates 3D cells of side scale", "[texture]") {
  const CompiledTexture unit(procedural(TextureKind::Checker, 1.0), nullptr);
  check_color(at(unit, {0.5, 0.5, 0.5}), kWhite);   // cell (0,0,0): even
  check_color(at(unit, {1.5, 0.5, 0.5}), kBlack);
  check_color(at(unit, {1.5, 1.5, 0.5}), kWhite);
  check_color(at(unit, {1.5, 1.5, 1.5}), kBlack);
  check_color(at(unit, {-0.5, 0.5, 0.5}), kBlack);  // cell -1: odd
  check_color(at(unit, {-1.5, -0.5, 0.5}), kBlack); // -2 + -1 + 0 = -3: odd

  const CompiledTexture wide(procedural(TextureKind::Checker, 2.0), nullptr);
  check_color(at(wide, {1.5, 0.5, 0.5}), kWhite);
  check_color(at(wide, {2.5, 0.5, 0.5}), kBlack);
}

TEST_CASE("checker on a face boundary does not flicker with rounding noise", "[texture]") {
  const CompiledTexture t(procedural(TextureKind::Checker, 1.0), nullptr);
  // A plane at y = 0: hit points land a hair above or below 0.
  for (double x : {0.25, 0.75, 1.25, -0.25, -3.75}) {
    INFO("x = " << x);
    const Color above = at(t, {x, 1e-12, 0.5});
    const Color below = at(t, {x, -1e-12, 0.5});
    CHECK(above == below);
  }
  // A box face at x = 1 viewed the same way.
  CHECK(at(t, {1.0 - 1e-13, 0.5, 0.5}) == at(t, {1.0 + 1e-13, 0.5, 0.5}));
}

TEST_CASE("stripes are half color1, half color2 per period along the axis", "[texture]") {
  const CompiledTexture x_stripes(procedural(TextureKind::Stripes, 2.0, 0), nullptr);
  check_color(at(x_stripes, {0.5, 9, 9}), kWhite);
  check_color(at(x_stripes, {1.5, 9, 9}), kBlack);
  check_color(at(x_stripes, {2.5, -4, 3}), kWhite);
  check_color(at(x_stripes, {-0.5, 0, 0}), kBlack);
  check_color(at(x_stripes, {-1.5, 0, 0}), kWhite);

  const CompiledTexture y_stripes(procedural(TextureKind::Stripes, 1.0, 1), nullptr);
  check_color(at(y_stripes, {7, 0.25, 0}), kWhite);
  check_color(at(y_stripes, {7, 0.75, 0}), kBlack);
  const CompiledTexture z_stripes(procedural(TextureKind::Stripes, 1.0, 2), nullptr);
  check_color(at(z_stripes, {0.75, 0.75, 0.25}), kWhite);
  check_color(at(z_stripes, {0.25, 0.25, 0.75}), kBlack);
}

TEST_CASE("gradient blends linearly over scale and repeats", "[texture]") {
  TextureDesc d = procedural(TextureKind::Gradient, 4.0, 0);
  d.color1 = kRed;
  d.color2 = kBlue;
  const CompiledTexture t(d, nullptr);
  check_color(at(t, {0, 0, 0}), kRed);
  check_color(at(t, {1, 0, 0}), {0.75, 0, 0.25});
  check_color(at(t, {2, 5, 5}), {0.5, 0, 0.5});
  check_color(at(t, {5, 0, 0}), {0.75, 0, 0.25});    // repeats every 4 units
  check_color(at(t, {-1, 0, 0}), {0.25, 0, 0.75});
  // Smooth inside a period: small steps make small changes.
  for (double x = 0.01; x < 3.9; x += 0.1) {
    CHECK(std::abs(at(t, {x + 0.01, 0, 0}).r - at(t, {x, 0, 0}).r) < 0.01);
  }
  const CompiledTexture along_y(procedural(TextureKind::Gradient, 1.0, 1), nullptr);
  check_color(at(along_y, {3, 0.25, 3}), Color(0.75));
}

TEST_CASE("textures are evaluated at inverse(transform) * point", "[texture]") {
  TextureDesc scaled = procedural(TextureKind::Checker, 1.0);
  scaled.transform = glm::scale(Mat4(1.0), Vec3(2.0));
  const CompiledTexture big(scaled, nullptr);
  check_color(at(big, {1.5, 0.5, 0.5}), kWhite);   // like scale = 2
  check_color(at(big, {2.5, 0.5, 0.5}), kBlack);

  TextureDesc moved = procedural(TextureKind::Stripes, 1.0, 0);
  moved.transform = glm::translate(Mat4(1.0), Vec3(0.5, 0, 0));
  const CompiledTexture shifted(moved, nullptr);
  check_color(at(shifted, {0.75, 0, 0}), kWhite);   // texture x = 0.25
  check_color(at(shifted, {0.25, 0, 0}), kBlack);   // texture x = -0.25

  TextureDesc turned = procedural(TextureKind::Stripes, 1.0, 0);
  turned.transform = glm::rotate(Mat4(1.0), std::numbers::pi / 2, Vec3(0, 0, 1));
  const CompiledTexture rotated(turned, nullptr);   // stripes now run along y
  check_color(at(rotated, {5.3, 0.25, 0}), kWhite); // texture point (0.25, -5.3)
  check_color(at(rotated, {5.3, -0.25, 0}), kBlack); // texture point (-0.25, -5.3)
}

TEST_CASE("image texture: bilinear lookup, v = 0 at the bottom, repeat wrapping", "[texture]") {
  const CompiledTexture t(image_desc("uv"), quad_image());
  // Texel centres give the texels exactly.
  check_color(at_uv(t, 0.25, 0.25), kBlue);    // bottom-left
  check_color(at_uv(t, 0.75, 0.25), kWhite);   // bottom-right
  check_color(at_uv(t, 0.25, 0.75), kRed);     // top-left
  check_color(at_uv(t, 0.75, 0.75), kGreen);   // top-right
  // Half-way between two centres: the average.
  check_color(at_uv(t, 0.5, 0.25), average(kBlue, kWhite));
  check_color(at_uv(t, 0.25, 0.5), average(kBlue, kRed));
  // The edge blends with the opposite edge (repeat).
  check_color(at_uv(t, 0.0, 0.75), average(kRed, kGreen));
  // Repeats outside [0,1).
  check_color(at_uv(t, 1.25, 0.25), kBlue);
  check_color(at_uv(t, -0.75, 2.75), kRed);
  check_color(at_uv(t, 1e9 + 0.25, 0.25), kBlue);
}

TEST_CASE("image mappings: uv falls back to planar, planar uses x and z", "[texture]") {
  const CompiledTexture uv(image_desc("uv"), quad_image());
  check_color(at(uv, {0.75, 123.0, 0.75}), kGreen);   // no UVs: planar x,z
  const CompiledTexture planar(image_desc("planar"), quad_image());
  check_color(at(planar, {0.25, -4.0, 0.25}), kBlue);
  check_color(at(planar, {2.75, 0.0, -0.25}), kGreen);
  // Planar ignores surface UVs.
  TexturePoint p{Vec3(0.25, 0, 0.75)};
  p.uv = {0.75, 0.25};
  p.has_uv = true;
  check_color(planar.eval(p), kRed);
  check_color(uv.eval(p), kWhite);
}

TEST_CASE("spherical mapping: longitude to u, latitude to v", "[texture]") {
  // 4x4 image whose texel (x, y) holds (x/3, y/3, 0.5): the color names the texel.
  auto image = std::make_shared<Image>(4, 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      float* p = image->at(x, y);
      p[0] = static_cast<float>(x) / 3.0f;
      p[1] = static_cast<float>(y) / 3.0f;
      p[2] = 0.5f;
    }
  }
  const CompiledTexture t(image_desc("spherical"), image);
  // Texel (x, y) centre: u = (x + 0.5)/4, v = 1 - (y + 0.5)/4.
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const double u = (x + 0.5) / 4.0, v = 1.0 - (y + 0.5) / 4.0;
      const double longitude = (u - 0.5) * 2.0 * std::numbers::pi;
      const double latitude = (v - 0.5) * std::numbers::pi;
      const double radius = 3.0;   // any distance: only the direction matters
      const Vec3 point = radius * Vec3(std::cos(latitude) * std::cos(longitude),
                                       std::sin(latitude),
                                       std::cos(latitude) * std::sin(longitude));
      INFO("texel " << x << ", " << y);
      check_color(at(t, point), {x / 3.0, y / 3.0, 0.5}, 1e-6);
    }
  }
  // The centre has no direction but still gives a color, never NaN.
  const Color centre = at(t, {0, 0, 0});
  CHECK_FALSE(std::isnan(centre.r));
}

TEST_CASE("image textures need an image and a known mapping", "[texture]") {
  CHECK_THROWS_AS(CompiledTexture(image_desc("uv"), nullptr), RenderError);
  TextureDesc bad = image_desc("cylindrical");
  bad.loc = {"scene.rts", 3, 9};
  try {
    CompiledTexture t(bad, quad_image());
    FAIL("unknown mapping accepted");
  } catch (const RenderError& e) {
    CHECK(e.where.line == 3u);
    CHECK_THAT(std::string(e.what()), Catch::Contains("cylindrical"));
  }
}

TEST_CASE("compile_textures loads images and reports unreadable ones where declared", "[texture]") {
  TempDir dir;
  const std::string path = dir.file("quad.png");
  Image stored(2, 2);
  for (int x = 0; x < 2; ++x) stored.at(x, 1)[2] = 1.0f;   // bottom row blue
  write_png(path, stored);

  SceneDesc scene;
  scene.textures.push_back(procedural(TextureKind::Checker));
  TextureDesc image = image_desc("uv");
  image.image_path = path;
  scene.textures.push_back(image);
  scene.textures.push_back(image);   // the same file twice

  const auto compiled = compile_textures(scene);
  REQUIRE(compiled.size() == 3);
  check_color(at(compiled[0], {0.5, 0.5, 0.5}), kWhite);
  check_color(at_uv(compiled[1], 0.5, 0.25), kBlue, 1e-6);
  check_color(at_uv(compiled[2], 0.5, 0.75), kBlack, 1e-6);

  TextureDesc missing = image_desc("uv");
  missing.image_path = dir.file("nope.png");
  missing.loc = {"textures.rts", 7, 14};
  scene.textures.push_back(missing);
  try {
    compile_textures(scene);
    FAIL("missing image accepted");
  } catch (const RenderError& e) {
    CHECK(std::string(e.where.file) == "textures.rts");
    CHECK(e.where.line == 7u);
    CHECK(e.where.col == 14u);
    CHECK_THAT(std::string(e.what()), Catch::Contains("nope.png"));
  }
}

namespace {
// A 24-bit BMP of w x h grey pixels (rows padded to 4 bytes): a texture that goes through
// stb_image instead of the PNG reader.
void write_bmp(const std::string& path, int w, int h) {
  const int row = (3 * w + 3) / 4 * 4;
  const uint32_t data = static_cast<uint32_t>(row * h), size = 54 + data;
  std::vector<unsigned char> b(size, 0x80);
  auto put32 = [&](std::size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + i] = static_cast<unsigned char>(v >> (8 * i));
  };
  std::fill(b.begin(), b.begin() + 54, 0);
  b[0] = 'B';
  b[1] = 'M';
  put32(2, size);
  put32(10, 54);  // pixel data offset
  put32(14, 40);  // BITMAPINFOHEADER
  put32(18, static_cast<uint32_t>(w));
  put32(22, static_cast<uint32_t>(h));
  b[26] = 1;   // planes
  b[28] = 24;  // bits per pixel
  put32(34, data);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  REQUIRE(f != nullptr);
  REQUIRE(std::fwrite(b.data(), 1, b.size(), f) == b.size());
  std::fclose(f);
}
}  // namespace

TEST_CASE("--max-memory reaches image decoding: PNG and stb formats fail located before decoding", "[texture]") {
  TempDir dir;
  const int side = 512;  // 512x512 decoded: about 4 MiB (bytes and floats per channel)
  const std::string png = dir.file("big.png"), bmp = dir.file("big.bmp");
  write_png(png, Image(side, side));
  write_bmp(bmp, side, side);
  for (const std::string& path : {png, bmp}) {
    SceneDesc scene;
    TextureDesc image = image_desc("uv");
    image.image_path = path;
    image.loc = {"limits.rts", 3, 9};
    scene.textures.push_back(image);
    // No limit, and a limit with room to spare: the image loads.
    REQUIRE(compile_textures(scene, nullptr, 0).size() == 1);
    REQUIRE(compile_textures(scene, nullptr, resident_bytes() + (std::size_t(64) << 20)).size() == 1);
    // 1 MiB above what the process holds now: the decoded image does not fit.
    try {
      compile_textures(scene, nullptr, resident_bytes() + (std::size_t(1) << 20));
      FAIL("image decoded past --max-memory: " << path);
    } catch (const RenderError& e) {
      CHECK(std::string(e.where.file) == "limits.rts");
      CHECK(e.where.line == 3u);
      CHECK_THAT(std::string(e.what()), Catch::Contains("512x512 pixels need") && Catch::Contains("--max-memory"));
    }
  }
}
