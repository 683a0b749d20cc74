// CSG blocks in World (render/accel/world.hpp): flattening a block into a tree whose leaves
// are instances of their own, and tracing a ray through it. The ray computes only the leaves
// whose state can matter inside its interval (render/geometry/csg/csg_prune.hpp), sweeps their
// crossings (csg_tree.hpp), and computes the full hit only at the surface found; a shadow ray
// stops at the sweep's answer.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <new>
#include <string>

#include "render/accel/world.hpp"
#include "render/geometry/csg/csg_prune.hpp"
#include "render/geometry/csg/leaf_crossings.hpp"
#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

namespace {

// The kinds whose crossings a sweep lists from where it starts, and only so many: closed meshes
// and the solids with leaf_crossings_from (render/geometry/csg/leaf_crossings.hpp).
template <std::size_t... I>
constexpr std::array<bool, 256> windowed_kinds(std::index_sequence<I...>) {
  std::array<bool, 256> k{};
  ((k[I] = std::is_same_v<ShapeKind<I>, MeshRef> ||
           requires(const ShapeKind<I>& g, const Ray& r, CsgLeafCrossings& c) { leaf_crossings_from(g, r, 0.0, c); }),
   ...);
  return k;
}
constexpr std::array<bool, 256> kWindowedKind = windowed_kinds(std::make_index_sequence<kShapeKindCount>());

}  // namespace

