// trace(object, origin, direction): the first point where a ray meets an object, and the
// surface normal there, for placing things on surfaces (POV-Ray's trace). The object is traced
// alone, with its transform, through the renderer's World (render/accel/probe.hpp); the last
// object's World is kept, so a loop tracing one object many times builds it once.
#include <fmt/format.h>

#include "render/accel/probe.hpp"
#include "runtime/interpreter.hpp"

namespace rts::runtime {

Value Interpreter::trace_object(const Value& object, const glm::dvec3& origin, const glm::dvec3& direction,
                                SourceLoc loc) {
  if (!(glm::length(direction) > 0.0)) fail(loc, "trace: the direction must not be the zero vector");
  render::Child key{realize_object(object), object_transform(object), ref(loc)};
  if (!probe_ || probe_key_.node != key.node || probe_key_.transform.matrix() != key.transform.matrix() ||
      probe_shapes_ != builder_.object_count()) {
    probe_.reset();
    try {
      probe_ = std::make_unique<render::ObjectProbe>(builder_.scene(), key);
    } catch (const render::RenderError& e) {
      fail(loc, fmt::format("trace: {}", e.what()));
    }
    // Building it walks every instance of the object: a loop tracing huge objects by turns
    // meets --max-steps.
    spend(probe_->instances(), loc, "object instances traced");
    probe_key_ = key;
    probe_shapes_ = builder_.object_count();
  }
  render::ProbeHit hit;
  if (!probe_->trace(origin, direction, hit)) return Value::none();
  return Value::list({Value::vector(hit.point), Value::vector(hit.normal)});
}

}  // namespace rts::runtime
