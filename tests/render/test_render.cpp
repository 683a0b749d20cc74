// Whole renders of small scenes: determinism whatever the thread count, seeds, NaN guards,
// statistics, AOVs, and render errors.
#include <cmath>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include <catch2/catch.hpp>

#include "render/image/image.hpp"
#include "render/renderer.hpp"
#include "scene_fixture.hpp"

using namespace rts::render;
using namespace rts::render::test;

namespace {

// Exercises every sampled dimension: stratified AA, an area light, glossy reflection, depth of
// field, refraction.
SceneDesc sampled_scene() {
  SceneDesc s;
  s.settings.width = 40;
  s.settings.height = 30;
  s.settings.samples = 4;
  s.settings.seed = 7;
  s.has_camera = true;
  s.camera.position = Vec3(0, 1, -6);
  s.camera.look_at = Vec3(0, 0.5, 0);
  s.camera.aperture = 0.2;
  MaterialDesc floor;
  floor.color = Color(0.7, 0.6, 0.5);
  floor.reflect = Color(0.3);
  floor.roughness = 0.2;
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, add_material(s, floor)));
  MaterialDesc glass;
  glass.transmit = Color(0.9);
  glass.ior = 1.5;
  glass.fresnel = true;
  glass.diffuse = 0.1;
  place(s, add_shape(s, Sphere{Vec3(0, 1, 0), 1.0}, add_material(s, glass)));
  MaterialDesc red;
  red.color = Color(0.9, 0.1, 0.1);
  red.specular = 0.5;
  place(s, add_shape(s, Box{Vec3(-0.5), Vec3(0.5)}, add_material(s, red)),
        translate(Vec3(2, 0.5, 1)) * rotate_deg(30, Vec3(0, 1, 0)));
  place(s, add_shape(s, Cylinder{Vec3(0), Vec3(0, 1.5, 0), 0.3, true}), translate(Vec3(-2, 0, 1)));
  LightDesc area;
  area.kind = LightKind::Area;
  area.position = Vec3(0, 6, -2);
  area.u = Vec3(2, 0, 0);
  area.v = Vec3(0, 0, 2);
  area.samples = 4;
  place(s, add_light(s, area));
  return s;
}

RenderResult render_with(const SceneDesc& s, int threads, std::optional<uint64_t> seed = {}) {
  RenderOptions o;
  o.threads = threads;
  o.seed = seed;
  return render(s, o);
}

bool all_finite(const Image& img) {
  for (float v : img.rgb)
    if (!std::isfinite(v)) return false;
  return true;
}

// An orthographic view straight down onto the y = 0 plane (+z up in the image), `view_width`
// units across.
// Adds `t` to the scene and a material that shows it unlit (ambient 1, no other light).
MaterialId unlit_texture_material(SceneDesc& s, const TextureDesc& t) {
  s.textures.push_back(t);
  MaterialDesc m = emissive(Color(0));
  m.ambient = 1;
  m.texture = static_cast<TextureId>(s.textures.size() - 1);
  return add_material(s, m);
}

}  // namespace

TEST_CASE("the image is identical whatever the thread count", "[render]") {
  SceneDesc s = sampled_scene();
  RenderResult one = render_with(s, 1), two = render_with(s, 2), four = render_with(s, 4);
  CHECK(one.color.rgb == two.color.rgb);
  CHECK(one.color.rgb == four.color.rgb);
  CHECK(one.stats.pixels.variance == four.stats.pixels.variance);
  CHECK(one.stats.rays.total() == four.stats.rays.total());
}

TEST_CASE("a different seed gives a different image; the same seed the same", "[render]") {
  SceneDesc s = sampled_scene();
  RenderResult a = render_with(s, 2), b = render_with(s, 2, 8), c = render_with(s, 2, 7);
  CHECK(a.color.rgb != b.color.rgb);
  CHECK(a.color.rgb == c.color.rgb);  // settings.seed is 7
}

TEST_CASE("ray counters and per-pixel statistics are filled in", "[render]") {
  SceneDesc s = sampled_scene();
  RenderResult r = render_with(s, 2);
  const RenderStats& st = r.stats;
  CHECK(st.rays.camera == 40u * 30u * 4u);
  CHECK(st.rays.shadow > 0);
  CHECK(st.rays.reflection > 0);
  CHECK(st.rays.refraction > 0);
  CHECK(st.rays.nan_samples == 0);
  CHECK(st.pixels.variance.size() == 40u * 30u * 3u);
  CHECK(st.error.known);
  CHECK(st.error.rmse > 0.0);
  CHECK(st.summary().find("40x30, 4 spp") != std::string::npos);
}

