#include "runtime/scene_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "render/scene/scene.hpp"

namespace rts {
namespace {

using render::Vec3;

SourceLoc locate(const SourceManager& sources, const render::SourceRef& where) {
  if (where.file && *where.file)
    if (const SourceFile* f = sources.find(where.file)) return SourceLoc::at(f, where.line, where.col);
  return {};
}

// In path mode emissive materials and the sky are lights too: a scene lit only by them is
// not "unlit".
bool path_lit(const render::SceneDesc& scene, std::string_view integrator) {
  bool path = integrator.empty() ? scene.settings.integrator == render::IntegratorKind::Path : integrator == "path";
  if (!path) return false;
  const render::Color& bg = scene.settings.background;
  if (scene.settings.environment != render::kNoId || bg.r > 0 || bg.g > 0 || bg.b > 0) return true;
  for (const render::MaterialDesc& m : scene.materials) {
    const render::Color& e = m.emission;
    if (m.emission_texture != render::kNoId || e.r > 0 || e.g > 0 || e.b > 0) return true;
  }
  return false;
}

// Whether the object-space point p is strictly inside the closed shape; false for the open
// ones (planes, triangles, discs, quads) and for meshes and superellipsoids (not checked).
struct Inside {
  Vec3 p;
  bool operator()(const render::Sphere& s) const { return glm::length(p - s.center) < s.radius; }
  bool operator()(const render::Box& b) const {
    return p.x > b.min.x && p.x < b.max.x && p.y > b.min.y && p.y < b.max.y && p.z > b.min.z && p.z < b.max.z;
  }
  bool operator()(const render::Cylinder& c) const { return in_cone(c.from, c.to, c.radius, c.radius, c.capped); }
  bool operator()(const render::Cone& c) const { return in_cone(c.from, c.to, c.radius_from, c.radius_to, c.capped); }
  bool operator()(const render::Torus& t) const {
    double ring = std::sqrt(p.x * p.x + p.z * p.z) - t.major;
    return ring * ring + p.y * p.y < t.minor * t.minor;
  }
  template <typename Other>
  bool operator()(const Other&) const { return false; }

  bool in_cone(const Vec3& from, const Vec3& to, double r0, double r1, bool capped) const {
    if (!capped) return false;
    Vec3 axis = to - from;
    double len2 = glm::dot(axis, axis);
    if (!(len2 > 0)) return false;
    double t = glm::dot(p - from, axis) / len2;
    if (!(t > 0 && t < 1)) return false;
    double r = r0 + (r1 - r0) * t;
    return glm::length(p - (from + t * axis)) < r;
  }
};

// The closed shapes Inside knows, by name; null for the others (not checked).
const char* closed_shape(const render::StoredGeometry& g) {
  if (g.holds<render::Sphere>()) return "sphere";
  if (g.holds<render::Box>()) return "box";
  if (g.holds<render::Cylinder>()) return "cylinder";
  if (g.holds<render::Cone>()) return "cone";
  if (g.holds<render::Torus>()) return "torus";
  return nullptr;
}

// Instances visited looking for one that holds the camera: the walk composes one transform
// per instance (and inverts it for a closed shape) and allocates nothing; this bounds its
// cost for scenes of millions of instances, which are not checked past them.
constexpr std::size_t kMaxInstancesChecked = 1'000'000;
// Deeper nesting is a cycle, which the render refuses (tol::kMaxGroupDepth); the walk just stops.
constexpr int kMaxGroupDepth = 1024;

// Depth-first over the placed instances (groups expanded, CSG blocks skipped: a hole cut in
// a solid may hold the camera), stopping at the first closed shape around the camera.
struct CameraSearch {
  const render::SceneDesc& scene;
  Vec3 eye;
  std::size_t visited = 0;
  const render::ShapeDesc* found = nullptr;
  render::SourceRef placed;

