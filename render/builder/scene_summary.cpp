#include "render/builder/scene_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include <fmt/format.h>

#include "render/geometry/shapes/shape_kinds.hpp"

namespace rts::render {

namespace {

// Object-space bounds of a shape (its descriptor's bounds()); false for unbounded shapes
// (planes) and empty meshes.
bool shape_bounds(const SceneDesc& scene, const ShapeDesc& s, Vec3& lo, Vec3& hi) {
  return visit_shape(
      [&](const auto& g) {
        using T = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<T, MeshRef>) {
          const MeshData& m = *scene.meshes[g.mesh];
          if (m.positions.empty()) return false;
          lo = Vec3(std::numeric_limits<double>::max());
          hi = -lo;
          for (const glm::vec3& p : m.positions) {
            lo = glm::min(lo, m.origin + Vec3(p));
            hi = glm::max(hi, m.origin + Vec3(p));
          }
          return true;
        } else if constexpr (ShapeTraits<T>::kInfo.bounded) {
          const AABB b = bounds(g);
          lo = b.lo;
          hi = b.hi;
          return true;
        } else {
          return false;
        }
      },
      s.geometry);
}


const char* light_kind(LightKind k) {
  switch (k) {
    case LightKind::Point:
      return "point_light";
    case LightKind::Spot:
      return "spot_light";
    case LightKind::Directional:
      return "directional_light";
    case LightKind::Area:
      return "area_light";
  }
  return "light";
}

// Each shape's object-space box (shape_bounds), by shape index: first false when unbounded.
using ShapeBoxes = std::vector<std::pair<bool, std::pair<Vec3, Vec3>>>;

// Placed instances summed up: the counts and the world-space box of what was added.
struct Totals {
  std::map<std::string, std::size_t> shapes, lights;
  std::size_t instances = 0, triangles = 0;
  bool unbounded = false, has_box = false;
  Vec3 lo{0.0}, hi{0.0};

  void extend(const Vec3& p) {
    if (!has_box) {
      lo = hi = p;
      has_box = true;
    }
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void extend_box(const Mat4& m, const Vec3& box_lo, const Vec3& box_hi) {
    for (int c = 0; c < 8; ++c)
      extend(Vec3(m * glm::dvec4((c & 1) ? box_hi.x : box_lo.x, (c & 2) ? box_hi.y : box_lo.y,
                                 (c & 4) ? box_hi.z : box_lo.z, 1.0)));
  }
  // One placement under `m` of what `t` sums (its box's corners under m).
  void add(const Totals& t, const Mat4& m) {
    for (const auto& [k, n] : t.shapes) shapes[k] += n;
    for (const auto& [k, n] : t.lights) lights[k] += n;
    instances += t.instances;
    triangles += t.triangles;
    unbounded = unbounded || t.unbounded;
    if (t.has_box) extend_box(m, t.lo, t.hi);
  }
};

// One placed shape or light (node `n`) under `m`.
void add_leaf(const SceneDesc& scene, const ShapeBoxes& boxes, const Node& n, const Mat4& m, Totals& out) {
  ++out.instances;
  if (n.kind == NodeKind::Light) {
    ++out.lights[light_kind(scene.lights[n.index].kind)];
    return;
  }
  const ShapeDesc& s = scene.shapes[n.index];
  ++out.shapes[std::string(shape_name(s.geometry))];
  if (auto* mesh = shape_if<MeshRef>(s.geometry)) out.triangles += scene.meshes[mesh->mesh]->indices.size() / 3;
  const auto& [bounded, box] = boxes[n.index];
  if (bounded)
    out.extend_box(m, box.first, box.second);
  else
    out.unbounded = out.unbounded || s.geometry.holds<Plane>();
}

const std::vector<Child>& members(const SceneDesc& scene, const Node& n) {
  return n.kind == NodeKind::Group ? scene.groups[n.index].children : scene.csgs[n.index].children;
}

bool is_leaf(const Node& n) { return n.kind == NodeKind::Shape || n.kind == NodeKind::Light; }

// Every placed instance visited, its transform composed through the groups above it: exact
// world-space bounds. Iterative: groups may nest as deep as macro recursion goes (far past the
// C++ stack). Stops past `max_instances` (the count GroupTotals made): only a group holding
// itself, which the evaluator cannot make but a SceneDesc built by hand can, goes on.
void walk(const SceneDesc& scene, const ShapeBoxes& boxes, NodeId root, const Mat4& root_transform, Totals& out,
          std::size_t max_instances) {
  std::vector<std::pair<NodeId, Mat4>> todo{{root, root_transform}};
  while (!todo.empty() && out.instances <= max_instances) {
    auto [id, m] = todo.back();
    todo.pop_back();
    const Node& n = scene.nodes[id];
    if (is_leaf(n)) {
      add_leaf(scene, boxes, n, m, out);
      continue;
    }
    ++out.instances;
    // A CSG block is counted by its shapes (a loose bound: a difference's holes and an
    // intersection's cuts do not shrink it).
    for (const Child& c : members(scene, n)) todo.emplace_back(c.node, m * c.transform);
  }
}

// The totals of one placement of each group and CSG block, in its own space (the box of its
// members' boxes under their transforms), made once: a group placed a million times is summed
// once, and each placement adds its totals under its transform.
class GroupTotals {
 public:
  GroupTotals(const SceneDesc& scene, const ShapeBoxes& boxes) : scene_(scene), boxes_(boxes) {}

