#include "render/builder/obj_loader.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <tuple>
#include <unordered_map>
#include <vector>

#include <fast_float/fast_float.h>
#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include "render/accel/memory.hpp"
#include "render/scene/resource_limits.hpp"
#include "render/scene/source_ref.hpp"

namespace rts::render {

namespace {

// Normals shorter than this (degenerate triangles only) are left as they are.
constexpr float kMinNormalLength = 1e-20f;

// Parses one OBJ index ("12", "-1"); false when it is not an integer.
bool parse_index(std::string_view s, long& out) {
  auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// One face corner as the file states it, resolved to 0-based indices (-1: absent).
struct Corner {
  int32_t v = -1, t = -1, n = -1;
  bool operator==(const Corner&) const = default;
};

struct CornerHash {
  std::size_t operator()(const Corner& c) const {
    uint64_t h = static_cast<uint32_t>(c.v) * 0x9E3779B97F4A7C15ull;
    h ^= (static_cast<uint64_t>(static_cast<uint32_t>(c.t)) << 32 | static_cast<uint32_t>(c.n)) + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h * 0xBF58476D1CE4E5B9ull);
  }
};

// What the loaded mesh costs per triangle and per vertex, roughly (the loader's arrays, the
// unified vertices and the BVH built later), to check the memory limit while reading.
constexpr std::size_t kBytesPerTriangle = 64;
constexpr std::size_t kBytesPerVertex = 48;

bool is_blank(char c) { return c == ' ' || c == '\t'; }

// A number field as `std::istream >> double` accepts it (an optional '+', then a decimal),
// parsed with fast_float (correctly rounded, no locale): false when the field is not a
// finite number.
bool parse_number(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  auto r = fast_float::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}

// Loads an OBJ file in one pass over fixed-size chunks (never the whole file in memory),
// validating as it goes: unparsable coordinates and face indices outside the arrays so far
// are errors with the OBJ's own line. Faces become triangles as tinyobjloader makes them
// (a quad is split along its shorter diagonal); unified vertices (one per distinct position,
// normal, uv triple) are numbered in order of first use, as the tinyobjloader path does.
// Found by profiling a 4M-triangle OBJ: `std::istringstream >> double` in the prescan plus
// tinyobjloader's own pass and the `std::map` of unified vertices were 5.5 s of an 8.5 s render.
class ObjReader {
 public:
  ObjReader(const std::string& shown, SourceRef where, const ObjLimits& limits)
      : shown_(shown), where_(where), limits_(limits) {}

  // False when the file has a face of more than four corners: the caller triangulates it
  // with tinyobjloader (ear clipping) instead; the file has been fully validated either way.
  bool has_colors() const { return !colors_.empty(); }

  bool read(std::FILE* f, MeshData& mesh) {
    constexpr std::size_t kChunk = std::size_t(1) << 22;
    std::vector<char> buf(kChunk + 1);
    std::size_t have = 0;  // bytes of an unfinished line carried over from the last chunk
    for (;;) {
      if (have == buf.size() - 1) buf.resize(buf.size() * 2);  // a line longer than a chunk
      std::size_t got = std::fread(buf.data() + have, 1, buf.size() - 1 - have, f);
      std::size_t end = have + got;
      if (got == 0) {
        if (std::ferror(f)) fail_io();
        if (end > 0) line(std::string_view(buf.data(), end));
        break;
      }
      std::size_t pos = 0;
      while (const char* nl = static_cast<const char*>(std::memchr(buf.data() + pos, '\n', end - pos))) {
        std::size_t next = static_cast<std::size_t>(nl - buf.data());
        line(std::string_view(buf.data() + pos, next - pos));
        pos = next + 1;
      }
      have = end - pos;
      std::memmove(buf.data(), buf.data() + pos, have);
    }
    check_limits();
    if (polygon_) return false;
    finish(mesh);
    return true;
  }

 private:
  [[noreturn]] void fail(const std::string& msg) const {
    throw SceneError(where_, fmt::format("malformed mesh file {}:{}: {}", shown_, line_no_, msg));
  }
  [[noreturn]] void fail_io() const {
    throw SceneError(where_, fmt::format("cannot read mesh file '{}'", shown_));
  }

