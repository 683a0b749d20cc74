// A scene made ready to trace: flattened, its world (instances and BVHs) built, its lights and
// the textures its placed materials use compiled. Building it is most of a small render's set-up,
// so what renders one scene many times (`rts converge`, tests that trace single rays) builds it
// once; render() builds one itself when given a SceneDesc.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "render/accel/flatten.hpp"
#include "render/accel/world.hpp"
#include "render/shade/features.hpp"
#include "render/shade/medium.hpp"
#include "render/shade/integrator.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/texture.hpp"

namespace rts::render {

struct RenderOptions;

class PreparedScene {
 public:
  // Builds in the calling thread's TBB arena (render() runs it in its own of --threads).
  // `specialize` false: the generic world (--no-specialize); `max_memory` bounds the textures'
  // decoded images (--max-memory; 0: no limit). `scene` must outlive this.
  PreparedScene(const SceneDesc& scene, bool specialize, std::size_t max_memory);
  // The same for a scene it takes: once the world holds its instances, the description's graph
  // (shapes, nodes, groups, CSG blocks, roots) and the flattened placements are released before
  // the top-level BVH is built, so the build's peak does not hold them (issue 24: the
  // description was the largest part of the peak of a large scene). scene() keeps everything
  // else (settings, camera, materials, textures, media, meshes, lights).
  PreparedScene(SceneDesc&& scene, bool specialize, std::size_t max_memory);

  const SceneDesc& scene() const { return *scene_; }
  // The flattened scene; of a taken scene, only the lights are left.
  const FlatScene& flat() const { return flat_; }
  // The shapes that have something to say after the render (an isosurface whose gradient went
  // above max_gradient), copies of the description's.
  const std::vector<ShapeDesc>& watched_shapes() const { return watched_; }
  const World& world() const { return *world_; }
  const std::vector<CompiledLight>& lights() const { return lights_; }
  const std::vector<CompiledTexture>& textures() const { return textures_; }
  const std::vector<CompiledMedium>& media() const { return media_; }
  bool specialized() const { return specialize_; }
  std::size_t max_memory() const { return max_memory_; }

  // What a render with these settings uses and leaves out (--stats, the integrator's flags).
  FeatureSet features(const FeatureContext& context) const;
  // The integrator's specialisation for `features` (the generic one unless specialized()).
  unsigned integrator_flags(const FeatureSet& features) const;

 private:
  void build(SceneDesc* release_graph);

  std::unique_ptr<SceneDesc> owned_;  // a taken scene
  const SceneDesc* scene_;
  bool specialize_;
  std::size_t max_memory_;
  FlatScene flat_;
  // What the placed shapes use, for max_depth 0 and above (features()); instancing placed.
  std::array<FeatureSet, 2> shape_features_;
  bool instancing_ = false;
  std::vector<ShapeDesc> watched_;
  std::unique_ptr<World> world_;
  std::vector<CompiledLight> lights_;
  std::vector<CompiledTexture> textures_;
  std::vector<CompiledMedium> media_;
};

// Builds the scene as render() would for `options` (its --threads, --no-specialize and
// --max-memory), in an arena of options.threads workers.
PreparedScene prepare_scene(const SceneDesc& scene, const RenderOptions& options);

}  // namespace rts::render
