// SceneBuilder's scene-graph blocks: shapes (every kind through its ShapeTraits, meshes inline
// or from OBJ files, height fields), lights, groups and CSG blocks. The settings, camera and
// texture blocks are in scene_builder.cpp, materials in material_builder.cpp.
#include "render/builder/scene_builder.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "render/geometry/aabb.hpp"
#include "render/geometry/shapes/shape_kinds.hpp"
#include "render/shade/lights.hpp"
#include "render/builder/block_properties.hpp"
#include "render/builder/height_field_builder.hpp"
#include "render/builder/obj_loader.hpp"
#include "render/builder/pattern_builder.hpp"
#include "render/builder/scene_builder_detail.hpp"
#include "render/geometry/tolerances.hpp"

namespace rts::render {

using builder_detail::add_node;
using builder_detail::names_of;
using builder_detail::resolve_path;
using builder_detail::names_of_block;
using builder_detail::reference;

namespace {

// "material" and each shape kind's own properties, by ShapeGeometry index.
const std::array<std::vector<std::string_view>, kShapeKindCount>& shape_property_names() {
  static const auto table = [] {
    std::array<std::vector<std::string_view>, kShapeKindCount> names;
    for (std::size_t k = 0; k < kShapeKindCount; ++k) {
      names[k].push_back("material");
      for (const PropertyInfo& p : kShapeInfos[k].properties) names[k].push_back(p.name);
      names[k].push_back("casts_shadow");
    }
    return names;
  }();
  return table;
}
template <class T>
const std::vector<std::string_view>& names_of() {
  return shape_property_names()[shape_index<T>()];
}
const std::vector<std::string_view> kPointLightNames = names_of_block("point_light");
const std::vector<std::string_view> kSpotLightNames = names_of_block("spot_light");
const std::vector<std::string_view> kDirectionalLightNames = names_of_block("directional_light");
const std::vector<std::string_view> kAreaLightNames = names_of_block("area_light");

const std::vector<std::string_view> kCsgNames = names_of_block("union");
const std::vector<std::string_view> kGroupNames = names_of_block("group");
const std::vector<std::string_view> kTextNames = names_of_block("text");


// The same file however a scene spells it ("a/../m.obj", "./m.obj", through a symlink).
std::string cache_key(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::path(path), ec);
  if (ec) p = fs::absolute(fs::path(path), ec).lexically_normal();
  return ec ? path : p.string();
}

bool is_obj_name(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj";
}

// Appends a scene node for the shape, light or group at `index`; returns its id.
uint32_t mesh_index(ParamSet& ps, double v, std::size_t vertex_count) {
  if (std::floor(v) != v || v < 0 || v >= static_cast<double>(vertex_count))
    throw SceneError(loc_of(ps, "faces"),
                     fmt::format("mesh face index {} out of range ({} vertices)", v, vertex_count));
  return static_cast<uint32_t>(v);
}

// `vertices`/`faces`/`normals` are lists of vectors; an empty list arrives as numbers.
std::vector<Vec3> vector_list(ParamSet& ps, std::string_view name) {
  const ParamValue* v = ps.value(name);
  if (!v) return {};
  if (auto* l = std::get_if<std::vector<Vec3>>(v)) return *l;
  if (auto* l = std::get_if<std::vector<double>>(v); l && l->empty()) return {};
  throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} expects a list of vectors, got a {}", name,
                                                 ps.kind(), param_type_name(*v)));
}

