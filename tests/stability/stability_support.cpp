#include "stability_support.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <tuple>

#include "render/image/image.hpp"

namespace rts::stability {
using namespace render;

RenderResult render_scene(const SceneDesc& s, int threads, bool aovs) {
  RenderOptions o;
  o.threads = threads;
  if (aovs) o.aovs = {"normal", "depth", "albedo"};
  return render::render(s, o);
}

std::vector<uint8_t> to_srgb8(const Image& img) {
  std::vector<uint8_t> out(img.rgb.size());
  for (std::size_t i = 0; i < img.rgb.size(); ++i) {
    float v = linear_to_srgb(std::clamp(img.rgb[i], 0.0f, 1.0f));
    out[i] = static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  }
  return out;
}

double differing_fraction(const Image& a, const Image& b, int threshold) {
  if (a.width != b.width || a.height != b.height) return 1.0;
  auto ca = to_srgb8(a), cb = to_srgb8(b);
  std::size_t pixels = static_cast<std::size_t>(a.width) * a.height, differ = 0;
  for (std::size_t p = 0; p < pixels; ++p)
    for (int k = 0; k < 3; ++k)
      if (std::abs(int(ca[p * 3 + k]) - int(cb[p * 3 + k])) > threshold) {
        ++differ;
        break;
      }
  return static_cast<double>(differ) / static_cast<double>(pixels);
}

int count_color(const Image& img, const Color& c) {
  int n = 0;
  for (std::size_t i = 0; i < img.rgb.size(); i += 3)
    if (img.rgb[i] == float(c.r) && img.rgb[i + 1] == float(c.g) && img.rgb[i + 2] == float(c.b)) ++n;
  return n;
}

int count_non_finite(const Image& img) {
  int n = 0;
  for (std::size_t i = 0; i < img.rgb.size(); i += 3)
    if (!std::isfinite(img.rgb[i]) || !std::isfinite(img.rgb[i + 1]) || !std::isfinite(img.rgb[i + 2])) ++n;
  return n;
}

int count_speckles(const Image& img, int threshold) {
  auto c = to_srgb8(img);
  auto px = [&](int x, int y, int k) { return int(c[(static_cast<std::size_t>(y) * img.width + x) * 3 + k]); };
  auto close = [&](int x0, int y0, int x1, int y1) {
    for (int k = 0; k < 3; ++k)
      if (std::abs(px(x0, y0, k) - px(x1, y1, k)) > threshold) return false;
    return true;
  };
  int n = 0;
  for (int y = 1; y + 1 < img.height; ++y)
    for (int x = 1; x + 1 < img.width; ++x) {
      const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
      bool neighbours_agree = true, differs_from_all = true;
      for (int i = 0; i < 4; ++i) {
        if (close(x, y, nx[i], ny[i])) differs_from_all = false;
        if (!close(nx[0], ny[0], nx[i], ny[i])) neighbours_agree = false;
      }
      if (differs_from_all && neighbours_agree) ++n;
    }
  return n;
}

int count_black(const Image& img) {
  auto c = to_srgb8(img);
  int n = 0;
  for (std::size_t i = 0; i < c.size(); i += 3)
    if (c[i] == 0 && c[i + 1] == 0 && c[i + 2] == 0) ++n;
  return n;
}

namespace {
std::mutex record_mutex;
std::filesystem::path out_dir() {
  std::filesystem::path p(RTS_STABILITY_OUT);
  std::filesystem::create_directories(p);
  return p;
}
}  // namespace

void record(const std::string& group, const std::string& name, const std::string& metric, double value,
            const std::string& limit, const std::string& image) {
  std::lock_guard lock(record_mutex);
  // One file per group, rewritten by each run of that group (ctest runs groups separately).
  static std::vector<std::string> started;
  std::filesystem::path file = out_dir() / ("figures-" + group + ".tsv");
  bool first = std::find(started.begin(), started.end(), group) == started.end();
  if (first) started.push_back(group);
  std::ofstream out(file, first ? std::ios::trunc : std::ios::app);
  out << group << '\t' << name << '\t' << metric << '\t' << value << '\t' << limit << '\t' << image << '\n';
}

std::string save(const Image& img, const std::string& file) {
  std::string name = file + ".png";
  write_png((out_dir() / name).string(), img, 8, Encoding::SRGB);
  return name;
}

MaterialId add_material(SceneDesc& s, const MaterialDesc& m) {
  s.materials.push_back(m);
  return static_cast<MaterialId>(s.materials.size() - 1);
}

NodeId add_shape(SceneDesc& s, ShapeGeometry g, MaterialId material) {
  ShapeDesc shape;
  shape.geometry = std::move(g);
  shape.material = material;
  s.shapes.push_back(std::move(shape));
  s.nodes.push_back(Node{NodeKind::Shape, static_cast<uint32_t>(s.shapes.size() - 1)});
  return static_cast<NodeId>(s.nodes.size() - 1);
}

NodeId add_light(SceneDesc& s, const LightDesc& l) {
  s.lights.push_back(l);
  s.nodes.push_back(Node{NodeKind::Light, static_cast<uint32_t>(s.lights.size() - 1)});
  return static_cast<NodeId>(s.nodes.size() - 1);
}

NodeId add_group(SceneDesc& s, std::vector<Child> children) {
  s.groups.push_back(GroupDesc{std::move(children)});
  s.nodes.push_back(Node{NodeKind::Group, static_cast<uint32_t>(s.groups.size() - 1)});
  return static_cast<NodeId>(s.nodes.size() - 1);
}

NodeId add_csg(SceneDesc& s, render::CsgOp op, std::vector<Child> children, MaterialId m) {
  render::CsgDesc d;
  d.op = op;
  d.children = std::move(children);
  d.material = m;
  s.csgs.push_back(std::move(d));
  s.nodes.push_back(Node{NodeKind::Csg, static_cast<uint32_t>(s.csgs.size() - 1)});
  return static_cast<NodeId>(s.nodes.size() - 1);
}

void place(SceneDesc& s, NodeId node, const Mat4& transform) { s.roots.push_back(Child{node, transform, {}}); }

MaterialDesc matte(Color c) {
  MaterialDesc m;
  m.color = c;
  return m;
}

MaterialDesc emissive(Color c) {
  MaterialDesc m;
  m.emission = c;
  m.ambient = 0;
  m.diffuse = 0;
  return m;
}

namespace {
// Positions are stored relative to the mesh's centre, as the scene builder does.
void finish_mesh(MeshData& m, const std::vector<Vec3>& positions) {
  Vec3 lo(1e300), hi(-1e300);
  for (const Vec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  m.origin = 0.5 * (lo + hi);
  for (const Vec3& p : positions) m.positions.emplace_back(p - m.origin);
}
void quad(std::vector<uint32_t>& idx, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  idx.insert(idx.end(), {a, b, c, a, c, d});
}
}  // namespace

std::shared_ptr<MeshData> uv_sphere_mesh(Vec3 center, double radius, int rings, int segments) {
  auto m = std::make_shared<MeshData>();
  std::vector<Vec3> pos;
  pos.push_back(center + Vec3(0, radius, 0));  // north pole
  for (int r = 1; r < rings; ++r) {
    double theta = M_PI * r / rings;
    for (int s = 0; s < segments; ++s) {
      double phi = 2.0 * M_PI * s / segments;
      pos.push_back(center + radius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                           std::sin(theta) * std::sin(phi)));
    }
  }
  pos.push_back(center - Vec3(0, radius, 0));  // south pole
  auto ring = [&](int r, int s) { return static_cast<uint32_t>(1 + (r - 1) * segments + (s % segments)); };
  uint32_t south = static_cast<uint32_t>(pos.size() - 1);
  for (int s = 0; s < segments; ++s) {
    m->indices.insert(m->indices.end(), {0u, ring(1, s + 1), ring(1, s)});
    for (int r = 1; r + 1 < rings; ++r) quad(m->indices, ring(r, s), ring(r, s + 1), ring(r + 1, s + 1), ring(r + 1, s));
    m->indices.insert(m->indices.end(), {south, ring(rings - 1, s), ring(rings - 1, s + 1)});
  }
  finish_mesh(*m, pos);
  return m;
}

std::shared_ptr<MeshData> grid_cube_mesh(double h, int n) {
  auto m = std::make_shared<MeshData>();
  std::vector<Vec3> pos;
  // Vertices of the cube's surface lattice, shared between faces through a lookup.
  std::map<std::tuple<int, int, int>, uint32_t> ids;
  auto vid = [&](int i, int j, int k) {
    auto [it, inserted] = ids.try_emplace({i, j, k}, static_cast<uint32_t>(pos.size()));
    if (inserted) pos.push_back(Vec3(-h + 2 * h * i / n, -h + 2 * h * j / n, -h + 2 * h * k / n));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side <= n; side += n)
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          auto at = [&](int u, int v) {
            int c[3];
            c[axis] = side;
            c[(axis + 1) % 3] = u;
            c[(axis + 2) % 3] = v;
            return vid(c[0], c[1], c[2]);
          };
          quad(m->indices, at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1));
        }
  finish_mesh(*m, pos);
  return m;
}

std::shared_ptr<MeshData> grid_mesh(double h, int n) {
  auto m = std::make_shared<MeshData>();
  std::vector<Vec3> pos;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) pos.push_back(Vec3(-h + 2 * h * i / n, -h + 2 * h * j / n, 0.0));
  auto id = [&](int i, int j) { return static_cast<uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) quad(m->indices, id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  finish_mesh(*m, pos);
  return m;
}

NodeId add_mesh(SceneDesc& s, std::shared_ptr<MeshData> mesh, MaterialId material, bool smooth) {
  s.meshes.push_back(std::move(mesh));
  MeshRef ref;
  ref.mesh = static_cast<MeshId>(s.meshes.size() - 1);
  ref.smooth = smooth;
  return add_shape(s, ref, material);
}

}  // namespace rts::stability
