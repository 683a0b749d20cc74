// Inverting an instance's transform at any scale. glm::inverse divides cofactors (products of
// three entries) by the determinant (also of three): a `scale 1e150` overflows both and a
// `scale 1e-110` underflows them, so the object vanished or a "singular" error named a scale
// that is not 0. Here the linear part is first multiplied by a power of two near 1 / its
// largest entry (exact), inverted, and multiplied back; transforms whose largest entry lies
// inside tol::kUnscaledLength* take glm::inverse itself, keeping their bits.
#pragma once

#include <cmath>

#include "render/geometry/tolerances.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// The power of two that brings the 3x3 part's largest entry near 1 (1 when it is 0 or not finite).
inline double linear_scale(const Mat4& m) {
  double big = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) big = std::max(big, std::abs(m[c][r]));
  return big > 0.0 && std::isfinite(big) ? std::ldexp(1.0, -std::ilogb(big)) : 1.0;
}

// Whether m can be inverted: its 3x3 part's determinant, taken on the scaled entries, is
// above tol::kSingularDeterminant (a scale of 0, or axes so flattened that no inverse exists
// in doubles). Non-finite determinants count as singular; the caller checks finiteness first.
inline bool invertible_transform(const Mat4& m) {
  const double det = glm::determinant(glm::dmat3(m) * linear_scale(m));
  return std::isfinite(det) && std::abs(det) > tol::kSingularDeterminant;
}

inline Mat4 inverse_transform(const Mat4& m) {
  const double s = linear_scale(m);
  if (s > tol::kUnscaledLengthMin && s < tol::kUnscaledLengthMax) return glm::inverse(m);  // 1/entry, same range
  // m = [A t] and [sA, s t]^-1 = [(sA)^-1, -(sA)^-1 s t] = [A^-1 / s, -A^-1 t].
  Mat4 scaled = m * s;
  scaled[3] = glm::dvec4(glm::dvec3(m[3]) * s, 1.0);
  Mat4 inv = glm::inverse(scaled);
  for (int c = 0; c < 3; ++c) inv[c] = glm::dvec4(glm::dvec3(inv[c]) * s, 0.0);
  return inv;
}

}  // namespace rts::render