// Per-vertex material lists of a triangle or mesh (`vertex_colors`, `vertex_diffuse`,
// `vertex_specular`, `vertex_shininess`), each absent or one entry per vertex; false when the
// block has none of them.
bool vertex_material(ParamSet& ps, std::size_t vertex_count, MeshData& mesh) {
  bool any = false;
  auto count_check = [&](std::string_view name, std::size_t n) {
    if (n != vertex_count)
      throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} has {} entries for {} vertices", name,
                                                     ps.kind(), n, vertex_count));
    any = true;
  };
  // A list of colors, one per vertex, none negative.
  auto colors_into = [&](std::string_view name, std::vector<glm::vec3>& out) {
    std::vector<Vec3> colors = vector_list(ps, name);
    count_check(name, colors.size());
    for (const Vec3& c : colors) {
      if (!(c.x >= 0 && c.y >= 0 && c.z >= 0) || !std::isfinite(c.x + c.y + c.z))
        throw SceneError(loc_of(ps, name), fmt::format("property '{}' must not be negative", name));
      out.emplace_back(c);
    }
  };
  if (ps.has("vertex_colors")) colors_into("vertex_colors", mesh.colors);
  // `vertex_specular`: numbers (white highlights of that weight) or colors (tinted ones, as
  // CSCI 420's per-vertex `spe` and UW's per-vertex `specular`).
  if (ps.has("vertex_specular")) {
    const ParamValue* v = ps.value("vertex_specular");
    if (const auto* numbers = std::get_if<std::vector<double>>(v)) {
      count_check("vertex_specular", numbers->size());
      for (double x : *numbers) {
        require(ps, "vertex_specular", x >= 0 && std::isfinite(x), ">= 0", x);
        mesh.specular.emplace_back(static_cast<float>(x));
      }
    } else if (std::get_if<std::vector<Vec3>>(v)) {
      colors_into("vertex_specular", mesh.specular);
    } else {
      throw SceneError(loc_of(ps, "vertex_specular"),
                       fmt::format("property 'vertex_specular' of {} expects a list of numbers or colors, got a {}",
                                   ps.kind(), param_type_name(*v)));
    }
  }
  for (auto [name, out] : {std::pair<std::string_view, std::vector<float>*>{"vertex_diffuse", &mesh.diffuse},
                           {"vertex_shininess", &mesh.shininess}}) {
    if (!ps.has(name)) continue;
    const ParamValue* v = ps.value(name);
    auto* list = std::get_if<std::vector<double>>(v);
    if (!list)
      throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} expects a list of numbers, got a {}", name,
                                                     ps.kind(), param_type_name(*v)));
    count_check(name, list->size());
    for (double x : *list) {
      require(ps, name, x >= 0 && std::isfinite(x), ">= 0", x);
      out->push_back(static_cast<float>(x));
    }
  }
  return any;
}

// Zero area by the renderer's own test (the angle between the edges below
// tol::kTriangleDeterminant): such triangles are never hit.
bool degenerate_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  // The ray that sees the triangle best runs along its normal.
  const Vec3 e1 = b - a, e2 = c - a;
  return !detail::crosses_plane(unit_vector(glm::cross(e1, e2)), e1, e2);
}

// A mesh keeps its vertices as floats relative to its centre: spans past float's range
// (3.4e38) would be infinite and spans below its normal numbers (1.2e-38) lose their digits,
// so the faces silently vanished ("zero area"). A transform has neither limit.
void check_single_precision_extent(ParamSet& ps, const AABB& box) {
  if (!box.valid() || !box.finite()) return;
  const double span = max_abs_component(box.extent());
  if (span > 1e38 || (span > 0.0 && span < 1e-36))
    throw SceneError(loc_of(ps, "vertices"),
                     fmt::format("mesh vertices span {:g} units: meshes are stored in single precision, which "
                                 "keeps spans from 1e-36 to 1e38; model the mesh near unit size and place it "
                                 "with a `scale` transform",
                                 span));
}

// One warning per mesh: how many faces are skipped and how many vertex normals cannot be
// used (zero length or NaN: the face normal shades there instead).
void warn_degenerate(const MeshData& mesh, SourceRef where, std::vector<Warning>& warnings) {
  std::size_t faces = mesh.indices.size() / 3, skipped = 0, first = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    const uint32_t* i = &mesh.indices[f * 3];
    if (i[0] >= mesh.positions.size() || i[1] >= mesh.positions.size() || i[2] >= mesh.positions.size()) continue;
    if (degenerate_triangle(Vec3(mesh.positions[i[0]]), Vec3(mesh.positions[i[1]]), Vec3(mesh.positions[i[2]])) &&
        skipped++ == 0)
      first = f;
  }
  if (skipped > 0)
    warnings.push_back({where, fmt::format("mesh: {} of {} faces have zero area (collinear or repeated vertices; "
                                           "first: face {}): they are skipped",
                                           skipped, faces, first)});
  std::size_t bad_normals = 0;
  for (const glm::vec3& n : mesh.normals) {
    float len2 = glm::dot(n, n);
    if (!(len2 > 0.0f) || !std::isfinite(len2)) ++bad_normals;
  }
  if (bad_normals > 0)
    warnings.push_back({where, fmt::format("mesh: {} of {} vertex normals are zero or not finite: the face normal "
                                           "is used there",
                                           bad_normals, mesh.normals.size())});
}

