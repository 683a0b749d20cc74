// SceneBuilder: categories, validation, SceneDesc contents, meshes (inline and OBJ).
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include <catch2/catch.hpp>

#include "render/builder/scene_builder.hpp"

using namespace rts::render;

namespace {
SourceRef at(uint32_t line, uint32_t col = 1) { return SourceRef{"scene.rts", line, col}; }

std::string scene_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// A scratch folder for OBJ files, removed at the end of the test.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    path = std::filesystem::temp_directory_path() / ("rts_builder_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(path / name) << text;
    return (path / name).string();
  }
};
}  // namespace

TEST_CASE("block kinds have categories", "[builder]") {
  CHECK(SceneBuilder::category("sphere") == BlockCategory::Shape);
  CHECK(SceneBuilder::category("area_light") == BlockCategory::Light);
  CHECK(SceneBuilder::category("checker") == BlockCategory::Texture);
  CHECK(SceneBuilder::category("material") == BlockCategory::Material);
  CHECK(SceneBuilder::category("group") == BlockCategory::Group);
  CHECK(SceneBuilder::category("settings") == BlockCategory::Settings);
  CHECK(SceneBuilder::category("camera") == BlockCategory::Camera);
  CHECK(SceneBuilder::category("shpere") == BlockCategory::Unknown);
  for (std::string_view k : SceneBuilder::block_kinds()) CHECK(SceneBuilder::category(k) != BlockCategory::Unknown);
}

TEST_CASE("a sphere becomes a shape node with its material", "[builder]") {
  SceneBuilder b;
  ParamSet mp("material", at(1));
  mp.add("color", Color(1, 0, 0), at(1, 12));
  mp.add("reflect", 0.5, at(1, 30));
  MaterialId m = b.material(mp);
  ParamSet sp("sphere", at(2));
  sp.add("center", Vec3(1, 2, 3), at(2, 10));
  sp.add("radius", 0.5, at(2, 30));
  sp.add("material", MaterialRef{m}, at(2, 40));
  NodeId n = b.shape("sphere", sp);
  const SceneDesc& s = b.scene();
  REQUIRE(s.nodes.size() == 1);
  CHECK(s.nodes[n].kind == NodeKind::Shape);
  const auto& sphere = shape_get<Sphere>(s.shapes[s.nodes[n].index].geometry);
  CHECK(sphere.center == Vec3(1, 2, 3));
  CHECK(sphere.radius == 0.5);
  CHECK(s.shapes[0].material == m);
  CHECK(s.materials[m].color == Color(1, 0, 0));
  CHECK(s.materials[m].reflect == Color(0.5));
  CHECK(s.roots.empty());  // not placed until place()
  b.place(Child{n, Mat4(1.0), at(3)});
  CHECK(b.scene().roots.size() == 1);
}