void World::add_csg(const SceneDesc& scene, const FlatCsg& block, std::vector<Instance>& parts, Instance& inst,
                    AABB& world_bounds) {
  Csg csg;
  auto transmits = [&](MaterialId m) {
    if (m >= scene.materials.size()) return false;
    const Color& t = scene.materials[m].transmit;
    return t.r > 0.0 || t.g > 0.0 || t.b > 0.0;
  };
  const double inf = Interval::kInfinity;
  std::vector<uint32_t> block_transforms;  // this block's leaf transforms so far
  // Appends the nodes for `node_id` placed by `m`, children before parents; a group is a union.
  auto add_node = [&](auto& self, NodeId node_id, const Mat4& m, MaterialId inherited, int depth) -> void {
    if (node_id >= scene.nodes.size() || depth > tol::kMaxGroupDepth)
      throw RenderError(block.loc, "internal: a CSG block refers to an unknown node");
    const Node& node = scene.nodes[node_id];
    auto add_op = [&](CsgOp op, const std::vector<Child>& kids, MaterialId mat, bool inverse) {
      std::vector<uint32_t> ids;
      for (const Child& c : kids) {
        self(self, c.node, m * c.transform, mat, depth + 1);
        ids.push_back(static_cast<uint32_t>(csg.tree.nodes.size() - 1));
      }
      CsgNode n;
      n.op = op;
      n.inverse = inverse;
      n.first = static_cast<uint32_t>(csg.tree.children.size());
      n.count = static_cast<uint32_t>(ids.size());
      csg.tree.children.insert(csg.tree.children.end(), ids.begin(), ids.end());
      csg.tree.nodes.push_back(n);
    };
    if (node.kind == NodeKind::Group) {
      const GroupDesc& g = scene.groups[node.index];
      add_op(CsgOp::Union, g.children, g.material != kNoId ? g.material : inherited, false);
      return;
    }
    if (node.kind == NodeKind::Csg) {
      const CsgDesc& d = scene.csgs[node.index];
      add_op(d.op, d.children, d.material != kNoId ? d.material : inherited, d.inverse);
      return;
    }
    if (node.kind != NodeKind::Shape) throw RenderError(node_loc(scene, node), "a CSG block holds only shapes");
    const ShapeDesc& shape = scene.shapes[node.index];
    Instance part;
    part.material = shape.material != kNoId ? shape.material : inherited;
    part.transmissive = transmits(part.material);
    AABB object_bounds;
    bool unbounded = false;
    add_geometry(scene, shape, part, object_bounds, unbounded);
    // A height field's solid has no floor (POV-Ray's): its bounds hold only the drawn surface.
    if (shape.geometry.holds<HeightField>()) unbounded = true;
    // Leaves placed by the same matrix (a die's box, sphere and pips under one rotation)
    // share one transform, so a ray is carried into their space once (trace_csg).
    if (m != Mat4(1.0)) {
      auto same = std::find_if(block_transforms.begin(), block_transforms.end(),
                               [&](uint32_t xf) { return instance_to_world(transforms_[xf]) == m; });
      part.transform = same != block_transforms.end() ? *same : add_transform(m);
      if (same == block_transforms.end()) block_transforms.push_back(part.transform);
    }
    AABB box = unbounded ? AABB{Vec3(-inf), Vec3(inf)}
                         : (m == Mat4(1.0) ? object_bounds : transform_bounds(m, object_bounds));
    if (const Sphere* sp = shape_if<Sphere>(shape.geometry); sp && m != Mat4(1.0) && box.valid()) {
      // A rotated sphere's cube of corners is up to sqrt(3) times too wide; the placed
      // sphere (an ellipsoid) reaches exactly r * |row i of the linear part| along axis i.
      // Tighter leaf boxes prune more leaves, and the block's box (a die: its box intersected
      // with its sphere) lets the BVH send fewer rays. Padded by a coincidence tie of the
      // box's scale, so that no crossing computed with rounding falls outside it.
      const Vec3 c(m * glm::dvec4(sp->center, 1.0));
      Vec3 half;
      for (int i = 0; i < 3; ++i)
        half[i] = std::abs(sp->radius) * std::sqrt(m[0][i] * m[0][i] + m[1][i] * m[1][i] + m[2][i] * m[2][i]);
      const Vec3 pad = tol::kCoincidentRelative * (glm::abs(c) + half);
      box.lo = glm::max(box.lo, c - half - pad);
      box.hi = glm::min(box.hi, c + half + pad);
    }
    CsgNode n;
    n.leaf = true;
    n.inverse = shape.inverse;
    n.first = static_cast<uint32_t>(csg.leaf_instance.size());
    csg.leaf_instance.push_back(static_cast<uint32_t>(parts.size()));  // made absolute at the end
    csg.leaf_bounds.push_back(box);
    csg.has_windowed = csg.has_windowed || kWindowedKind[shape.geometry.index()];
    csg.tree.nodes.push_back(n);
    parts.push_back(part);
    inst.transmissive = inst.transmissive || part.transmissive;
  };
  const CsgDesc& d = scene.csgs[block.csg];
  {
    std::vector<uint32_t> top;
    for (const Child& c : d.children) {
      add_node(add_node, c.node, block.to_world * c.transform, d.material != kNoId ? d.material : block.inherited, 0);
      top.push_back(static_cast<uint32_t>(csg.tree.nodes.size() - 1));
    }
    CsgNode n;
    n.op = d.op;
    n.inverse = d.inverse;
    n.first = static_cast<uint32_t>(csg.tree.children.size());
    n.count = static_cast<uint32_t>(top.size());
    csg.tree.children.insert(csg.tree.children.end(), top.begin(), top.end());
    csg.tree.nodes.push_back(n);
  }
  csg.tree.leaf_count = static_cast<uint32_t>(csg.leaf_instance.size());
  if (csg.tree.leaf_count > kMaxCsgLeaves || csg.tree.nodes.size() > kMaxCsgNodes)
    throw RenderError(block.loc, "a CSG block holds more than " + std::to_string(kMaxCsgLeaves) + " shapes");
  world_bounds = csg.tree.bounds(csg.leaf_bounds);
  inst.kind = kCsgKind;
  inst.index = static_cast<uint32_t>(csgs_.size());
  csgs_.push_back(std::move(csg));
}

bool World::intersect_csg(const Instance& inst, const Ray& world_ray, const Interval& ray_t, SurfaceHit& hit) const {
  return trace_csg(inst, world_ray, ray_t, &hit);
}

bool World::occluded_csg(const Instance& inst, const Ray& world_ray, const Interval& ray_t) const {
  return trace_csg(inst, world_ray, ray_t, nullptr);
}