// The kinds whose descriptor builds them from their parameters alone (ShapeTraits<T>::build):
// true when `kind` is one of them and `out` is built. Triangles and meshes, which may create
// MeshData, are built by SceneBuilder::shape itself.
template <std::size_t... I>
bool build_described(std::index_sequence<I...>, std::string_view kind, ParamSet& ps, StoredGeometry& out) {
  return ((kShapeInfos[I].name == kind && [&] {
            using T = ShapeKind<I>;
            if constexpr (requires { ShapeTraits<T>::build(ps); }) {
              out = ShapeTraits<T>::build(ps);
              ps.check_unused(names_of<T>());
              return true;
            } else {
              return false;
            }
          }()) ||
          ...);
}

}  // namespace

namespace builder_detail {

NodeId add_node(SceneDesc& scene, NodeKind kind, std::size_t index, SourceRef loc) {
  // The item keeps where it was written (a shape's and a light's were set from the same
  // block's location when they were made).
  if (kind == NodeKind::Group) scene.groups[index].loc = loc;
  if (kind == NodeKind::Csg) scene.csgs[index].loc = loc;
  scene.nodes.push_back(Node{kind, static_cast<uint32_t>(index)});
  return static_cast<NodeId>(scene.nodes.size() - 1);
}

// The names a shape, light or CSG kind takes, or null for other kinds.
const std::vector<std::string_view>* names_of(std::string_view kind) {
  for (std::size_t k = 0; k < kShapeKindCount; ++k)
    if (kShapeInfos[k].name == kind) return &shape_property_names()[k];
  static const std::pair<std::string_view, const std::vector<std::string_view>*> kTable[] = {
      {"point_light", &kPointLightNames},  {"spot_light", &kSpotLightNames}, {"area_light", &kAreaLightNames},
      {"directional_light", &kDirectionalLightNames}, {"union", &kCsgNames}, {"intersection", &kCsgNames},
      {"difference", &kCsgNames},          {"merge", &kCsgNames},         {"clip", &kCsgNames},        {"text", &kTextNames},
      {"group", &kGroupNames}};
  for (const auto& [name, names] : kTable)
    if (name == kind) return names;
  return nullptr;
}

}  // namespace builder_detail

