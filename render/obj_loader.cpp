#include "render/obj_loader.hpp"

#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include "render/source_ref.hpp"

namespace rts::render {

namespace {

// Normals shorter than this (degenerate triangles only) are left as they are.
constexpr float kMinNormalLength = 1e-20f;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Parses one OBJ index ("12", "-1"); false when it is not an integer.
bool parse_index(std::string_view s, long& out) {
  auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// tinyobjloader skips or clamps bad data silently, so check what it cannot report with a line:
// unparsable vertex coordinates and face indices that point outside the arrays so far.
// Returns whether any vertex carries a color (`v x y z r g b`, a common OBJ extension).
bool prescan(const std::string& shown, std::istream& in, SourceRef where) {
  bool colors = false;
  std::size_t counts[3] = {0, 0, 0};  // v, vt, vn
  std::string line;
  unsigned line_no = 0;
  auto fail = [&](const std::string& msg) {
    throw SceneError(where, fmt::format("malformed mesh file {}:{}: {}", shown, line_no, msg));
  };
  while (std::getline(in, line)) {
    ++line_no;
    std::string_view s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    std::size_t sp = s.find_first_of(" \t");
    std::string_view tag = s.substr(0, sp);
    std::string_view rest = sp == std::string_view::npos ? std::string_view() : trim(s.substr(sp));
    if (tag == "v" || tag == "vt" || tag == "vn") {
      std::istringstream fields{std::string(rest)};
      double x;
      int n = 0;
      while (fields >> x) ++n;
      int need = tag == "vt" ? 1 : 3;
      if (n < need || !fields.eof()) fail(fmt::format("malformed '{}' line: '{}'", tag, s));
      if (tag == "v" && n >= 6) colors = true;
      ++counts[tag == "v" ? 0 : tag == "vt" ? 1 : 2];
    } else if (tag == "f") {
      int corners = 0;
      while (!rest.empty()) {
        std::size_t end = rest.find_first_of(" \t");
        std::string_view corner = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view() : trim(rest.substr(end));
        ++corners;
        for (int k = 0; k < 3 && !corner.empty(); ++k) {
          std::size_t slash = corner.find('/');
          std::string_view part = corner.substr(0, slash);
          corner = slash == std::string_view::npos ? std::string_view() : corner.substr(slash + 1);
          if (part.empty() && k > 0) continue;  // "1//3": no texture coordinate
          long idx;
          if (!parse_index(part, idx) || idx == 0) fail(fmt::format("malformed face index '{}'", part));
          long n = static_cast<long>(counts[k]);
          long resolved = idx > 0 ? idx : n + idx + 1;
          if (resolved < 1 || resolved > n) {
            static const char* what[3] = {"vertex", "texture coordinate", "normal"};
            fail(fmt::format("face {} index {} out of range ({} defined so far)", what[k], idx, n));
          }
        }
      }
      if (corners < 3) fail(fmt::format("face with {} corners (needs at least 3)", corners));
    }
  }
  return colors;
}

}  // namespace

void compute_smooth_normals(MeshData& mesh) {
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    // The cross product's length is twice the area: larger triangles weigh more.
    glm::vec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    mesh.normals[a] += n;
    mesh.normals[b] += n;
    mesh.normals[c] += n;
  }
  for (glm::vec3& n : mesh.normals) {
    float len = glm::length(n);
    if (len > kMinNormalLength) n /= len;
  }
}

std::shared_ptr<MeshData> load_obj(const std::string& path, const std::string& shown, bool smooth, SourceRef where) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw SceneError(where, fmt::format("cannot open mesh file '{}': no such file", shown));
  bool has_colors = false;
  {
    std::ifstream in(path);
    if (!in) throw SceneError(where, fmt::format("cannot open mesh file '{}'", shown));
    has_colors = prescan(shown, in, where);
  }

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = has_colors;  // vertices without a color get white
  config.mtl_search_path = fs::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    std::string err = reader.Error();
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw SceneError(where, fmt::format("malformed mesh file '{}': {}", shown, err));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  auto mesh = std::make_shared<MeshData>();
  mesh->source = path;
  bool has_normals = !attrib.normals.empty();
  bool has_uvs = !attrib.texcoords.empty();

  // One unified vertex per distinct (position, normal, uv) index triple.
  std::map<std::tuple<int, int, int>, uint32_t> unified;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    for (const tinyobj::index_t& idx : shape.mesh.indices) {
      auto key =
          std::make_tuple(idx.vertex_index, has_normals ? idx.normal_index : -1, has_uvs ? idx.texcoord_index : -1);
      auto [it, inserted] = unified.try_emplace(key, static_cast<uint32_t>(mesh->positions.size()));
      if (inserted) {
        std::size_t v = static_cast<std::size_t>(idx.vertex_index) * 3;
        if (idx.vertex_index < 0 || v + 2 >= attrib.vertices.size())
          throw SceneError(where, fmt::format("malformed mesh file '{}': vertex index out of range", shown));
        mesh->positions.emplace_back(attrib.vertices[v], attrib.vertices[v + 1], attrib.vertices[v + 2]);
        if (has_colors) {
          if (v + 2 < attrib.colors.size())
            mesh->colors.emplace_back(attrib.colors[v], attrib.colors[v + 1], attrib.colors[v + 2]);
          else
            mesh->colors.emplace_back(1.0f);
        }
        if (has_normals) {
          std::size_t n = static_cast<std::size_t>(idx.normal_index) * 3;
          if (idx.normal_index >= 0 && n + 2 < attrib.normals.size())
            mesh->normals.emplace_back(attrib.normals[n], attrib.normals[n + 1], attrib.normals[n + 2]);
          else
            mesh->normals.emplace_back(0.0f);
        }
        if (has_uvs) {
          std::size_t t = static_cast<std::size_t>(idx.texcoord_index) * 2;
          if (idx.texcoord_index >= 0 && t + 1 < attrib.texcoords.size())
            mesh->uvs.emplace_back(attrib.texcoords[t], attrib.texcoords[t + 1]);
          else
            mesh->uvs.emplace_back(0.0f);
        }
      }
      mesh->indices.push_back(it->second);
    }
  }
  if (mesh->indices.empty()) throw SceneError(where, fmt::format("mesh file '{}' has no faces", shown));
  if (!has_normals && smooth) compute_smooth_normals(*mesh);
  return mesh;
}

}  // namespace rts::render