TEST_CASE("builder validation messages", "[builder]") {
  SceneBuilder b;
  CHECK(scene_error([&] {
          ParamSet p("sphere", at(1));
          p.add("radius", -1.0, at(1, 10));
          b.shape("sphere", p);
        }) == "property 'radius' of sphere must be > 0, got -1");
  CHECK(scene_error([&] {
          ParamSet p("sphere", at(1));
          b.shape("sphere", p);
        }) == "sphere needs property 'radius'");
  CHECK(scene_error([&] {
          ParamSet p("sphere", at(1));
          p.add("radius", 1.0, at(1, 10));
          p.add("raduis", 1.0, at(1, 20));
          b.shape("sphere", p);
        }) == "unknown property 'raduis' for sphere; did you mean 'radius'? (sphere takes material, center, radius, casts_shadow)");
  CHECK(scene_error([&] {
          ParamSet p("settings", at(1));
          p.add("width", 0.0, at(1, 10));
          b.settings(p);
        }) == "property 'width' of settings must be >= 1, got 0");
  CHECK(scene_error([&] {
          ParamSet p("material", at(1));
          p.add("ior", 0.0, at(1, 10));
          b.material(p);
        }) == "property 'ior' of material must be > 0, got 0");
  CHECK(scene_error([&] {
          ParamSet p("area_light", at(1));
          p.add("position", Vec3(0), at(1, 2));
          p.add("u", Vec3(1, 0, 0), at(1, 3));
          p.add("v", Vec3(0, 0, 1), at(1, 4));
          p.add("samples", 0.0, at(1, 5));
          b.light("area_light", p);
        }) == "property 'samples' of area_light must be >= 1, got 0");
  CHECK(scene_error([&] {
          ParamSet p("area_light", at(1));
          p.add("position", Vec3(0), at(1, 2));
          p.add("u", Vec3(1, 0, 0), at(1, 3));
          p.add("v", Vec3(0, 0, 1), at(1, 4));
          p.add("falloff", 40.0, at(1, 5));
          b.light("area_light", p);
        }) == "property 'falloff' of area_light needs 'point_at' (the spot's axis)");
  {
    // With point_at the area light is a spot: POV-Ray's spotlight with an area_light.
    ParamSet p("area_light", at(1));
    p.add("position", Vec3(0, 5, 0), at(1, 2));
    p.add("u", Vec3(1, 0, 0), at(1, 3));
    p.add("v", Vec3(0, 0, 1), at(1, 4));
    p.add("point_at", Vec3(0), at(1, 5));
    p.add("radius", 20.0, at(1, 6));
    b.light("area_light", p);
    const LightDesc& l = b.scene().lights.back();
    CHECK(l.area_spot);
    CHECK(l.radius == 20.0);
    CHECK(l.falloff == 45.0);
  }
  CHECK(scene_error([&] {
          ParamSet p("point_light", at(1));
          p.add("position", 3.0, at(1, 2));
          b.light("point_light", p);
        }) == "property 'position' of point_light expects a vector, got a number");
}

TEST_CASE("settings and camera fill the scene", "[builder]") {
  SceneBuilder b;
  ParamSet s("settings", at(1));
  s.add("width", 320.0, at(1, 2));
  s.add("background", Color(0.1, 0.2, 0.3), at(1, 3));
  b.settings(s);
  ParamSet c("camera", at(2));
  c.add("position", Vec3(0, 1, -5), at(2, 2));
  c.add("fov", 40.0, at(2, 3));
  b.camera(c);
  CHECK(b.scene().settings.width == 320);
  CHECK(b.scene().settings.height == 480);  // untouched default
  CHECK(b.scene().settings.background == Color(0.1, 0.2, 0.3));
  CHECK(b.scene().has_camera);
  CHECK(b.scene().camera.fov == 40.0);
  CHECK(b.scene().camera.position == Vec3(0, 1, -5));
}

TEST_CASE("material color may be a texture", "[builder]") {
  SceneBuilder b;
  ParamSet t("checker", at(1));
  t.add("color1", Color(1), at(1, 2));
  t.add("scale", 0.5, at(1, 3));
  TextureId tex = b.texture("checker", t);
  ParamSet m("material", at(2));
  m.add("color", TextureRef{tex}, at(2, 2));
  MaterialId mat = b.material(m);
  CHECK(b.scene().materials[mat].texture == tex);
  CHECK(b.scene().textures[tex].scale == 0.5);
}

TEST_CASE("inline meshes check indices and count triangles against the limit", "[builder]") {
  BuilderLimits limits;
  limits.max_mesh_triangles = 1;
  SceneBuilder b(limits);
  auto mesh = [&](std::vector<Vec3> faces) {
    ParamSet p("mesh", at(1));
    p.add("vertices", std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, at(1, 2));
    p.add("faces", std::move(faces), at(1, 3));
    return b.shape("mesh", p);
  };
  NodeId n = mesh({{0, 1, 2}});
  const auto& ref = shape_get<MeshRef>(b.scene().shapes[b.scene().nodes[n].index].geometry);
  const MeshData& data = *b.scene().meshes[ref.mesh];
  CHECK(data.indices == std::vector<uint32_t>{0, 1, 2});
  CHECK(data.normals.size() == 3);  // smooth by default: normals computed
  CHECK(data.normals[0].z == Approx(1.0f));
  CHECK(scene_error([&] { mesh({{0, 1, 3}}); }) == "mesh face index 3 out of range (3 vertices)");
  CHECK_THAT(scene_error([&] { mesh({{0, 1, 2}}); }), Catch::Contains("more than 1 triangles"));
}