NodeId SceneBuilder::shape(std::string_view kind, ParamSet& ps) {
  ShapeDesc s;
  s.loc = ps.loc();
  ps.set_valid_names(names_of(kind));  // a missing property is first checked for a misspelling
  if (const MaterialRef* ref = reference<MaterialRef>(ps, "material", kind, "material")) s.material = ref->id;
  if (kind == "text") {  // a group of glyph prisms (text_builder.cpp)
    s.casts_shadow = ps.boolean("casts_shadow", true);
    return text(ps, s);
  }
  // `inverse` (for CSG) is read first, on solids only: an open shape's `inverse` stays an
  // unknown property, and the names each kind lists stay its descriptor's.
  if (const ShapeInfo* info = find_shape(kind); info && info->closure != Closure::Open)
    s.inverse = ps.boolean("inverse", false);
  s.casts_shadow = ps.boolean("casts_shadow", true);
  if (build_described(std::make_index_sequence<kShapeKindCount>(), kind, ps, s.geometry)) {
    // built by its descriptor
  } else if (kind == "triangle") {
    Triangle g;
    g.v0 = ps.require_vec3("v0");
    g.v1 = ps.require_vec3("v1");
    g.v2 = ps.require_vec3("v2");
    int normals = ps.has("n0") + ps.has("n1") + ps.has("n2");
    if (normals != 0 && normals != 3) ps.fail_block("triangle needs all of n0, n1, n2 or none of them");
    if (normals == 3) {
      g.normals = Boxed<TriangleNormals>(
          TriangleNormals{ps.vec3("n0", Vec3(0.0)), ps.vec3("n1", Vec3(0.0)), ps.vec3("n2", Vec3(0.0))});
    }
    auto mesh = std::make_shared<MeshData>();
    if (vertex_material(ps, 3, *mesh)) {
      // A triangle whose vertices carry material values is traced as a one-triangle mesh,
      // which knows how to interpolate them.
      for (const Vec3& v : {g.v0, g.v1, g.v2}) mesh->positions.emplace_back(v);
      if (g.normals)
        for (const Vec3& n : {g.normals->n0, g.normals->n1, g.normals->n2}) mesh->normals.emplace_back(glm::normalize(n));
      mesh->indices = {0, 1, 2};
      scene_.meshes.push_back(std::move(mesh));
      s.geometry = MeshRef{static_cast<MeshId>(scene_.meshes.size() - 1), static_cast<bool>(g.normals)};
    } else {
      if (degenerate_triangle(g.v0, g.v1, g.v2))
        scene_.warnings.push_back({ps.loc(), "triangle has zero area (collinear or repeated vertices): it is skipped"});
      s.geometry = g;
    }
    ps.check_unused(names_of<Triangle>());
  } else if (kind == "height_field") {
    std::string path;
    if (ps.has("file")) {
      SourceRef where = loc_of(ps, "file");
      std::string file = ps.string("file", "");
      path = resolve_path(file, where);
      check_readable(path, file, "height_field image", where);
    }
    s.geometry = build_height_field(ps, path, limits_.max_memory);
    ps.check_unused(names_of<HeightField>());
  } else if (kind == "mesh") {
    MeshRef g;
    g.smooth = ps.boolean("smooth", g.smooth);
    const std::string weights = ps.string("smooth_weights", "area");
    if (weights != "area" && weights != "equal")
      throw SceneError(loc_of(ps, "smooth_weights"),
                       fmt::format("property 'smooth_weights' of mesh must be \"area\" or \"equal\", got \"{}\"",
                                   weights));
    const bool equal_weights = weights == "equal";
    std::shared_ptr<MeshData> mesh;
    std::optional<std::pair<std::string, int>> obj_key;
    if (ps.has("file")) {
      if (ps.has("vertices") || ps.has("faces"))
        ps.fail_block("mesh takes either 'file' or 'vertices' and 'faces', not both");
      SourceRef where = loc_of(ps, "file");
      std::string file = ps.string("file", "");
      std::string path = resolve_path(file, where);
      check_readable(path, file, "mesh file", where);
      obj_key = std::make_pair(cache_key(path), g.smooth ? (equal_weights ? 2 : 1) : 0);
      // Errors quote lines of a malformed OBJ, so no other kind of file is read as one
      // (`file = "/etc/shadow"` must not show its lines). Checked after links are resolved.
      if (!is_obj_name(obj_key->first))
        throw SceneError(where, fmt::format("cannot read mesh file '{}': mesh files must be Wavefront OBJ files named "
                                            "*.obj",
                                            file));
      if (auto it = obj_meshes_.find(*obj_key); it != obj_meshes_.end()) {
        g.mesh = it->second;  // already loaded (and counted against the triangle limit): share it
      } else {
        ObjLimits limits;
        limits.max_triangles = limits_.max_mesh_triangles - std::min(mesh_triangles_, limits_.max_mesh_triangles);
        limits.max_memory = limits_.max_memory;
        mesh = load_obj(path, file, g.smooth && !equal_weights, where, limits);
        if (g.smooth && equal_weights && mesh->normals.empty()) compute_smooth_normals(*mesh, true);
      }
      for (std::string_view name : {"vertex_colors", "vertex_diffuse", "vertex_specular", "vertex_shininess"})
        if (ps.has(name))
          throw SceneError(loc_of(ps, name), fmt::format("property '{}' of mesh needs inline 'vertices' (OBJ files "
                                                         "carry their own vertex colors: v x y z r g b)", name));
    } else {
      if (!ps.has("vertices")) ps.fail_block("mesh needs property 'file' or 'vertices' and 'faces'");
      if (!ps.has("faces")) ps.fail_block("mesh needs property 'faces'");
      std::vector<Vec3> vertices = vector_list(ps, "vertices");
      std::vector<Vec3> faces = vector_list(ps, "faces");
      std::vector<Vec3> normals = vector_list(ps, "normals");
      if (faces.empty()) throw SceneError(loc_of(ps, "faces"), "mesh needs at least one face");
      if (!normals.empty() && normals.size() != vertices.size())
        throw SceneError(loc_of(ps, "normals"),
                         fmt::format("mesh has {} vertices but {} normals", vertices.size(), normals.size()));
      mesh = std::make_shared<MeshData>();
      // Stored as float relative to the centre of the vertices' bounds (MeshData::origin).
      AABB box;
      for (const Vec3& v : vertices) box.extend(v);
      if (box.valid() && box.finite()) mesh->origin = box.centroid();
      check_single_precision_extent(ps, box);
      for (const Vec3& v : vertices) mesh->positions.emplace_back(v - mesh->origin);
      for (const Vec3& n : normals) mesh->normals.emplace_back(glm::normalize(n));
      for (const Vec3& f : faces)
        for (int k = 0; k < 3; ++k) mesh->indices.push_back(mesh_index(ps, f[k], vertices.size()));
      if (normals.empty() && g.smooth) compute_smooth_normals(*mesh, equal_weights);
      vertex_material(ps, vertices.size(), *mesh);
    }
    if (mesh) warn_degenerate(*mesh, ps.loc(), scene_.warnings);
    if (mesh) {  // newly built or loaded
      mesh_triangles_ += mesh->indices.size() / 3;
      if (mesh_triangles_ > limits_.max_mesh_triangles)
        ps.fail_block(fmt::format("meshes have more than {} triangles in total (raise with --max-mesh-triangles)",
                                  limits_.max_mesh_triangles));
      scene_.meshes.push_back(std::move(mesh));
      g.mesh = static_cast<MeshId>(scene_.meshes.size() - 1);
      if (obj_key) obj_meshes_.emplace(std::move(*obj_key), g.mesh);
    }
    s.geometry = g;
    ps.check_unused(names_of<MeshRef>());
  } else {
    ps.fail_block(fmt::format("'{}' is not a shape", kind));
  }
  scene_.shapes.push_back(std::move(s));
  return add_node(scene_, NodeKind::Shape, scene_.shapes.size() - 1, ps.loc());
}

