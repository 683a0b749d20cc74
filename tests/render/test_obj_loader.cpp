// OBJ loading (render/builder/obj_loader.cpp): the one-pass reader's triangulation, unified vertices,
// relative indices and located errors, checked against hand-computed meshes.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "render/builder/obj_loader.hpp"

using namespace rts::render;

namespace {

std::string write_obj(const std::string& name, const std::string& text) {
  auto path = std::filesystem::temp_directory_path() / ("rts_obj_test_" + name + ".obj");
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

std::string load_error(const std::string& path) {
  try {
    load_obj(path, "m.obj", false, SourceRef{});
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("OBJ quads split along the shorter diagonal; relative indices resolve", "[obj]") {
  // The quad's diagonal 1-3 (length 1.2) is shorter than 0-2 (length ~2.1): triangles
  // (0,1,3) and (1,2,3). Negative indices count back from the last vertex defined.
  std::string path = write_obj("quad", "v 0 0 0\nv 1 0 0\r\nv 1.5 1.5 0\nv 0.2 1 0\n\tf -4 -3 -2 -1  \n");
  auto m = load_obj(path, "m.obj", false, SourceRef{});
  // Unified vertices are numbered in order of first use: file vertex 3 becomes 2, 2 becomes 3.
  REQUIRE(m->indices == std::vector<uint32_t>{0, 1, 2, 1, 3, 2});
  CHECK(m->positions[2] == glm::vec3(0.2f, 1.0f, 0.0f));
  CHECK(m->positions[3] == glm::vec3(1.5f, 1.5f, 0.0f));
  CHECK(m->normals.empty());
  CHECK(m->uvs.empty());
}

TEST_CASE("OBJ corners with different normals or uvs become separate vertices", "[obj]") {
  std::string path = write_obj("unify",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 -1\nvt 0.25\n"
                               "f 1//1 2//1 3//1\nf 1//2 3//2 2//2\nf 1 2 3\n");
  auto m = load_obj(path, "m.obj", true, SourceRef{});
  // First face: vertices 0,1,2; second: three new ones (other normal); third: no normal → new.
  REQUIRE(m->indices == std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8});
  CHECK(m->normals[0] == glm::vec3(0, 0, 1));
  CHECK(m->normals[3] == glm::vec3(0, 0, -1));
  CHECK(m->normals[6] == glm::vec3(0.0f));  // corner without a normal in a file with normals
  CHECK(m->uvs.size() == 9);                // the file has a vt line: every vertex gets a uv
}

TEST_CASE("OBJ polygons of five or more corners are triangulated", "[obj]") {
  std::string path = write_obj("pentagon", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 2 0\nv -1 1 0\nf 1 2 3 4 5\n");
  auto m = load_obj(path, "m.obj", false, SourceRef{});
  CHECK(m->indices.size() == 9);  // three triangles
  CHECK(m->positions.size() == 5);
}

TEST_CASE("OBJ errors name the file's own line", "[obj]") {
  CHECK_THAT(load_error(write_obj("e1", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n")),
             Catch::Contains("m.obj:4: face vertex index 4 out of range (3 defined so far)"));
  CHECK_THAT(load_error(write_obj("e2", "v 0 0 0\nv 1 0\n")), Catch::Contains("m.obj:2: malformed 'v' line: 'v 1 0'"));
  CHECK_THAT(load_error(write_obj("e3", "v 0 0 nan\n")), Catch::Contains("m.obj:1: malformed 'v' line"));
  CHECK_THAT(load_error(write_obj("e4", "v 0 0 1e999\n")), Catch::Contains("m.obj:1: malformed 'v' line"));
  CHECK_THAT(load_error(write_obj("e5", "v 0 0 0\nf 1 1\n")), Catch::Contains("m.obj:2: face with 2 corners"));
  CHECK_THAT(load_error(write_obj("e6", "v 0 0 0\nf 1/x 1 1\n")), Catch::Contains("malformed face index 'x'"));
  CHECK_THAT(load_error(write_obj("e7", "# nothing\nv 0 0 0\n")), Catch::Contains("has no faces"));
  // The last line may lack its newline; a leading '+' is a number as in C++ streams.
  auto m = load_obj(write_obj("ok", "v +1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3"), "m.obj", false, SourceRef{});
  CHECK(m->positions[0].x == 1.0f);
}

TEST_CASE("smooth normals: by area, or each face's unit normal once (MIT a2)", "[obj]") {
  // Two faces meet at vertex 0: a big one in the xy-plane (normal +z, area 8) and a small one in
  // the xz-plane (normal -y, area 0.5).
  MeshData mesh;
  mesh.positions = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, -1}, {1, 0, 0}};
  mesh.indices = {0, 1, 2, 0, 3, 4};
  compute_smooth_normals(mesh);
  const glm::vec3 area = mesh.normals[0];
  // Area-weighted: (0, -1·2·0.5, 1·2·8) normalised = (0, -1, 16) / |..|.
  CHECK(area.y == Approx(-1.0 / std::sqrt(257.0)));
  CHECK(area.z == Approx(16.0 / std::sqrt(257.0)));
  compute_smooth_normals(mesh, true);
  const glm::vec3 equal = mesh.normals[0];
  // Equal weights: (0, -1, 1) / sqrt(2), whatever the areas.
  CHECK(equal.y == Approx(-1.0 / std::sqrt(2.0)));
  CHECK(equal.z == Approx(1.0 / std::sqrt(2.0)));
  CHECK(equal.x == Approx(0.0).margin(1e-7));
  // A vertex of one face only keeps that face's normal either way.
  CHECK(mesh.normals[2].z == Approx(1.0));
}

TEST_CASE("smooth normals of a mesh 1e30 or 1e-30 units wide are the unit mesh's", "[obj][extremes]") {
  // Float cross products of 1e30-long edges overflow (and of 1e-30-long ones lose their
  // digits): the edges are scaled by a power of two first, so the directions are the same.
  auto normals = [](float k, bool equal) {
    MeshData mesh;
    mesh.positions = {{0, 0, 0}, {4 * k, 0, 0}, {0, 4 * k, 0}, {0, 0, -k}, {k, 0, 0}};
    mesh.indices = {0, 1, 2, 0, 3, 4};
    compute_smooth_normals(mesh, equal);
    return mesh.normals;
  };
  for (bool equal : {false, true}) {
    const auto unit = normals(1.0f, equal);
    for (float k : {1e30f, 1e-30f}) {
      CAPTURE(equal, k);
      const auto scaled = normals(k, equal);
      REQUIRE(scaled.size() == unit.size());
      for (std::size_t i = 0; i < unit.size(); ++i) {
        CHECK(scaled[i].x == Approx(unit[i].x).margin(1e-6));
        CHECK(scaled[i].y == Approx(unit[i].y).margin(1e-6));
        CHECK(scaled[i].z == Approx(unit[i].z).margin(1e-6));
      }
    }
  }
}
