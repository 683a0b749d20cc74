// Casting rays at one object of a scene while it is being built: the language's
// trace(object, origin, direction), which places things on surfaces. Part of the scene
// interface the runtime uses; implemented over the traceable World (render/accel/probe.cpp),
// whose headers stay out of this one.
#pragma once

#include <memory>

#include "render/scene/scene.hpp"

namespace rts::render {

struct ProbeHit {
  Vec3 point{0.0};
  Vec3 normal{0.0};  // unit, the surface's outward (geometric) normal, in world space
};

class ObjectProbe {
 public:
  // The instance `object` (a node of `scene`, with its transform) alone, ready to be traced.
  // Throws RenderError as flattening does (a singular transform). `scene` is only read here.
  ObjectProbe(const SceneDesc& scene, const Child& object);
  ~ObjectProbe();
  ObjectProbe(const ObjectProbe&) = delete;
  ObjectProbe& operator=(const ObjectProbe&) = delete;

  // The first surface along origin + t * direction, t > 0; false when the ray misses.
  bool trace(const Vec3& origin, const Vec3& direction, ProbeHit& hit) const;
  // Shape instances it holds (what building it cost, for evaluation budgets).
  std::size_t instances() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rts::render