NodeId SceneBuilder::light(std::string_view kind, ParamSet& ps) {
  LightDesc l;
  l.loc = ps.loc();
  ps.set_valid_names(names_of(kind));  // a missing property is first checked for a misspelling
  l.color = ps.color("color", l.color);
  non_negative_color(ps, "color", l.color);
  l.intensity = non_negative(ps, "intensity", ps.number("intensity", l.intensity));
  l.shadows = ps.boolean("shadows", l.shadows);
  auto attenuation = [&] {
    l.attenuation = ps.vec3("attenuation", l.attenuation);
    const Vec3& a = l.attenuation;
    if (a.x < 0 || a.y < 0 || a.z < 0 || a.x + a.y + a.z <= 0)
      throw SceneError(loc_of(ps, "attenuation"),
                       "property 'attenuation' must have non-negative components, not all zero");
    l.attenuation_clamp = ps.boolean("attenuation_clamp", l.attenuation_clamp);
  };
  // A spot's cone: its axis towards point_at, full within radius, none past falloff (spot_light,
  // and an area_light with point_at).
  auto spot_cone = [&] {
    l.point_at = ps.require_vec3("point_at");
    distinct(ps, "point_at", "position", l.point_at - l.position);
    l.radius = ps.number("radius", l.radius);
    // 90: full intensity over the whole front half-space; 0: none at full intensity, the
    // falloff cone alone (POV-Ray scenes use both).
    require(ps, "radius", l.radius >= 0 && l.radius <= 90, "from 0 to 90 degrees", l.radius);
    l.falloff = ps.number("falloff", std::max(l.falloff, l.radius));
    require(ps, "falloff", l.falloff >= l.radius && l.falloff <= 90, ">= radius and <= 90 degrees", l.falloff);
  };
  if (kind == "point_light") {
    l.kind = LightKind::Point;
    l.position = ps.require_vec3("position");
    attenuation();
    ps.check_unused(kPointLightNames);
  } else if (kind == "spot_light") {
    l.kind = LightKind::Spot;
    l.position = ps.require_vec3("position");
    spot_cone();
    attenuation();
    ps.check_unused(kSpotLightNames);
  } else if (kind == "directional_light") {
    l.kind = LightKind::Directional;
    l.direction = unit_vector(direction(ps, "direction", ps.require_vec3("direction")));
    ps.check_unused(kDirectionalLightNames);
  } else if (kind == "area_light") {
    l.kind = LightKind::Area;
    l.position = ps.require_vec3("position");
    l.u = direction(ps, "u", ps.require_vec3("u"));
    l.v = direction(ps, "v", ps.require_vec3("v"));
    l.auto_samples = !ps.has("samples");
    l.samples = ps.integer("samples", l.samples);
    require(ps, "samples", l.samples >= 1, ">= 1", l.samples);
    if (l.samples > kMaxAreaSamples) {
      warnings_.push_back(SceneWarning{loc_of(ps, "samples"),
                                       fmt::format("area_light samples {} is more than {}; {} are used",
                                                   l.samples, kMaxAreaSamples, kMaxAreaSamples)});
      l.samples = kMaxAreaSamples;
    }
    l.disc = ps.boolean("disc", l.disc);
    if (ps.has("point_at")) {
      // A spot's cone on an area light (POV-Ray's spotlight with area_light), from its centre.
      l.area_spot = true;
      spot_cone();
    } else if (ps.has("radius") || ps.has("falloff")) {
      const char* name = ps.has("radius") ? "radius" : "falloff";
      throw SceneError(loc_of(ps, name), fmt::format("property '{}' of area_light needs 'point_at' (the spot's axis)", name));
    }
    attenuation();
    ps.check_unused(kAreaLightNames);
  } else {
    ps.fail_block(fmt::format("'{}' is not a light", kind));
  }
  scene_.lights.push_back(std::move(l));
  return add_node(scene_, NodeKind::Light, scene_.lights.size() - 1, ps.loc());
}