  [[noreturn]] void over(const std::string& msg) const {
    throw SceneError(where_, fmt::format("mesh file {}:{}: {}", shown_, line_no_, msg));
  }

  // The triangle and memory limits, checked while reading, before anything big is built.
  void check_limits() const {
    if (triangles_ > limits_.max_triangles)
      over(fmt::format("more than {} triangles, the limit left for meshes (raise it with --max-mesh-triangles)",
                       limits_.max_triangles));
    if (!memory_fits(limits_.max_memory, triangles_ * kBytesPerTriangle + positions_.size() / 3 * kBytesPerVertex))
      over(fmt::format("the mesh would need more than the memory limit of {} (raise it with --max-memory)",
                       size_in_words(limits_.max_memory)));
  }

  void line(std::string_view s) {
    ++line_no_;
    if ((line_no_ & 0xFFFF) == 0) check_limits();
    while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && (is_blank(s.back()) || s.back() == '\r')) s.remove_suffix(1);
    if (s.empty() || s[0] == '#') return;
    std::size_t sp = 0;
    while (sp < s.size() && !is_blank(s[sp])) ++sp;
    std::string_view tag = s.substr(0, sp), rest = s.substr(sp);
    if (tag == "v") {
      vertex_line(tag, s, rest, 3, positions_);
      if (vertex_color_count_ == 6) {  // `v x y z r g b`, a common OBJ extension
        if (colors_.size() + 3 < positions_.size()) colors_.resize(positions_.size() - 3, 1.0f);  // earlier: white
        colors_.insert(colors_.end(), last_color_, last_color_ + 3);
      }
    } else if (tag == "vt") {
      vertex_line(tag, s, rest, 1, uvs_);
    } else if (tag == "vn") {
      vertex_line(tag, s, rest, 3, normals_);
    } else if (tag == "f") {
      face_line(rest);
    }
  }

  // Appends the first three numbers of a vertex line (missing ones are 0) to `out`.
  void vertex_line(std::string_view tag, std::string_view whole, std::string_view rest, int need,
                   std::vector<float>& out) {
    double x[6] = {0, 0, 0, 0, 0, 0};
    int n = 0;
    bool bad = false;
    for (;;) {
      while (!rest.empty() && is_blank(rest.front())) rest.remove_prefix(1);
      if (rest.empty()) break;
      std::size_t end = 0;
      while (end < rest.size() && !is_blank(rest[end])) ++end;
      double value;
      if (!parse_number(rest.substr(0, end), value)) bad = true;
      if (n < 6) x[n] = value;
      ++n;
      rest.remove_prefix(end);
    }
    if (bad || n < need) fail(fmt::format("malformed '{}' line: '{}'", tag, whole));
    vertex_color_count_ = n;
    if (n >= 6)
      for (int k = 0; k < 3; ++k) last_color_[k] = static_cast<float>(x[3 + k]);
    if (&out == &uvs_) {
      out.push_back(static_cast<float>(x[0]));
      out.push_back(static_cast<float>(x[1]));
    } else {
      for (int k = 0; k < 3; ++k) out.push_back(static_cast<float>(x[k]));
    }
  }

