#include "render/accel/flatten.hpp"

#include <cmath>
#include <string>

#include "render/geometry/tolerances.hpp"

namespace rts::render {
namespace {

Vec3 transform_point(const Mat4& m, const Vec3& p) { return Vec3(m * glm::dvec4(p, 1.0)); }
Vec3 transform_vector(const Mat4& m, const Vec3& v) { return Vec3(m * glm::dvec4(v, 0.0)); }

// A composed child → world transform must be finite and invertible: instances are traced in
// object space through its inverse, and a singular one (a scale of 0, or tiny scales whose
// product underflows) would give NaN rays and normals, or silently lose the object.
void check_transform(const Mat4& m, const SourceRef& loc) {
  if (m == Mat4(1.0)) return;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r]))
        throw RenderError(loc, "transform is not finite (a scale or translation too large?)");
  double det = glm::determinant(glm::dmat3(m));
  if (!std::isfinite(det)) throw RenderError(loc, "transform is not finite (a scale too large?)");
  if (!(std::abs(det) > tol::kSingularDeterminant)) throw RenderError(loc, "transform is singular (scale 0?)");
}

void flatten_child(const SceneDesc& scene, const Child& child, const Mat4& parent, int depth,
                   FlatScene& out) {
  if (depth > tol::kMaxGroupDepth)
    throw RenderError(child.loc, "groups nested more than " + std::to_string(tol::kMaxGroupDepth) +
                                     " deep (a group containing itself?)");
  if (child.node >= scene.nodes.size())
    throw RenderError(child.loc, "internal: instance of unknown node " + std::to_string(child.node));
  const Node& node = scene.nodes[child.node];
  Mat4 m = parent * child.transform;
  switch (node.kind) {
    case NodeKind::Shape:
      if (node.index >= scene.shapes.size()) throw RenderError(node.loc, "internal: unknown shape");
      check_transform(m, child.loc);
      out.shapes.push_back(FlatShape{node.index, m, child.loc});
      break;
    case NodeKind::Light:
      if (node.index >= scene.lights.size()) throw RenderError(node.loc, "internal: unknown light");
      check_transform(m, child.loc);
      out.lights.push_back(transform_light(scene.lights[node.index], m));
      break;
    case NodeKind::Csg:
      if (node.index >= scene.csgs.size()) throw RenderError(node.loc, "internal: unknown CSG block");
      check_transform(m, child.loc);
      out.csgs.push_back(FlatCsg{node.index, m, node.loc});
      break;
    case NodeKind::Group:
      if (node.index >= scene.groups.size()) throw RenderError(node.loc, "internal: unknown group");
      for (const Child& c : scene.groups[node.index].children) flatten_child(scene, c, m, depth + 1, out);
      break;
  }
}

}  // namespace

LightDesc transform_light(const LightDesc& light, const Mat4& m) {
  LightDesc l = light;
  l.position = transform_point(m, light.position);
  l.point_at = transform_point(m, light.point_at);
  l.direction = transform_vector(m, light.direction);
  l.u = transform_vector(m, light.u);
  l.v = transform_vector(m, light.v);
  return l;
}

FlatScene flatten_instance(const SceneDesc& scene, const Child& instance) {
  FlatScene out;
  flatten_child(scene, instance, Mat4(1.0), 0, out);
  return out;
}

FlatScene flatten_scene(const SceneDesc& scene) {
  FlatScene out;
  for (const Child& root : scene.roots) flatten_child(scene, root, Mat4(1.0), 0, out);
  return out;
}

}  // namespace rts::render