NodeId SceneBuilder::group(std::vector<Child> children, SourceRef loc) {
  scene_.groups.push_back(GroupDesc{std::move(children), kNoId});
  return add_node(scene_, NodeKind::Group, scene_.groups.size() - 1, loc);
}

NodeId SceneBuilder::group(std::vector<Child> children, ParamSet& ps) {
  ps.set_valid_names(&kGroupNames);
  GroupDesc g{std::move(children), kNoId};
  if (const MaterialRef* ref = reference<MaterialRef>(ps, "material", "group", "material")) g.material = ref->id;
  g.casts_shadow = ps.boolean("casts_shadow", true);
  ps.check_unused(kGroupNames);
  scene_.groups.push_back(std::move(g));
  return add_node(scene_, NodeKind::Group, scene_.groups.size() - 1, ps.loc());
}

namespace {

// Why `id` (a child of a CSG block of kind `op`) cannot take part, or "" when it can: CSG
// combines solids, so a light or an open surface (no inside: a disc, an uncapped cylinder, a
// mesh with holes) is refused. Blocks inside were checked when they were built. `closure`
// tells whether a mesh bounds a solid (computed once per mesh).
template <class MeshClosureOf>
std::string csg_refusal(const SceneDesc& scene, NodeId id, std::string_view op, MeshClosureOf& closure, int depth = 0) {
  const Node& node = scene.nodes[id];
  if (node.kind == NodeKind::Light) return "a light cannot be part of a CSG block (place it beside the block)";
  if (node.kind == NodeKind::Csg) return "";
  if (node.kind == NodeKind::Group) {
    if (depth > tol::kMaxGroupDepth) return "groups nested too deep";
    for (const Child& c : scene.groups[node.index].children)
      if (std::string why = csg_refusal(scene, c.node, op, closure, depth + 1); !why.empty()) return why;
    return "";
  }
  const ShapeDesc& s = scene.shapes[node.index];
  const ShapeInfo& info = kShapeInfos[s.geometry.index()];
  if (const auto* m = shape_if<MeshRef>(s.geometry)) {
    if (m->mesh >= scene.meshes.size() || !scene.meshes[m->mesh]) return "internal: unknown mesh";
    const MeshClosure& c = closure(*scene.meshes[m->mesh]);
    if (c.closed) return "";
    if (c.triangles == 0) return fmt::format("an empty mesh cannot be part of '{}': it has no inside", op);
    auto v = [](const Vec3& p) { return fmt::format("<{:g}, {:g}, {:g}>", p.x, p.y, p.z); };
    if (c.inconsistent)
      return fmt::format("this mesh cannot be part of '{}': its faces are not wound consistently, so it has no "
                         "inside (the edge from {} to {} is walked the same way by two triangles; {} edge{} in all). "
                         "Every triangle must list its corners in the same turning order seen from outside",
                         op, v(c.edge_from), v(c.edge_to), c.open_edges, c.open_edges == 1 ? "" : "s");
    return fmt::format("this mesh cannot be part of '{}': it is not closed, so it has no inside ({} edge{} belong{} "
                       "to one triangle only, the first from {} to {}). CSG needs a watertight mesh; use a group "
                       "to place an open one beside the block",
                       op, c.open_edges, c.open_edges == 1 ? "" : "s", c.open_edges == 1 ? "s" : "", v(c.edge_from),
                       v(c.edge_to));
  }
  bool open = info.closure == Closure::Open;
  if (const auto* c = shape_if<Cylinder>(s.geometry)) open = !c->capped;
  if (const auto* c = shape_if<Cone>(s.geometry)) open = !c->capped;
  if (const auto* c = shape_if<Sor>(s.geometry)) open = (*c)->open;
  if (const auto* c = shape_if<Lathe>(s.geometry)) open = !(*c)->closed;
  if (const auto* c = shape_if<Prism>(s.geometry)) open = (*c)->open;
  if (open) {
    bool capped_kind = info.closure == Closure::WhenCapped;
    std::string what = fmt::format("{} {}", capped_kind ? "an uncapped" : "a", info.name);
    return fmt::format("{} cannot be part of '{}': it is an open surface with no inside, and CSG combines solids "
                       "(use a group to place it beside the block, or a closed shape: box, sphere, capped cylinder)",
                       what, op);
  }
  return "";
}

}  // namespace