  void face_line(std::string_view rest) {
    corners_.clear();
    for (;;) {
      while (!rest.empty() && is_blank(rest.front())) rest.remove_prefix(1);
      if (rest.empty()) break;
      std::size_t end = 0;
      while (end < rest.size() && !is_blank(rest[end])) ++end;
      std::string_view corner = rest.substr(0, end);
      rest.remove_prefix(end);
      Corner c;
      int32_t* slot[3] = {&c.v, &c.t, &c.n};
      const std::size_t counts[3] = {positions_.size() / 3, uvs_.size() / 2, normals_.size() / 3};
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
        *slot[k] = static_cast<int32_t>(resolved - 1);
      }
      corners_.push_back(c);
    }
    if (corners_.size() < 3) fail(fmt::format("face with {} corners (needs at least 3)", corners_.size()));
    triangles_ += corners_.size() - 2;
    if (triangles_ > limits_.max_triangles) check_limits();
    if (polygon_) return;  // validating only: tinyobjloader triangulates this file
    if (corners_.size() == 3) {
      emit(corners_[0], corners_[1], corners_[2]);
    } else if (corners_.size() == 4) {
      // tinyobjloader's rule (in float, as it computes it): split along the shorter diagonal.
      auto p = [&](const Corner& c) {
        const float* q = &positions_[static_cast<std::size_t>(c.v) * 3];
        return glm::vec3(q[0], q[1], q[2]);
      };
      glm::vec3 e02 = p(corners_[2]) - p(corners_[0]), e13 = p(corners_[3]) - p(corners_[1]);
      float sqr02 = e02.x * e02.x + e02.y * e02.y + e02.z * e02.z;
      float sqr13 = e13.x * e13.x + e13.y * e13.y + e13.z * e13.z;
      if (sqr02 < sqr13) {
        emit(corners_[0], corners_[1], corners_[2]);
        emit(corners_[0], corners_[2], corners_[3]);
      } else {
        emit(corners_[0], corners_[1], corners_[3]);
        emit(corners_[1], corners_[2], corners_[3]);
      }
    } else {
      polygon_ = true;
    }
  }

  void emit(const Corner& a, const Corner& b, const Corner& c) {
    indices_.push_back(unify(a));
    indices_.push_back(unify(b));
    indices_.push_back(unify(c));
  }

  // The unified vertex of a corner. Most positions are used with one (normal, uv) pair: a
  // direct table per position answers those; the rest go through a hash map.
  uint32_t unify(const Corner& c) {
    auto v = static_cast<std::size_t>(c.v);
    if (first_.size() <= v) first_.resize(std::max(positions_.size() / 3, v + 1), kNone);
    uint32_t& f = first_[v];
    if (f == kNone) {
      f = static_cast<uint32_t>(unified_.size());
      unified_.push_back(c);
      return f;
    }
    if (unified_[f] == c) return f;
    auto [it, inserted] = others_.try_emplace(c, static_cast<uint32_t>(unified_.size()));
    if (inserted) unified_.push_back(c);
    return it->second;
  }

  void finish(MeshData& mesh) {
    std::vector<uint32_t>().swap(first_);
    std::size_t n = unified_.size();
    mesh.positions.resize(n);
    bool has_normals = !normals_.empty(), has_uvs = !uvs_.empty();
    if (has_normals) mesh.normals.resize(n);
    if (has_uvs) mesh.uvs.resize(n);
    const bool has_colors = !colors_.empty();
    if (has_colors) {
      colors_.resize(positions_.size(), 1.0f);  // vertices after the last colored one: white
      mesh.colors.resize(n);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const Corner& c = unified_[i];
      const float* p = &positions_[static_cast<std::size_t>(c.v) * 3];
      mesh.positions[i] = glm::vec3(p[0], p[1], p[2]);
      if (has_colors) {
        const float* q = &colors_[static_cast<std::size_t>(c.v) * 3];
        mesh.colors[i] = glm::vec3(q[0], q[1], q[2]);
      }
      if (has_normals) {
        if (c.n >= 0) {
          const float* q = &normals_[static_cast<std::size_t>(c.n) * 3];
          mesh.normals[i] = glm::vec3(q[0], q[1], q[2]);
        } else {
          mesh.normals[i] = glm::vec3(0.0f);
        }
      }
      if (has_uvs) {
        if (c.t >= 0) {
          const float* q = &uvs_[static_cast<std::size_t>(c.t) * 2];
          mesh.uvs[i] = glm::vec2(q[0], q[1]);
        } else {
          mesh.uvs[i] = glm::vec2(0.0f);
        }
      }
    }
    // The file's own arrays go before the index array is trimmed (trimming copies it): the
    // peak memory of a large mesh is reached here.
    std::vector<float>().swap(positions_);
    std::vector<float>().swap(normals_);
    std::vector<float>().swap(uvs_);
    std::vector<float>().swap(colors_);
    std::vector<Corner>().swap(unified_);
    others_ = {};
    indices_.shrink_to_fit();
    mesh.indices = std::move(indices_);
  }