  void visit(const render::Child& c, const render::Mat4& parent, int depth) {
    if (found || ++visited > kMaxInstancesChecked || depth > kMaxGroupDepth) return;
    if (c.node >= scene.nodes.size()) return;
    const render::Node& node = scene.nodes[c.node];
    const render::Mat4 m = parent * c.transform;
    if (node.kind == render::NodeKind::Group) {
      if (node.index < scene.groups.size())
        for (const render::Child& g : scene.groups[node.index].children) visit(g, m, depth + 1);
      return;
    }
    if (node.kind != render::NodeKind::Shape || node.index >= scene.shapes.size()) return;
    const render::ShapeDesc& shape = scene.shapes[node.index];
    if (shape.inverse || closed_shape(shape.geometry) == nullptr) return;
    // A clear or glass shape around the camera is seen through (a box of haze around a
    // scene, docs/rendering.md#media): no warning.
    if (shape.material < scene.materials.size() && render::transmits(scene.materials[shape.material])) return;
    const double det = glm::determinant(m);
    if (!std::isfinite(det) || det == 0.0) return;  // the render reports a singular transform
    const Vec3 p = Vec3(glm::inverse(m) * glm::dvec4(eye, 1.0));
    if (std::isfinite(p.x + p.y + p.z) && visit_shape(Inside{p}, shape.geometry)) {
      found = &shape;
      placed = c.loc;
    }
  }
};

void camera_inside(const EvalResult& result, const SourceManager& sources, std::vector<Diagnostic>& out) {
  const render::SceneDesc& scene = result.scene;
  CameraSearch search{scene, scene.camera.position, 0, nullptr, {}};
  for (const render::Child& root : scene.roots) search.visit(root, render::Mat4(1.0), 0);
  if (!search.found) return;
  const char* word = closed_shape(search.found->geometry);
  Diagnostic d;
  d.severity = Severity::Warning;
  d.loc = locate(sources, scene.camera.loc);
  d.message = fmt::format("the camera is inside a {}: it sees only the {}'s inside (move the camera or the {})",
                          word, word, word);
  SourceLoc placed = locate(sources, search.placed);
  if (!placed.valid()) placed = locate(sources, search.found->loc);
  if (placed.valid()) d.notes.push_back(Note{placed, fmt::format("the {} is placed here", word)});
  if (!d.loc.valid()) d.loc = placed;
  out.push_back(std::move(d));
}

// Intersection tests square distances: past about 1e154 units those overflow and below
// 1e-154 they underflow, and hits are lost without any error. Every shape gives the unit
// scene's picture scaled by 1e-150 to 1e150 (tests/render/test_extremes.cpp: a camera up to
// 7e150 from the origin); a camera past 1e152, or looking across less than 1e-152, says so.
constexpr double kLargestScale = 1e152, kSmallestScale = 1e-152;

void camera_scale(const render::SceneDesc& scene, const SourceManager& sources, std::vector<Diagnostic>& out) {
  const render::CameraDesc& c = scene.camera;
  using render::max_abs_component;
  const double far = std::max(max_abs_component(c.position), c.given_vectors ? 0.0 : max_abs_component(c.look_at));
  const double view = c.given_vectors ? kLargestScale : max_abs_component(c.look_at - c.position);
  std::string message;
  if (far > kLargestScale && std::isfinite(far))
    message = fmt::format("the camera is {:.3g} units from the origin, past the 1e152 within which rts renders "
                          "exactly (squared distances overflow past about 1e154): objects may be missing; model "
                          "the scene smaller",
                          far);
  else if (view < kSmallestScale && view > 0.0)
    message = fmt::format("the camera looks across {:.3g} units, below the 1e-152 within which rts renders exactly "
                          "(squared distances underflow below about 1e-154): objects may be missing; model the "
                          "scene larger",
                          view);
  if (message.empty()) return;
  out.push_back({Severity::Warning, locate(sources, c.loc), std::move(message), {}});
}

}  // namespace

std::vector<Diagnostic> scene_warnings(const EvalResult& result, const SourceManager& sources,
                                       const SourceFile* main, std::string_view integrator) {
  std::vector<Diagnostic> out;
  for (const render::Warning& w : result.scene.warnings) {
    Diagnostic d{Severity::Warning, locate(sources, w.where), w.message, {}};
    if (!d.loc.valid() && w.where.file && *w.where.file)
      d.message = fmt::format("{}:{}:{}: {}", w.where.file, w.where.line, w.where.col, w.message);
    out.push_back(std::move(d));
  }
  // A black image with no word of why is a trap (a library file rendered by mistake).
  SourceLoc whole_file = SourceLoc::whole(main);
  if (result.world_shapes == 0)
    out.push_back({Severity::Warning, whole_file, "the scene places no objects: the image shows only the background", {}});
  else if (result.world_lights == 0 && !path_lit(result.scene, integrator))
    out.push_back({Severity::Warning, whole_file,
                   "the scene places no lights: objects show only their ambient light and emission", {}});
  if (result.world_shapes > 0) camera_inside(result, sources, out);
  if (result.scene.has_camera) camera_scale(result.scene, sources, out);
  return out;
}

}  // namespace rts
