#include "render/prepared_scene.hpp"

namespace rts::render {

// Only what is placed is built: textures no placed material uses are never loaded.
PreparedScene::PreparedScene(const SceneDesc& scene, bool specialize, std::size_t max_memory)
    : scene_(&scene), specialize_(specialize), max_memory_(max_memory) {
  flat_ = flatten_scene(scene);
  world_ = std::make_unique<World>(scene, flat_, specialize);
  lights_ = compile_lights(flat_.lights);
  std::vector<bool> used = used_textures(scene, flat_);
  textures_ = compile_textures(scene, &used, max_memory);
  media_ = compile_media(scene, textures_);
}

FeatureSet PreparedScene::features(const FeatureContext& context) const {
  FeatureSet f = analyze_features(*scene_, flat_, context);
  if (world_->uses_bvh()) f.add(Feature::Bvh);
  if (!flat_.groups.empty()) f.add(Feature::Instancing);
  return f;
}

unsigned PreparedScene::integrator_flags(const FeatureSet& features) const {
  return specialize_ ? trace_flags::for_features(features) : trace_flags::kGeneric | trace_flags::kAll;
}

}  // namespace rts::render