TEST_CASE("a 1-spp render keeps no per-pixel variances: there is no estimate to keep", "[render]") {
  SceneDesc s = sampled_scene();
  s.settings.samples = 1;
  RenderResult r = render(s, RenderOptions{});
  CHECK(r.stats.pixels.variance.empty());
  CHECK(r.stats.pixels.taken.size() == 40u * 30u);
  CHECK_FALSE(r.stats.error.known);
  CHECK(r.stats.error.max_spp == 1);
  // The error AOVs still come: zeros, and the error map's grey "unknown".
  RenderOptions o;
  o.aovs = {"error", "error_map"};
  RenderResult a = render(s, o);
  CHECK(a.aovs.at("error").rgb[0] == 0.0f);
  CHECK(a.aovs.at("error_map").rgb[0] == Approx(0.5f));
  CHECK(a.color.rgb == r.color.rgb);
}

TEST_CASE("error statistics: a flat background has zero variance and an exact value", "[render]") {
  SceneDesc s;
  s.settings.width = 8;
  s.settings.height = 8;
  s.settings.samples = 9;
  s.settings.background = Color(0.5, 0.5, 0.5);
  RenderResult r = render_with(s, 1);
  for (std::size_t i = 0; i < r.stats.pixels.variance.size(); ++i) {
    CHECK(r.color.rgb[i] == Approx(0.5));
    CHECK(r.stats.pixels.variance[i] == Approx(0.0).margin(1e-12));
  }
  CHECK(r.stats.error.known);
  CHECK(r.stats.error.rmse == Approx(0.0).margin(1e-9));
}

TEST_CASE("degenerate geometry never produces NaN pixels", "[render]") {
  SceneDesc s;
  s.settings.width = 24;
  s.settings.height = 24;
  s.settings.samples = 4;
  s.has_camera = true;
  s.camera.position = Vec3(0, 0, -4);
  MaterialDesc shiny;
  shiny.reflect = Color(0.5);
  shiny.transmit = Color(0.5);
  shiny.ior = 1.3;
  shiny.specular = 1.0;
  shiny.roughness = 0.1;
  MaterialId m = add_material(s, shiny);
  place(s, add_shape(s, triangle(Vec3(0), Vec3(1, 1, 0), Vec3(2, 2, 0)), m));        // zero area
  place(s, add_shape(s, triangle(Vec3(0.5), Vec3(0.5), Vec3(0.5)), m));               // a point
  place(s, add_shape(s, Sphere{Vec3(0), 0.0}, m));                                    // zero radius
  place(s, add_shape(s, Cylinder{Vec3(0), Vec3(0), 1.0, true}, m));                   // zero length
  place(s, add_shape(s, Cone{Vec3(0), Vec3(0, 1, 0), 0.0, 0.0, true}, m));            // zero radii
  place(s, add_shape(s, Disc{Vec3(0), Vec3(0), 1.0, 0.0}, m));                        // no normal
  place(s, add_shape(s, Plane{Vec3(0), 0.0}, m));                                     // no normal
  // (a flattened instance, scale <1, 0, 1>, is a render error: see test_extremes.cpp)
  place(s, add_shape(s, Box{Vec3(-0.5), Vec3(0.5)}, m), translate(Vec3(1, 0, 0)));
  auto mesh = std::make_shared<MeshData>();
  mesh->positions = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}};
  mesh->normals = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};  // zero normals
  mesh->indices = {0, 1, 2, 0, 1, 7};                // degenerate, and out of range
  s.meshes.push_back(mesh);
  place(s, add_shape(s, MeshRef{0, true}, m));
  LightDesc l;
  l.position = Vec3(0);  // a light inside the geometry, at a degenerate spot
  l.attenuation = Vec3(0, 0, 0);
  place(s, add_light(s, l));
  LightDesc spot;
  spot.kind = LightKind::Spot;
  spot.position = Vec3(0, 3, 0);
  spot.point_at = Vec3(0, 3, 0);  // no direction
  place(s, add_light(s, spot));
  RenderResult r = render_with(s, 2);
  CHECK(all_finite(r.color));
  CHECK(r.stats.rays.nan_samples == 0);
}

TEST_CASE("AOVs: normal, depth and albedo images", "[render]") {
  SceneDesc s;
  s.settings.width = 16;
  s.settings.height = 16;
  s.has_camera = true;
  s.camera.position = Vec3(0, 0, -5);
  s.camera.fov = 30;
  MaterialDesc m;
  m.color = Color(0.25, 0.5, 0.75);
  place(s, add_shape(s, Sphere{Vec3(0), 1.0}, add_material(s, m)));
  RenderOptions o;
  o.aovs = {"normal", "depth", "albedo"};
  RenderResult r = render(s, o);
  REQUIRE(r.aovs.count("normal"));
  REQUIRE(r.aovs.count("depth"));
  REQUIRE(r.aovs.count("albedo"));
  const float* centre_n = r.aovs["normal"].at(8, 8);
  CHECK(centre_n[2] < 0.1f);   // facing the camera: n ~ (0,0,-1) → blue ~ 0
  CHECK(centre_n[0] == Approx(0.5).margin(0.1));
  const float* corner_d = r.aovs["depth"].at(0, 0);
  CHECK(corner_d[0] == 0.0f);  // background
  float centre_d = r.aovs["depth"].at(8, 8)[0];
  CHECK(centre_d > 0.0f);
  CHECK(centre_d <= 1.0f);
  float max_d = 0;
  for (float v : r.aovs["depth"].rgb) max_d = std::max(max_d, v);
  CHECK(max_d == 1.0f);  // normalised by the farthest finite depth
  CHECK(r.aovs["albedo"].at(8, 8)[1] == Approx(0.5));
}