  static constexpr uint32_t kNone = ~uint32_t(0);
  const std::string& shown_;
  SourceRef where_;
  const ObjLimits& limits_;
  std::size_t triangles_ = 0;
  int vertex_color_count_ = 0;  // numbers on the last vertex line
  float last_color_[3] = {1, 1, 1};
  std::vector<float> colors_;   // 3 per position once any vertex has a color (else empty)
  unsigned line_no_ = 0;
  bool polygon_ = false;  // a face of 5+ corners was seen
  std::vector<float> positions_, uvs_, normals_;  // as the file lists them (uvs: 2 per entry)
  std::vector<Corner> corners_;                   // the current face's
  std::vector<Corner> unified_;                   // the corner each unified vertex stands for
  std::vector<uint32_t> first_;                   // per position: its first unified vertex
  std::unordered_map<Corner, uint32_t, CornerHash> others_;
  std::vector<uint32_t> indices_;
};

// tinyobjloader's path, for files with polygons of five or more corners (ear clipping).
void load_with_tinyobj(const std::string& path, const std::string& shown, SourceRef where, bool has_colors,
                       MeshData& out) {
  std::string text;
  {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(where, fmt::format("cannot open mesh file '{}'", shown));
    std::ostringstream all;
    all << in.rdbuf();
    text = std::move(all).str();
  }
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = has_colors;  // vertices without a color get white
  tinyobj::ObjReader reader;
  // From memory, with an empty material text: tinyobjloader then opens no `mtllib` file.
  if (!reader.ParseFromString(text, std::string(), config)) {
    std::string err = reader.Error();
    while (!err.empty() && err.back() == '\n') err.pop_back();
    throw SceneError(where, fmt::format("malformed mesh file '{}': {}", shown, err));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  MeshData* mesh = &out;
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
}

}  // namespace

void compute_smooth_normals(MeshData& mesh, bool equal_weights) {
  mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f));
  // Float cross products overflow for edges past about 1e19 (a mesh 1e30 units wide) and lose
  // their digits below 1e-19: such a mesh's edges are scaled by a power of two near 1 / its
  // largest coordinate first (exact, so the normals' directions are the unscaled ones).
  float big = 0.0f;
  for (const glm::vec3& p : mesh.positions) big = std::max({big, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const float scale = big > 0.0f && std::isfinite(big) && !(big > 1e-8f && big < 1e8f) ? std::ldexp(1.0f, -std::ilogb(big)) : 1.0f;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    // The cross product's length is twice the area: larger triangles weigh more.
    glm::vec3 n = glm::cross((mesh.positions[b] - mesh.positions[a]) * scale, (mesh.positions[c] - mesh.positions[a]) * scale);
    if (equal_weights) {
      const float len = glm::length(n);
      if (!(len > kMinNormalLength)) continue;  // a degenerate face has no normal to give
      n /= len;
    }
    mesh.normals[a] += n;
    mesh.normals[b] += n;
    mesh.normals[c] += n;
  }
  for (glm::vec3& n : mesh.normals) {
    float len = glm::length(n);
    if (len > kMinNormalLength) n /= len;
  }
}

std::shared_ptr<MeshData> load_obj(const std::string& path, const std::string& shown, bool smooth, SourceRef where,
                                   const ObjLimits& limits) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw SceneError(where, fmt::format("cannot open mesh file '{}': no such file", shown));
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw SceneError(where, fmt::format("cannot open mesh file '{}'", shown));
  auto mesh = std::make_shared<MeshData>();
  mesh->source = path;
  ObjReader reader(shown, where, limits);
  bool done = reader.read(file.get(), *mesh);
  file.reset();
  if (!done) load_with_tinyobj(path, shown, where, reader.has_colors(), *mesh);
  if (mesh->indices.empty()) throw SceneError(where, fmt::format("mesh file '{}' has no faces", shown));
  if (mesh->normals.empty() && smooth) compute_smooth_normals(*mesh);
  release_free_memory(mesh->indices.size() / 3);
  return mesh;
}

}  // namespace rts::render
