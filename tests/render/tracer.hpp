// Traces single rays through a SceneDesc without an image: the scene prepared as render()
// prepares it (render/prepared_scene.hpp: flattening, world, lights, textures and the leave-out
// analysis that picks the integrator's specialisation), for tests that check one ray's
// radiance against a closed-form answer.
#pragma once

#include <memory>

#include "render/prepared_scene.hpp"
#include "render/shade/integrator.hpp"

namespace rts::render::test {

struct Tracer {
  SceneDesc scene;
  PreparedScene prepared;  // points into `scene`: a Tracer is neither copied nor moved
  const World* world;
  std::unique_ptr<Integrator> integrator;

  explicit Tracer(SceneDesc s, int max_depth = 5)
      : scene(std::move(s)), prepared(scene, /*specialize=*/true, /*max_memory=*/0), world(&prepared.world()) {
    const FeatureSet features = prepared.features(FeatureContext{scene.settings.samples, max_depth, false});
    integrator = std::make_unique<Integrator>(prepared.world(), prepared.lights(), scene.materials,
                                              prepared.textures(), scene.settings, max_depth,
                                              prepared.integrator_flags(features), &prepared.media());
  }
  Tracer(const Tracer&) = delete;
  Tracer& operator=(const Tracer&) = delete;

  Rgb trace(const Ray& r) const {
    Sampler sampler(0, 0, 0, 0);
    RayCounters counters;
    return integrator->trace(r, sampler, counters);
  }
};

}  // namespace rts::render::test