TEST_CASE("depth AOV: a visible infinite plane does not squash bounded geometry to black", "[render]") {
  // A floor running to the horizon has enormous depths near it; scaling by the farthest hit
  // left the sphere (about 5 units away) at a few percent of gray.
  SceneDesc s;
  s.settings.width = 48;
  s.settings.height = 36;
  s.has_camera = true;
  s.camera.position = Vec3(0, 1, -5);
  s.camera.look_at = Vec3(0, 0.5, 0);
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}));
  place(s, add_shape(s, Sphere{Vec3(0, 0.5, 0), 0.5}));
  RenderOptions o;
  o.aovs = {"depth"};
  RenderResult r = render(s, o);
  const Image& d = r.aovs["depth"];
  // The sphere's centre pixel: ~4.6 units away; the farthest bounded hit is < 5.6.
  float sphere = d.at(24, 18)[0];
  CHECK(sphere > 0.75f);
  CHECK(sphere < 1.0f);
  float max_d = 0;
  for (float v : d.rgb) {
    CHECK(v >= 0.0f);
    max_d = std::max(max_d, v);
  }
  CHECK(max_d == 1.0f);  // the far floor clamps to white
  CHECK(d.at(0, 0)[0] == 0.0f);  // the sky above the horizon: nothing hit

  SECTION("only the plane in view: scaled by the 99th percentile, not the horizon") {
    SceneDesc p;
    p.settings.width = 48;
    p.settings.height = 36;
    p.has_camera = true;
    p.camera.position = Vec3(0, 1, -5);
    p.camera.look_at = Vec3(0, 0.5, 0);
    place(p, add_shape(p, Plane{Vec3(0, 1, 0), 0.0}));
    RenderResult rp = render(p, o);
    const Image& dp = rp.aovs["depth"];
    // Near the horizon the top 1% of depths clamp to white; nearer floor is a gradient.
    std::size_t hits = 0, white = 0;
    for (std::size_t i = 0; i < dp.rgb.size(); i += 3) {
      hits += dp.rgb[i] > 0.0f;
      white += dp.rgb[i] == 1.0f;
    }
    REQUIRE(hits > 0);
    CHECK(white * 100 >= hits);
    CHECK(white * 100 <= hits * 2);
    CHECK(dp.at(24, 35)[0] > 0.0f);
    CHECK(dp.at(24, 35)[0] < dp.at(24, 20)[0]);
  }
}

TEST_CASE("render errors: oversize image, bad settings, unknown AOV", "[render]") {
  static const char* kFile = "scene.rts";
  SceneDesc s;
  s.settings.loc = SourceRef{kFile, 3, 1};
  RenderOptions o;
  o.width = 2000;
  o.height = 2000;
  o.max_pixels = 1'000'000;
  try {
    render(s, o);
    FAIL("expected a RenderError");
  } catch (const RenderError& e) {
    CHECK(std::string(e.what()).find("exceeds the limit") != std::string::npos);
    CHECK(e.where.line == 3);
  }
  RenderOptions zero;
  zero.width = 0;
  CHECK_THROWS_AS(render(s, zero), RenderError);
  RenderOptions aov;
  aov.width = aov.height = 4;
  aov.aovs = {"bogus"};
  CHECK_THROWS_AS(render(s, aov), RenderError);
}

TEST_CASE("an unreadable texture image is a located render error", "[render]") {
  static const char* kFile = "tex.rts";
  SceneDesc s;
  s.settings.width = s.settings.height = 4;
  TextureDesc t;
  t.kind = TextureKind::Image;
  t.image_path = "/nonexistent/texture.png";
  t.loc = SourceRef{kFile, 7, 5};
  s.textures.push_back(t);
  MaterialDesc m;
  m.texture = 0;
  place(s, add_shape(s, Sphere{}, add_material(s, m)));
  try {
    render(s, RenderOptions{});
    FAIL("expected a RenderError");
  } catch (const RenderError& e) {
    CHECK(e.where.line == 7);
    CHECK(std::string(e.where.file) == kFile);
  }
}