  // The instances one placement of node `id` holds (itself and, through groups, its members).
  std::size_t instances(NodeId id) { return is_leaf(scene_.nodes[id]) ? 1 : of(id).instances; }

  // One placement of node `id` under `m`, added to `out`.
  void add(NodeId id, const Mat4& m, Totals& out) {
    const Node& n = scene_.nodes[id];
    if (is_leaf(n))
      add_leaf(scene_, boxes_, n, m, out);
    else
      out.add(of(id), m);
  }

 private:
  // Post-order over the groups below `group` (an explicit stack): a group's totals are made
  // once its member groups' are. A member already open on the stack would be a cycle, which
  // the evaluator cannot make (a group holds only what existed before it); it adds nothing.
  const Totals& of(NodeId group) {
    if (auto it = done_.find(group); it != done_.end()) return it->second;
    std::vector<NodeId> todo{group};
    while (!todo.empty()) {
      const NodeId id = todo.back();
      if (done_.count(id)) {
        todo.pop_back();
        continue;
      }
      const bool first_visit = open_.insert(id).second;
      bool ready = true;
      for (const Child& c : members(scene_, scene_.nodes[id]))
        if (first_visit && !is_leaf(scene_.nodes[c.node]) && !done_.count(c.node) && !open_.count(c.node)) {
          todo.push_back(c.node);
          ready = false;
        }
      if (!ready) continue;
      Totals t;
      t.instances = 1;  // the group itself, as the walk counts it
      for (const Child& c : members(scene_, scene_.nodes[id]))
        if (is_leaf(scene_.nodes[c.node]) || done_.count(c.node)) add(c.node, c.transform, t);
      done_.emplace(id, std::move(t));
      todo.pop_back();
    }
    return done_.at(group);
  }

