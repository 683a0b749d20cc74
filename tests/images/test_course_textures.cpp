// Texture files and environment maps (issue 11, items 6 and 8): BMP and JPEG read as PNG does,
// color spaces, nearest filtering, cube-map faces and their orientation, latitude-longitude
// lookups. Assets: tests/golden/images/assets/make_course_assets.py.
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "render/shade/texture.hpp"

using namespace rts::render;

namespace {

const std::string kAssets = std::string(RTS_SOURCE_DIR) + "/tests/golden/images/assets/";

void check_color(const Color& got, const Color& want, double margin) {
  INFO("got (" << got.r << ", " << got.g << ", " << got.b << ") want (" << want.r << ", " << want.g << ", "
               << want.b << ")");
  CHECK(got.r == Approx(want.r).margin(margin));
  CHECK(got.g == Approx(want.g).margin(margin));
  CHECK(got.b == Approx(want.b).margin(margin));
}

Color pixel(const Image& image, int x, int y) {
  const float* p = image.at(x, y);
  return Color(p[0], p[1], p[2]);
}

TextureDesc file_texture(TextureKind kind, const std::string& file) {
  TextureDesc d;
  d.kind = kind;
  d.image_path = kAssets + file;
  return d;
}

CompiledTexture compile_one(const TextureDesc& d) {
  SceneDesc scene;
  scene.textures.push_back(d);
  return compile_textures(scene).at(0);
}

TextureDesc cube(const std::string& dir, const std::string (&names)[6], const std::string& ext) {
  TextureDesc d;
  d.kind = TextureKind::CubeMap;
  for (const std::string& n : names) d.face_paths.push_back(kAssets + dir + "/" + n + ext);
  return d;
}

const std::string kGlNames[6] = {"posx", "negx", "posy", "negy", "posz", "negz"};
const std::string kMitNames[6] = {"right", "left", "up", "down", "front", "back"};
const Color kRed{1, 0, 0}, kCyan{0, 1, 1}, kGreen{0, 1, 0}, kMagenta{1, 0, 1}, kBlue{0, 0, 1}, kYellow{1, 1, 0};

}  // namespace

TEST_CASE("BMP and JPEG files read as the same picture as the PNG", "[texture][files]") {
  const Image png = read_image(kAssets + "tile4.png");
  const Image bmp = read_image(kAssets + "tile4.bmp");
  const Image jpg = read_image(kAssets + "tile4.jpg");
  REQUIRE(bmp.width == 16);
  REQUIRE(jpg.height == 16);
  for (int y : {2, 13})
    for (int x : {2, 13}) {
      check_color(pixel(bmp, x, y), pixel(png, x, y), 0.0);   // lossless: exact
      check_color(pixel(jpg, x, y), pixel(png, x, y), 0.03);  // quality 100, away from edges
    }
  check_color(pixel(png, 2, 2), Color(1, 0, 0), 0.0);          // top-left red, top row first
  check_color(pixel(png, 13, 13), Color(1, 1, 1), 0.0);
}

TEST_CASE("a file that is no image is a located error, not a crash", "[texture][files]") {
  CHECK_THROWS_AS(read_image(kAssets + "ball.obj"), RenderError);
  CHECK_THROWS_AS(read_image(kAssets + "missing.bmp"), RenderError);
}

TEST_CASE("color_space linear keeps the stored values; srgb decodes them", "[texture][files]") {
  // tilt.png's green channel is 128 everywhere.
  const Image srgb = read_image(kAssets + "tilt.png", {}, Encoding::SRGB);
  const Image linear = read_image(kAssets + "tilt.png", {}, Encoding::Linear);
  CHECK(linear.at(0, 0)[1] == Approx(128.0 / 255.0).margin(1e-6));
  CHECK(srgb.at(0, 0)[1] == Approx(srgb_to_linear(128.0f / 255.0f)).margin(1e-6));
  TextureDesc d = file_texture(TextureKind::Image, "tilt.png");
  d.linear = true;
  TexturePoint p;
  p.has_uv = true;
  p.uv = {0.25, 0.5};
  CHECK(compile_one(d).eval(p).g == Approx(128.0 / 255.0).margin(1e-6));
}

TEST_CASE("nearest filtering returns texels; bilinear blends at a texel edge", "[texture][files]") {
  TextureDesc d = file_texture(TextureKind::Image, "tile4.png");
  TexturePoint p;
  p.has_uv = true;
  p.uv = {0.5, 0.75};   // on the red/green edge of the top half
  const Color blended = compile_one(d).eval(p);
  CHECK(blended.r == Approx(0.5).margin(1e-6));
  CHECK(blended.g == Approx(0.5).margin(1e-6));
  d.filter = TextureFilter::Nearest;
  p.uv = {0.49, 0.75};
  check_color(compile_one(d).eval(p), kRed, 0.0);
  p.uv = {0.51, 0.75};
  check_color(compile_one(d).eval(p), kGreen, 0.0);
}