TEST_CASE("textures color the surface: checker on a plane", "[render]") {
  SceneDesc s = top_down_scene(32, 32, 4);
  TextureDesc t;
  t.kind = TextureKind::Checker;
  t.color1 = Color(1, 0, 0);
  t.color2 = Color(0, 0, 1);
  t.scale = 1.0;
  place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, unlit_texture_material(s, t)));
  RenderResult r = render(s, RenderOptions{});
  // Neighbouring cells (one unit = 8 pixels apart) have opposite colors.
  const float* a = r.color.at(4, 4);
  const float* b = r.color.at(12, 4);
  CHECK((a[0] > 0.5f) != (b[0] > 0.5f));
  CHECK((a[2] > 0.5f) != (b[2] > 0.5f));
}

TEST_CASE("write_png replaces a file only when the write succeeds", "[render]") {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "rts_render_atomic_test";
  fs::create_directories(dir);
  fs::path out = dir / "out.png";
  {
    std::ofstream(out) << "old contents";
  }
  Image img(4, 4);
  // An unsupported bit depth fails: the old file must be untouched, no temp file left.
  CHECK_THROWS_AS(write_png(out.string(), img, 12), RenderError);
  std::ifstream in(out);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text == "old contents");
  int files = 0;
  for ([[maybe_unused]] auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 1);
  // Into a missing directory: an error, nothing created.
  CHECK_THROWS_AS(write_png((dir / "missing" / "x.png").string(), img), RenderError);
  CHECK_FALSE(fs::exists(dir / "missing"));
  // A successful write replaces it with a PNG of the right size.
  write_png(out.string(), img, 8);
  Image back = read_png(out.string());
  CHECK(back.width == 4);
  fs::remove_all(dir);
}

TEST_CASE("procedural textures move with their object's transform", "[render]") {
  // A checkered plane seen from above; translating the plane by half a cell in x moves the
  // cell boundaries by half a cell in the image (the texture lives in object space).
  auto render_plane = [](double shift) {
    SceneDesc s = top_down_scene(64, 8, 8);  // 8 pixels per unit
    TextureDesc t;
    t.kind = TextureKind::Checker;
    t.color1 = Color(1, 1, 1);
    t.color2 = Color(0, 0, 0);
    place(s, add_shape(s, Plane{Vec3(0, 1, 0), 0.0}, unlit_texture_material(s, t)), translate(Vec3(shift, 0, 0)));
    RenderResult r = render(s, RenderOptions{});
    std::vector<bool> row;
    for (int x = 0; x < 64; ++x) row.push_back(r.color.at(x, 4)[0] > 0.5f);
    return row;
  };
  std::vector<bool> base = render_plane(0.0), shifted = render_plane(0.5);
  int changes = 0;
  for (int x = 0; x < 64; ++x) changes += base[x] != shifted[x];
  CHECK(changes == 32);  // half of every cell flips
  for (int x = 4; x < 64; ++x) CHECK(shifted[x] == base[x - 4]);  // moved by 4 pixels
}

TEST_CASE("image textures use the mesh's UVs", "[render]") {
  namespace fs = std::filesystem;
  fs::path png = fs::temp_directory_path() / "rts_render_uv_test.png";
  Image tex(2, 2);  // top row red, green; bottom row blue, white (v = 0 is the bottom row)
  const float colors[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) tex.at(i % 2, i / 2)[c] = colors[i][c];
  write_png(png.string(), tex, 8, Encoding::Linear);

  auto mesh = std::make_shared<MeshData>();
  mesh->positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  mesh->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh->indices = {0, 1, 2, 0, 2, 3};
  SceneDesc s;
  s.meshes.push_back(mesh);
  s.settings.width = s.settings.height = 16;
  s.has_camera = true;
  s.camera.projection = Projection::Orthographic;
  s.camera.position = Vec3(0, 0, -5);
  s.camera.view_width = 2;
  TextureDesc t;
  t.kind = TextureKind::Image;
  t.image_path = png.string();
  place(s, add_shape(s, MeshRef{0, true}, unlit_texture_material(s, t)));
  RenderResult r = render(s, RenderOptions{});
  fs::remove(png);
  // Sample well inside each quadrant (bilinear filtering blends near the centre lines).
  auto dominant = [&](int x, int y) {
    const float* p = r.color.at(x, y);
    return std::array<bool, 3>{p[0] > 0.5f, p[1] > 0.5f, p[2] > 0.5f};
  };
  CHECK(dominant(1, 1) == std::array<bool, 3>{true, false, false});    // top left: red
  CHECK(dominant(14, 1) == std::array<bool, 3>{false, true, false});   // top right: green
  CHECK(dominant(1, 14) == std::array<bool, 3>{false, false, true});   // bottom left: blue
  CHECK(dominant(14, 14) == std::array<bool, 3>{true, true, true});    // bottom right: white
}
