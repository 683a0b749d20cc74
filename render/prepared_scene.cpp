#include "render/prepared_scene.hpp"

#include <algorithm>
#include <array>
#include <utility>
#include <variant>

#include "render/accel/memory.hpp"

namespace rts::render {

namespace {
// By shape kind: whether the kind has something to say after the render (after_render_warning).
template <class T>
constexpr bool kWatched = requires(const T& g) { after_render_warning(g); };
template <std::size_t... I>
constexpr std::array<bool, sizeof...(I)> watched_kinds(std::index_sequence<I...>) {
  return {kWatched<std::variant_alternative_t<I, ShapeGeometry>>...};
}
constexpr auto kWatchedKinds = watched_kinds(std::make_index_sequence<std::variant_size_v<ShapeGeometry>>{});
static_assert(kWatchedKinds[kPrimKind<Isosurface>], "an isosurface warns after the render");

// Frees a container's blocks (a vector's clear() keeps its block).
template <class Container>
void release(Container& c) {
  Container().swap(c);
}
}  // namespace

PreparedScene::PreparedScene(const SceneDesc& scene, bool specialize, std::size_t max_memory)
    : scene_(&scene), specialize_(specialize), max_memory_(max_memory) {
  build(nullptr);
}

PreparedScene::PreparedScene(SceneDesc&& scene, bool specialize, std::size_t max_memory)
    : owned_(std::make_unique<SceneDesc>(std::move(scene))), scene_(owned_.get()), specialize_(specialize),
      max_memory_(max_memory) {
  build(owned_.get());
}

// Only what is placed is built: textures no placed material uses are never loaded. Everything
// that reads the shapes or the graph (the textures used, the shapes' features, the shapes
// with something to say after the render, the world's instances) runs before the top-level
// BVH. With `release_graph` (the scene taken), the description goes as soon as nothing reads
// it: the roots once flattened, the shapes while the world's instances are made from them
// (World, shape_release.hpp), the rest before the BVH build. Profile finding (RSS trace, 4M
// spheres): the peak was the world's instances made beside the whole description.
void PreparedScene::build(SceneDesc* release_graph) {
  const SceneDesc& scene = *scene_;
  flat_ = flatten_scene(scene);
  if (release_graph) {
    // What follows makes large arrays, which cannot reuse the roots' chunks: their pages go back
    // once there were many placements, of shapes or of groups (1M placements of a group: their
    // 152-byte matrix blocks, 150 MB, stayed resident through the BVH build when only placed
    // shapes were counted; RSS trace of bench/instancing/copies.rts -D m=8 -D c=1000).
    const std::size_t placements = release_graph->roots.size();
    release(release_graph->roots);
    release_free_memory(std::max(placements, flat_.shapes.size()));
  }
  lights_ = compile_lights(flat_.lights);
  std::vector<bool> used = used_textures(scene, flat_);
  textures_ = compile_textures(scene, &used, max_memory_);
  media_ = compile_media(scene, textures_);
  shape_features_ = shape_features(scene, flat_);
  instancing_ = !flat_.groups.empty();
  for (const ShapeDesc& sd : scene.shapes)
    if (kWatchedKinds[sd.geometry.index()]) watched_.push_back(sd);
  world_ = std::make_unique<World>(scene, flat_, specialize_, WorldBuild::BvhLater, release_graph);
  // Freed, not trimmed: the builder's references and nodes reuse those blocks (a trim here
  // measured the same peak and a slower build: fresh pages faulted in again).
  if (release_graph) {
    release(release_graph->shapes);
    release(release_graph->nodes);
    release(release_graph->groups);
    release(release_graph->csgs);
    flat_.keep_lights_only();
  }
  world_->build_bvh();
}

FeatureSet PreparedScene::features(const FeatureContext& context) const {
  FeatureSet f = analyze_features(*scene_, shape_features_[context.max_depth > 0 ? 1 : 0], flat_.lights, context);
  if (world_->uses_bvh()) f.add(Feature::Bvh);
  if (instancing_) f.add(Feature::Instancing);
  return f;
}

unsigned PreparedScene::integrator_flags(const FeatureSet& features) const {
  return specialize_ ? trace_flags::for_features(features) : trace_flags::kGeneric | trace_flags::kAll;
}

}  // namespace rts::render