TEST_CASE("OBJ meshes load, resolve relative paths and report their own line numbers", "[builder]") {
  TempDir dir;
  dir.write("quad.obj",
            "# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n");
  dir.write("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\n\nf 1 2 7\n");
  dir.write("bad_vertex.obj", "v 0 0 0\nv 1 zero 0\n");
  std::string scene_file = (dir.path / "scene.rts").string();
  SceneBuilder b;
  auto load = [&](const std::string& file) {
    ParamSet p("mesh", SourceRef{scene_file.c_str(), 4, 1});
    p.add("file", file, SourceRef{scene_file.c_str(), 4, 8});
    return b.shape("mesh", p);
  };
  NodeId n = load("quad.obj");  // relative to the scene file's folder
  const auto& ref = shape_get<MeshRef>(b.scene().shapes[b.scene().nodes[n].index].geometry);
  const MeshData& m = *b.scene().meshes[ref.mesh];
  CHECK(m.indices.size() == 6);  // triangulated
  CHECK(m.positions.size() == 4);
  CHECK(m.uvs.size() == 4);
  CHECK(m.normals.size() == 4);  // computed: smooth = true by default
  CHECK_THAT(scene_error([&] { load("bad_index.obj"); }),
             Catch::Contains("malformed mesh file bad_index.obj:5:") && Catch::Contains("out of range"));
  CHECK_THAT(scene_error([&] { load("bad_vertex.obj"); }), Catch::Contains("bad_vertex.obj:2:"));
  CHECK_THAT(scene_error([&] { load("missing.obj"); }),
             Catch::Contains("missing.obj") && Catch::Contains("no such file"));
}

TEST_CASE("an OBJ file named by many mesh statements is loaded once and shared", "[builder]") {
  TempDir dir;
  dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::filesystem::create_directories(dir.path / "sub");
  std::string scene_file = (dir.path / "scene.rts").string();
  BuilderLimits limits;
  limits.max_mesh_triangles = 3;  // shared data counts once against the limit
  SceneBuilder b(limits);
  auto load = [&](const std::string& file, std::optional<bool> smooth = {}) {
    ParamSet p("mesh", SourceRef{scene_file.c_str(), 4, 1});
    p.add("file", file, SourceRef{scene_file.c_str(), 4, 8});
    if (smooth) p.add("smooth", *smooth, SourceRef{scene_file.c_str(), 4, 30});
    NodeId n = b.shape("mesh", p);
    return shape_get<MeshRef>(b.scene().shapes[b.scene().nodes[n].index].geometry);
  };
  for (int i = 0; i < 100; ++i) CHECK(load("tri.obj").mesh == 0);
  CHECK(load("sub/../tri.obj").mesh == 0);   // the same file spelled differently
  CHECK(load(dir.path / "tri.obj").mesh == 0);  // and absolute
  CHECK(b.scene().meshes.size() == 1);
  CHECK(b.scene().shapes.size() == 102);
  // smooth = false builds different data (no computed normals): its own entry.
  MeshRef flat = load("tri.obj", false);
  CHECK(flat.mesh == 1);
  CHECK_FALSE(flat.smooth);
  CHECK(b.scene().meshes[1]->normals.empty());
  CHECK(b.scene().meshes[0]->normals.size() == 3);
  CHECK(load("tri.obj", false).mesh == 1);
  CHECK(b.scene().meshes.size() == 2);
}

TEST_CASE("groups and dumps", "[builder]") {
  SceneBuilder b;
  ParamSet p("sphere", at(1));
  p.add("radius", 1.0, at(1, 2));
  NodeId s = b.shape("sphere", p);
  Mat4 t(1.0);
  t[3] = glm::dvec4(2, 0, 0, 1);
  NodeId g = b.group({Child{s, Mat4(1.0), at(2)}, Child{s, t, at(3)}}, at(2));
  b.place(Child{g, Mat4(1.0), at(4)});
  std::ostringstream out;
  b.scene().dump(out);
  std::string d = out.str();
  CHECK_THAT(d, Catch::Contains("node 0: sphere center <0, 0, 0> radius 1 material none @scene.rts:1:1"));
  CHECK_THAT(d, Catch::Contains("node 1: group children 2"));
  CHECK_THAT(d, Catch::Contains("child node 0 transform [1 0 0 2; 0 1 0 0; 0 0 1 0]"));
  CHECK_THAT(d, Catch::Contains("root node 1 transform identity"));
}
