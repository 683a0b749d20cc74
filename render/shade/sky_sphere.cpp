// POV-Ray 3.7's sky_sphere (its Trace::ComputeSky), as the environment texture kind SkySphere:
//  - the ray's unit direction goes through the inverse of the sky's own transform as a
//    direction (a translate does nothing; a scale stretches the pattern, not renormalised),
//    and each layer is evaluated at that point, after its own transform;
//  - layers composite from the last (on top) down to the first: a layer adds its color times
//    (1 - transmit) times what the layers above let through, and the settings' background
//    shows through what every layer transmits. POV-Ray's `filter` (light tinted by the layer)
//    is not modelled: a layer is see-through only by `transmit`.
#include <algorithm>
#include <cmath>

#include "render/shade/pattern/patterns.hpp"
#include "render/shade/texture.hpp"

namespace rts::render {

glm::dvec4 CompiledTexture::eval_layer(const Vec3& p) const {
  if (desc_.kind == TextureKind::Pattern) {
    const Vec3 q = Vec3(inverse_ * glm::dvec4(p, 1.0));
    glm::dvec4 c = map_entries_.empty() ? pattern::pattern_color_transmit(desc_.pattern, q) : eval_map_entries(q);
    c.w = std::isfinite(c.w) ? std::clamp(c.w, 0.0, 1.0) : 0.0;
    return c;
  }
  TexturePoint tp;
  tp.object_point = p;
  const Color c = eval(tp);
  return {c.r, c.g, c.b, 0.0};
}

Color CompiledTexture::eval_sky(const Vec3& direction) const {
  const double length = glm::length(direction);
  if (!(length > 0.0) || !std::isfinite(length)) return sky_background_;   // no direction: nothing to see
  const Vec3 p = Vec3(inverse_ * glm::dvec4(direction / length, 0.0));
  glm::dvec3 sum(0.0);
  double through = 1.0;   // what the layers above let through
  for (auto layer = sky_layers_.rbegin(); layer != sky_layers_.rend() && through > 0.0; ++layer) {
    const glm::dvec4 c = layer->eval_layer(p);
    sum += glm::dvec3(c) * ((1.0 - c.w) * through);
    through *= c.w;
  }
  return {sum.x + sky_background_.r * through, sum.y + sky_background_.g * through,
          sum.z + sky_background_.b * through};
}

}  // namespace rts::render
