// Carrying a SurfaceHit from a child's space into its parent's: the step an instanced group
// adds between a shape's object space and the world (World::intersect does the last step
// itself, with the normalisation and the world's hit record).
#pragma once

#include <algorithm>
#include <cmath>

#include "render/accel/world.hpp"
#include "render/geometry/ray.hpp"

namespace rts::render {

// The infinity norm of the 3x3 linear part (largest row sum of absolute values): how much it
// can stretch a per-component error bound.
template <class M>
double linear_norm(const M& m) {
  double best = 0.0;
  for (int row = 0; row < 3; ++row)
    best = std::max(best, std::abs(m[0][row]) + std::abs(m[1][row]) + std::abs(m[2][row]));
  return best;
}

// Point, error bound, normals and tangents of `h` moved by the affine map `to_parent` (its
// linear part `vec` for tangents, `nrm` (inverse transpose) for normals); the normals are
// left unnormalised, as shapes report them. The error bound grows as pbrt-v4's transformed
// point's: the linear part scales it, the product and the translation add rounding.
inline void hit_to_parent(const Vec3& point, const glm::dmat3& vec, const Vec3& translation, const glm::dmat3& nrm,
                          SurfaceHit& h) {
  const double linear = linear_norm(vec);
  h.error = linear * h.error * (1.0 + error_gamma(3)) +
            error_gamma(3) * (linear * max_abs_component(h.point) + max_abs_component(translation));
  h.point = point;
  h.normal = nrm * h.normal;
  h.shading_normal = nrm * h.shading_normal;
  h.dpdu = vec * h.dpdu;
  h.dpdv = vec * h.dpdv;
}

// A placement's map to its parent (World::group_to_world), and its inverse's linear part (normals).
inline void group_to_parent(const glm::dmat4x3& to_world, const glm::dmat3& object_linear, SurfaceHit& h) {
  const glm::dmat3 vec(to_world);
  hit_to_parent(to_world * glm::dvec4(h.point, 1.0), vec, to_world[3], glm::transpose(object_linear), h);
}

// A shape instance's map: its shared linear parts and its own translation.
inline void shape_to_parent(const InstanceLinear& lin, const Vec3& to_world_t, SurfaceHit& h) {
  hit_to_parent(apply_affine(lin.to_world, to_world_t, h.point, 1.0), lin.to_world, to_world_t, lin.normal_to_world, h);
}

}  // namespace rts::render
