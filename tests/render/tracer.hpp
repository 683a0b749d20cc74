// Traces single rays through a SceneDesc without an image: everything the Integrator needs,
// built from the scene and kept alive together (tests that check one ray's radiance against
// a closed-form answer).
#pragma once

#include <memory>
#include <vector>

#include "render/accel/world.hpp"
#include "render/accel/flatten.hpp"
#include "render/shade/integrator.hpp"
#include "render/shade/lights.hpp"
#include "render/shade/texture.hpp"

namespace rts::render::test {

struct Tracer {
  SceneDesc scene;
  FlatScene flat;
  std::unique_ptr<World> world;
  std::vector<CompiledLight> lights;
  std::vector<CompiledTexture> textures;
  std::unique_ptr<Integrator> integrator;

  explicit Tracer(SceneDesc s, int max_depth = 5) : scene(std::move(s)) {
    flat = flatten_scene(scene);
    world = std::make_unique<World>(scene, flat);
    lights = compile_lights(flat.lights);
    textures = compile_textures(scene);
    integrator = std::make_unique<Integrator>(*world, lights, scene.materials, textures, scene.settings, max_depth);
  }
  Rgb trace(const Ray& r) const {
    Sampler sampler(0, 0, 0, 0);
    RayCounters counters;
    return integrator->trace(r, sampler, counters);
  }
};

}  // namespace rts::render::test