  const SceneDesc& scene_;
  const ShapeBoxes& boxes_;
  std::unordered_map<NodeId, Totals> done_;
  std::unordered_set<NodeId> open_;
};

// Rounding noise (a rotation's 1e-17 where 0 is meant) prints as 0: values below 1e-9 of
// `scale`, the largest magnitude printed beside them (1 for a lone number, so a scene
// modelled at 1e-13 units still shows its bounds).
std::string num(double x, double scale = 1.0) {
  constexpr double kPrintZero = 1e-9;
  if (std::fabs(x) < kPrintZero * scale) x = 0;
  return fmt::format("{:.6g}", x);
}
std::string vec(const Vec3& v) {
  const double scale = std::min(1.0, max_abs_component(v));
  return fmt::format("<{}, {}, {}>", num(v.x, scale), num(v.y, scale), num(v.z, scale));
}

}  // namespace

SceneSummary summarize(const SceneDesc& scene, std::size_t exact_walk_limit) {
  SceneSummary s;
  s.shape_definitions = scene.shapes.size();
  s.materials = scene.materials.size();
  s.textures = scene.textures.size();
  s.meshes = scene.meshes.size();
  s.groups = scene.groups.size();
  ShapeBoxes boxes(scene.shapes.size());
  for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
    Vec3 lo(0.0), hi(0.0);
    bool b = shape_bounds(scene, scene.shapes[i], lo, hi);
    boxes[i] = {b, {lo, hi}};
  }
  // Every placement walked shape by shape bounds the scene exactly; past exact_walk_limit
  // (groups placed many times: a million placements of a 64-sphere group were 67M visits and
  // 4 s, where rendering took 1.5) the counts come from each group's totals, made once, and
  // the bounds from each placed group's own box (looser under rotations: print_summary says so).
  // The instance count decides first (a placed shape counts once, a group from its totals),
  // so the roots are summed up by one of the two ways only.
  GroupTotals groups(scene, boxes);
  std::size_t placed = 0;
  for (const Child& c : scene.roots) placed += groups.instances(c.node);
  s.bounds_of_group_boxes = placed > exact_walk_limit;
  Totals all;
  for (const Child& c : scene.roots) {
    if (s.bounds_of_group_boxes)
      groups.add(c.node, c.transform, all);
    else
      walk(scene, boxes, c.node, c.transform, all, placed);
  }
  s.shapes = std::move(all.shapes);
  s.lights = std::move(all.lights);
  s.instances = all.instances;
  s.triangles = all.triangles;
  s.unbounded = all.unbounded;
  s.has_bounds = all.has_box;
  s.bounds_min = all.lo;
  s.bounds_max = all.hi;
  return s;
}

void print_summary(std::ostream& out, const SceneDesc& scene, const SceneSummary& s, double seconds) {
  std::size_t placed_shapes = 0, placed_lights = 0;
  for (auto& [k, n] : s.shapes) placed_shapes += n;
  for (auto& [k, n] : s.lights) placed_lights += n;
  out << fmt::format("objects:    {} placed ({} shape definitions, {} groups, {} instances in all)\n", placed_shapes,
                     s.shape_definitions, s.groups, s.instances);
  for (auto& [k, n] : s.shapes) out << fmt::format("  {:<18} {}\n", k, n);
  out << fmt::format("triangles:  {} (in {} mesh{})\n", s.triangles, s.meshes, s.meshes == 1 ? "" : "es");
  out << fmt::format("lights:     {}\n", placed_lights);
  for (auto& [k, n] : s.lights) out << fmt::format("  {:<18} {}\n", k, n);
  out << fmt::format("materials:  {}\n", s.materials);
  out << fmt::format("textures:   {}\n", s.textures);
  if (s.has_bounds)
    out << fmt::format("bounds:     {} .. {}{}{}\n", vec(s.bounds_min), vec(s.bounds_max),
                       s.unbounded ? " (plus unbounded planes)" : "",
                       s.bounds_of_group_boxes ? " (of the placed groups' boxes)" : "");
  else
    out << fmt::format("bounds:     none{}\n", s.unbounded ? " (only unbounded planes)" : "");
  const CameraDesc& c = scene.camera;
  if (c.given_vectors)
    out << fmt::format("camera:     {} at {}, direction {} right {} up {} (as given)\n",
                       projection_name(c.projection), vec(c.position), vec(c.direction), vec(c.right), vec(c.up));
  else
    out << fmt::format("camera:     {}{} at {} looking at {}, {}\n",
                       projection_name(c.projection), scene.has_camera ? "" : " (default)", vec(c.position),
                       vec(c.look_at),
                       c.projection == Projection::Perspective ? fmt::format("fov {}", num(c.fov))
                                                               : fmt::format("view width {}", num(c.view_width)));
  const Settings& st = scene.settings;
  out << fmt::format("image:      {}x{}, {} sample{} per pixel, max depth {}\n", st.width, st.height, st.samples,
                     st.samples == 1 ? "" : "s", st.max_depth);
  out << fmt::format("evaluated in {:.3f} s\n", seconds);
}

}  // namespace rts::render
