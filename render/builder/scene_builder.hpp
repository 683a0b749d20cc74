// The narrow interface through which the evaluator builds a scene (pbrt's ParserTarget).
// Each call takes the block's parameters and location; it validates names and types, fills
// the SceneDesc, and throws SceneError (located) on anything wrong. Nothing here knows the
// scene language's syntax.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "render/geometry/shapes/mesh_closure.hpp"
#include "render/scene/params.hpp"
#include "render/scene/resource_limits.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

enum class BlockCategory { Settings, Camera, Material, Texture, Shape, Light, Group, Csg, Unknown };

struct BuilderLimits {
  std::size_t max_mesh_triangles = 50'000'000;  // OBJ / inline meshes, in total
  std::size_t max_memory = 0;                   // bytes the process may hold (0: no limit)
};

// Something valid but probably not what the scene meant (a clamped value), located.
struct SceneWarning {
  SourceRef where;
  std::string message;
};

class SceneBuilder {
 public:
  explicit SceneBuilder(BuilderLimits limits = {}) : limits_(limits) {}

  // What a block kind name means: "sphere" → Shape, "point_light" → Light, "checker" →
  // Texture, "material", "group", "camera", "settings"; anything else → Unknown.
  static BlockCategory category(std::string_view kind);
  // Every block kind name, for "did you mean" suggestions.
  static std::vector<std::string_view> block_kinds();
  // The properties a block kind takes (the names its unknown-property check accepts); empty
  // for group and unknown kinds. Docs and the fuzz dictionary are checked against these.
  static std::vector<std::string_view> property_names(std::string_view kind);

  void settings(ParamSet& params);                            // may be called more than once;
  void camera(ParamSet& params);                              // later values override
  void given_vectors_camera(ParamSet& params, CameraDesc& c);  // camera { direction right up }
  void output_settings(ParamSet& params, Settings& s);         // settings { aov depth_range ... }
  TextureId texture(std::string_view kind, ParamSet& params, const Mat4& transform = Mat4(1.0));
  MaterialId material(ParamSet& params);
  MaterialId chosen_material(ParamSet& params);  // material { pattern  materials }
  MaterialId layered_material(ParamSet& params);  // material { layers }
  // An ordinary material from `params`, starting from `start`'s values (else the defaults).
  MaterialId ordinary_material(ParamSet& params, const MaterialDesc* start);
  // text { font string thickness offset }: a group of glyph prisms (text_builder.cpp); `base`
  // holds the material and casts_shadow every glyph takes.
  NodeId text(ParamSet& params, const ShapeDesc& base);
  MediumId medium(ParamSet& params);  // the media_* properties of a material or settings; kNoId if none
  NodeId shape(std::string_view kind, ParamSet& params);      // not placed yet
  NodeId light(std::string_view kind, ParamSet& params);      // not placed yet
  NodeId group(std::vector<Child> children, SourceRef loc);
  // A group with properties: `material`, the default of members that have none.
  NodeId group(std::vector<Child> children, ParamSet& params);
  // `union`, `intersection`, `difference` or `merge` of the children (properties `material`,
  // the children's default, and `inverse`). Throws SceneError when a child cannot take part:
  // a light, or an open shape (no inside) in anything but a union.
  NodeId csg(std::string_view kind, std::vector<Child> children, ParamSet& params);
  void place(const Child& instance);                          // into the world

  // Files (meshes, image textures) outside the policy's folders are refused (SceneError).
  void set_read_policy(ReadPolicy policy) { read_policy_ = std::move(policy); }
  // Warnings since the last call, oldest first.
  std::vector<SceneWarning> take_warnings() { return std::exchange(warnings_, {}); }

  std::size_t object_count() const { return scene_.shapes.size(); }
  const SceneDesc& scene() const { return scene_; }
  SceneDesc finish() { return std::move(scene_); }

 private:
  void sky_sphere(ParamSet& params, TextureDesc& t);           // texture(): `sky_sphere { layers }`
  // Checks that the scene may read `path` (as the scene wrote it: `shown`) and that it is a
  // regular file, not a FIFO or device that would block or never end.
  void check_readable(const std::string& path, const std::string& shown, std::string_view what, SourceRef where) const;

  BuilderLimits limits_;
  ReadPolicy read_policy_;
  std::vector<SceneWarning> warnings_;
  SceneDesc scene_;
  std::size_t mesh_triangles_ = 0;
  // OBJ files already loaded, by (absolute resolved path, smooth): every `mesh { file }` naming
  // the same file shares one MeshId, so the file is read once and one BVH is built for it.
  // (file, shading): 0 flat, 1 smooth by area, 2 smooth by equal weights.
  std::map<std::pair<std::string, int>, MeshId> obj_meshes_;
  // Whether each mesh placed in CSG bounds a solid, computed once per mesh (a loop may place
  // one mesh in many blocks). Keyed by the data, which the scene keeps alive.
  std::unordered_map<const MeshData*, MeshClosure> mesh_closures_;
};

}  // namespace rts::render