TEST_CASE("a cube map shows each face along its axis, upright and unmirrored", "[texture][environment]") {
  for (const auto* names : {&kGlNames, &kMitNames}) {
    const bool mit = names == &kMitNames;
    const CompiledTexture env = compile_one(cube(mit ? "cube_mit" : "cube", *names, mit ? ".bmp" : ".png"));
    REQUIRE(env.is_environment());
    check_color(env.eval_direction({1, 0, 0}), kRed, 1e-6);
    check_color(env.eval_direction({-3, 0, 0}), kCyan, 1e-6);   // length does not matter
    check_color(env.eval_direction({0, 1, 0}), kGreen, 1e-6);
    check_color(env.eval_direction({0, -1, 0}), kMagenta, 1e-6);
    check_color(env.eval_direction({0, 0, 1}), kBlue, 1e-6);
    check_color(env.eval_direction({0, 0, -1}), kYellow, 1e-6);
    // Each face's white marker is its image's top-left corner, as seen from inside the cube
    // in rts's left-handed view (right = cross(up, forward)).
    const Color white(1.0);
    check_color(env.eval_direction({-0.8, 0.8, 1}), white, 1e-6);    // front: left is -x
    check_color(env.eval_direction({0.8, 0.8, -1}), white, 1e-6);    // back: left is +x
    check_color(env.eval_direction({1, 0.8, 0.8}), white, 1e-6);     // right (+x): left is +z
    check_color(env.eval_direction({-1, 0.8, -0.8}), white, 1e-6);   // left (-x): left is -z
    check_color(env.eval_direction({-0.8, 1, -0.8}), white, 1e-6);   // up: top edge meets the back
    check_color(env.eval_direction({-0.8, -1, 0.8}), white, 1e-6);   // down: top edge meets the front
    check_color(env.eval_direction({0.8, 0.8, 1}), kBlue, 1e-6);     // the other corners are not
  }
}

TEST_CASE("a cube map with orientation mit reads the faces as MIT 6.837 a2 does", "[texture][environment]") {
  TextureDesc d = cube("cube_mit", kMitNames, ".bmp");
  d.cube_mit = true;
  const CompiledTexture env = compile_one(d);
  // The same face along each axis...
  check_color(env.eval_direction({1, 0, 0}), kRed, 1e-6);
  check_color(env.eval_direction({0, 1, 0}), kGreen, 1e-6);
  check_color(env.eval_direction({0, 0, 1}), kBlue, 1e-6);
  // ...but a2's texel lookup: u = (z/x + 1)/2 on right, (z/x + 1)/2 on left (x < 0), v = (z/y + 1)/2
  // on up, u = 1 - (x/z + 1)/2 on front; back and down as rts's. The white marker is each
  // image's top-left corner (u = 0, v = 1).
  const Color white(1.0);
  check_color(env.eval_direction({0.8, 0.8, 1}), white, 1e-6);     // front: mirrored left-right
  check_color(env.eval_direction({0.8, 0.8, -1}), white, 1e-6);    // back: as rts's
  check_color(env.eval_direction({1, 0.8, -0.8}), white, 1e-6);    // right: mirrored
  check_color(env.eval_direction({-1, 0.8, 0.8}), white, 1e-6);    // left: mirrored
  check_color(env.eval_direction({-0.8, 1, 0.8}), white, 1e-6);    // up: mirrored top-bottom
  check_color(env.eval_direction({-0.8, -1, 0.8}), white, 1e-6);   // down: as rts's
  check_color(env.eval_direction({-0.8, 0.8, 1}), kBlue, 1e-6);    // rts's front corner is not
}

TEST_CASE("a latitude-longitude map: +z at the centre column, +x to its right, +y at the top",
          "[texture][environment]") {
  const CompiledTexture env = compile_one(file_texture(TextureKind::LatLong, "bands.png"));
  // Longitude bands in quarters of u: red, green, blue, yellow; u = 0.5 looks along +z.
  check_color(env.eval_direction({-1, 0, 1}), kGreen, 1e-6);    // u = 0.375
  check_color(env.eval_direction({1, 0, 1}), kBlue, 1e-6);      // u = 0.625
  check_color(env.eval_direction({1, 0, -1}), kYellow, 1e-6);   // u = 0.875
  check_color(env.eval_direction({-1, 0, -1}), kRed, 1e-6);     // u = 0.125
  check_color(env.eval_direction({0, 1, 0}), Color(1.0), 1e-6);  // the pole, clamped to the top row
  const float grey = srgb_to_linear(40.0f / 255.0f);
  check_color(env.eval_direction({0.2, -1, 0.1}), Color(grey), 1e-6);
  check_color(env.eval_direction({0, 0, 0}), env.eval_direction({0, 0, 0}), 0.0);   // no NaN
}