NodeId SceneBuilder::csg(std::string_view kind, std::vector<Child> children, ParamSet& ps) {
  ps.set_valid_names(names_of(kind));
  CsgDesc d;
  d.op = kind == "intersection" ? CsgOp::Intersection
         : kind == "difference" ? CsgOp::Difference
         : kind == "merge"      ? CsgOp::Merge
         : kind == "clip"       ? CsgOp::Clip
                                : CsgOp::Union;
  if (children.empty()) ps.fail_block(fmt::format("{} needs at least one shape", kind));
  auto closure_of = [this](const MeshData& m) -> const MeshClosure& {
    auto it = mesh_closures_.find(&m);
    if (it == mesh_closures_.end()) it = mesh_closures_.emplace(&m, mesh_closure(m)).first;
    return it->second;
  };
  for (const Child& c : children) {
    if (std::string why = csg_refusal(scene_, c.node, kind, closure_of); !why.empty()) throw SceneError(c.loc, why);
    // A block is one object to shadow rays: a part's own casts_shadow cannot apply.
    const Node& n = scene_.nodes[c.node];
    if ((n.kind == NodeKind::Shape && !scene_.shapes[n.index].casts_shadow) ||
        (n.kind == NodeKind::Group && !scene_.groups[n.index].casts_shadow) ||
        (n.kind == NodeKind::Csg && !scene_.csgs[n.index].casts_shadow))
      scene_.warnings.push_back({c.loc, fmt::format("casts_shadow = false on a part of '{}' has no effect: a CSG "
                                                    "block casts its shadow as a whole (give the block "
                                                    "casts_shadow = false)", kind)});
  }
  if (const MaterialRef* ref = reference<MaterialRef>(ps, "material", kind, "material")) d.material = ref->id;
  d.inverse = ps.boolean("inverse", false);
  d.casts_shadow = ps.boolean("casts_shadow", true);
  ps.check_unused(kCsgNames);
  d.children = std::move(children);
  scene_.csgs.push_back(std::move(d));
  return add_node(scene_, NodeKind::Csg, scene_.csgs.size() - 1, ps.loc());
}

void SceneBuilder::place(const Child& instance) { scene_.roots.push_back(instance); }

void SceneBuilder::check_readable(const std::string& path, const std::string& shown, std::string_view what,
                                  SourceRef where) const {
  if (!read_policy_.allows(path)) throw SceneError(where, read_policy_.refusal(shown, path));
  if (std::string kind = non_regular_kind(path); !kind.empty())
    throw SceneError(where, fmt::format("cannot read {} '{}': it is {}, not a file", what, shown, kind));
}

}  // namespace rts::render
