#include "render/accel/probe.hpp"

#include "render/accel/world.hpp"
#include "render/accel/flatten.hpp"

namespace rts::render {

struct ObjectProbe::Impl {
  World world;
  Impl(const SceneDesc& scene, const FlatScene& flat) : world(scene, flat) {}
};

ObjectProbe::ObjectProbe(const SceneDesc& scene, const Child& object)
    : impl_(std::make_unique<Impl>(scene, flatten_instance(scene, object))) {}

ObjectProbe::~ObjectProbe() = default;

std::size_t ObjectProbe::instances() const { return impl_->world.instance_count(); }

bool ObjectProbe::trace(const Vec3& origin, const Vec3& direction, ProbeHit& hit) const {
  WorldHit h;
  if (!impl_->world.intersect(Ray{origin, direction}, Interval::positive(), h)) return false;
  hit.point = h.point;
  hit.normal = h.normal;
  return true;
}

}  // namespace rts::render
