// Helpers to build small SceneDescs in tests, without the scene language.
#pragma once

#include <algorithm>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/scene/scene.hpp"

namespace rts::render::test {

inline MaterialId add_material(SceneDesc& s, const MaterialDesc& m) {
  s.materials.push_back(m);
  return static_cast<MaterialId>(s.materials.size() - 1);
}

inline NodeId add_shape(SceneDesc& s, ShapeGeometry g, MaterialId material = kNoId) {
  ShapeDesc shape;
  shape.geometry = std::move(g);
  shape.material = material;
  s.shapes.push_back(std::move(shape));
  s.nodes.push_back(Node{NodeKind::Shape, static_cast<uint32_t>(s.shapes.size() - 1)});
  return static_cast<NodeId>(s.nodes.size() - 1);
}

inline NodeId add_light(SceneDesc& s, const LightDesc& l) {
  s.lights.push_back(l);
  s.nodes.push_back(Node{NodeKind::Light, static_cast<uint32_t>(s.lights.size() - 1)});
  return static_cast<NodeId>(s.nodes.size() - 1);
}

inline NodeId add_group(SceneDesc& s, std::vector<Child> children, MaterialId material = kNoId) {
  s.groups.push_back(GroupDesc{std::move(children), material});
  s.nodes.push_back(Node{NodeKind::Group, static_cast<uint32_t>(s.groups.size() - 1)});
  return static_cast<NodeId>(s.nodes.size() - 1);
}

inline NodeId add_csg(SceneDesc& s, CsgDesc block) {
  s.csgs.push_back(std::move(block));
  s.nodes.push_back(Node{NodeKind::Csg, static_cast<uint32_t>(s.csgs.size() - 1)});
  return static_cast<NodeId>(s.nodes.size() - 1);
}

inline void place(SceneDesc& s, NodeId node, const Mat4& transform = Mat4(1.0)) {
  s.roots.push_back(Child{node, transform, {}});
}

// Emits exactly `c`: no ambient, diffuse or specular response.
inline MaterialDesc emissive(Color c) {
  MaterialDesc m;
  m.emission = c;
  m.ambient = 0;
  m.diffuse = 0;
  return m;
}

// A checker of black (color1: the first choice) and white (the second), cells of side 1.
inline TextureId add_checker(SceneDesc& s) {
  TextureDesc t;
  t.kind = TextureKind::Checker;
  t.color1 = Color(0.0);
  t.color2 = Color(1.0);
  t.scale = 1.0;
  s.textures.push_back(t);
  return static_cast<TextureId>(s.textures.size() - 1);
}

// The choices stored together, then the chooser (as the builder stores them).
inline MaterialId add_chooser(SceneDesc& s, TextureId pattern, const std::vector<MaterialDesc>& choices) {
  MaterialDesc m;
  m.choice_pattern = pattern;
  m.first_choice = static_cast<MaterialId>(s.materials.size());
  m.choice_count = static_cast<uint32_t>(choices.size());
  m.transmit = Color(0.0);  // the most any choice transmits, as the builder sets it
  for (const MaterialDesc& c : choices) {
    s.materials.push_back(c);
    m.transmit = Color(std::max(m.transmit.r, c.transmit.r), std::max(m.transmit.g, c.transmit.g),
                       std::max(m.transmit.b, c.transmit.b));
  }
  return add_material(s, m);
}

// A flat triangle without vertex normals.
inline Triangle triangle(Vec3 a, Vec3 b, Vec3 c) {
  Triangle t;
  t.v0 = a;
  t.v1 = b;
  t.v2 = c;
  return t;
}

// An orthographic camera straight down on the y = 0 plane from y = 5, `view_width` units wide,
// +z up in the image.
inline SceneDesc top_down_scene(int width, int height, double view_width) {
  SceneDesc s;
  s.settings.width = width;
  s.settings.height = height;
  s.has_camera = true;
  s.camera.projection = Projection::Orthographic;
  s.camera.position = Vec3(0, 5, 0);
  s.camera.look_at = Vec3(0, 0, 0);
  s.camera.up = Vec3(0, 0, 1);
  s.camera.view_width = view_width;
  return s;
}

inline Mat4 translate(Vec3 v) { return glm::translate(Mat4(1.0), v); }
inline Mat4 scale(Vec3 v) { return glm::scale(Mat4(1.0), v); }
inline Mat4 rotate_deg(double deg, Vec3 axis) { return glm::rotate(Mat4(1.0), glm::radians(deg), axis); }

}  // namespace rts::render::test