bool World::trace_csg(const Instance& inst, const Ray& world_ray, const Interval& ray_t, SurfaceHit* hit) const {
  const Csg& csg = csgs_[inst.index];
  // Storage for kMaxCsgLeaves lists, left unconstructed: an array of them would run their
  // default member initializers, 256 of them for every ray (the profile's largest cost after
  // pruning). Every list the sweep reads is written first (csg_gather, or the loop below).
  alignas(CsgLeafCrossings) std::byte storage[sizeof(CsgLeafCrossings) * kMaxCsgLeaves];
  CsgLeafCrossings* crossings = std::launder(reinterpret_cast<CsgLeafCrossings*>(storage));
  const RayInverse inv(world_ray.origin, world_ray.direction);
  // Each leaf in its own object space (t is the same in every space).
  // The ray in the space of the last transform used: leaves sharing a transform (add_csg)
  // reuse it.
  uint32_t ray_transform = kNoId;
  Ray transformed = world_ray;
  auto leaf_ray = [&](const Instance& part) -> const Ray& {
    if (part.transform == kNoId) return world_ray;
    if (part.transform != ray_transform) {
      transformed = object_ray(part, world_ray);
      ray_transform = part.transform;
    }
    return transformed;
  };
  auto with_leaf = [&](uint32_t l, auto&& f) -> bool {
    const Instance& part = instances_[csg.leaf_instance[l]];
    const Ray& ray = leaf_ray(part);
    // The part's kind, among those with leaf_crossings() (render/geometry/csg/leaf_crossings.hpp);
    // other kinds are refused when the scene is built (meshes are handled by the callers).
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
      bool result = false;
      (void)((part.kind == I && [&] {
                using T = ShapeKind<I>;
                if constexpr (requires(const T& g, CsgLeafCrossings& c) { leaf_crossings(g, ray, c); })
                  result = f(std::get<I>(shapes_)[part.index], ray);
                return true;
              }()) || ...);
      return result;
    }(std::make_index_sequence<kShapeKindCount>());
  };
  // The same tie as World::intersect's between instances.
  const double tie_abs =
      tol::kCoincidentRelative * max_abs_component(world_ray.origin) / max_abs_component(world_ray.direction);
  const double tie_rel = tol::kCoincidentRelative;
  auto ties = [&](double t) { return tol::kCsgPruneTies * (tie_abs + tie_rel * std::abs(t)); };
  // Leaf l's crossings along the whole line, unless its box misses `span` widened by
  // kCsgPruneTies ties at each end (then it is outside throughout the span; an infinite end
  // stays infinite). An unbounded leaf's box is infinite (add_csg), which every ray meets:
  // its slabs give -inf and +inf, never NaN, since no infinite bound minus an origin is 0.
  auto widen = [&](const Interval& span) { return Interval(span.min - ties(span.min), span.max + ties(span.max)); };
  // A closed mesh, and a solid a line may cross often (leaf_crossings_from), list only their
  // crossings from the span on, and only so many (MeshAccel::csg_crossings,
  // render/geometry/csg/leaf_crossings.hpp): the earliest place one stopped short is where this
  // pass's answer stops being known.
  double stopped_short = Interval::kInfinity;
  Interval window = ray_t;  // where this pass looks for the surface (below)
  // Such a leaf, out of line: the sweep's per-leaf step below stays small enough to be inlined
  // into csg_gather (the profile's largest cost on the csg race scene).
  auto windowed = [&](uint32_t l, const Interval& span) __attribute__((noinline)) {
    CsgLeafCrossings& c = crossings[l];
    const Instance& part = instances_[csg.leaf_instance[l]];
    // From the span's start, or the window's when every leaf is listed over the whole line.
    const double from = widen(Interval(std::max(span.min, window.min), span.max)).min;
    bool short_list = false;
    if (part.kind == kPrimKind<MeshRef>) {
      short_list = meshes_[part.index]->csg_crossings(leaf_ray(part), from, tie_abs, tie_rel, c);
    } else {
      with_leaf(l, [&](const auto& shape, const Ray& ray) {
        if constexpr (requires { leaf_crossings_from(shape, ray, 0.0, c); }) short_list = leaf_crossings_from(shape, ray, from, c);
        return true;
      });
    }
    if (short_list) stopped_short = std::min(stopped_short, c.t[c.count - 1]);
  };
  auto compute = [&](uint32_t l, const Interval& span) {
    if (!slab_hit(csg.leaf_bounds[l], inv, widen(span))) return;
    if (csg.has_windowed && kWindowedKind[instances_[csg.leaf_instance[l]].kind]) return windowed(l, span);
    with_leaf(l, [&](const auto& shape, const Ray& ray) {
      leaf_crossings(shape, ray, crossings[l]);
      return true;
    });
  };
  // Usually one pass. When a leaf's list stopped short, a surface found before that place (less
  // the ties its batch may span) stands; otherwise the sweep runs again from there, every leaf
  // listing its crossings again (a windowed one from the new start).
  CsgSurface surface;
  for (int pass = 0;; ++pass) {
    stopped_short = Interval::kInfinity;
    bool none = false;
    if (csg_pruning_) {
      // A result that cannot be inside anywhere near the window changes state nowhere there,
      // so it shows no surface (the ray met its box but missed its first leaves: most CSG rays).
      none = csg_gather(csg.tree, window, crossings, compute).intersect(widen(window)).empty();
    } else {  // every leaf the whole line meets (tests compare the two)
      const Interval line = pass == 0 ? Interval::universe() : Interval(window.min, Interval::kInfinity);
      for (uint32_t l = 0; l < csg.tree.leaf_count; ++l) {
        crossings[l].count = 0;
        crossings[l].inside_at_start = false;
        compute(l, line);
      }
    }
    const bool found = !none && csg_first_surface(csg.tree, crossings, window, tie_abs, tie_rel, surface);
    if (stopped_short == Interval::kInfinity) {
      if (!found) return false;
      break;
    }
    const double known_until = stopped_short - ties(stopped_short);
    if (found && surface.t < known_until) break;
    // Onwards from where the answer stopped being known (always forwards: the crossings a mesh
    // lists start at the window, so the last one kept lies beyond it).
    const double next = known_until > window.min ? known_until : stopped_short;
    if (!(next > window.min) || !(next < window.max) || pass + 1 >= tol::kCsgMaxPasses) return false;
    window.min = next;
  }
  // A shadow ray needs only that answer: the sweep already stopped at the first surface, and
  // leaf_hit below finds a hit at every crossing leaf_crossings reported.
  if (!hit) return true;
  const CsgLeafCrossings& c = crossings[surface.leaf];
  int k = 0;
  while (k + 1 < c.count && c.t[k] != surface.t) ++k;
  // Out of the result: towards the ray where it enters, along it where it leaves.
  auto orient = [&](const Ray& ray) {
    if ((glm::dot(hit->normal, ray.direction) < 0.0) != surface.entering) {
      hit->normal = -hit->normal;
      hit->shading_normal = -hit->shading_normal;
    }
  };
  bool ok;
  if (const Instance& part = instances_[csg.leaf_instance[surface.leaf]]; part.kind == kPrimKind<MeshRef>) {
    // The triangle hit first among those of that place (they lie within a tie after it).
    const Ray& ray = leaf_ray(part);
    const double near = 2.0 * (tie_abs + tie_rel * std::abs(surface.t));
    ok = meshes_[part.index]->intersect(ray, Interval(surface.t - near, surface.t + near), *hit, part.smooth);
    if (ok) orient(ray);
  } else {
    ok = with_leaf(surface.leaf, [&](const auto& shape, const Ray& ray) {
      if (!leaf_hit(shape, ray, c, k, *hit)) return false;
      orient(ray);
      return true;
    });
  }
  if (!ok) return false;
  hit->t = surface.t;
  hit->csg_part = csg.leaf_instance[surface.leaf];
  return true;
}
}  // namespace rts::render
