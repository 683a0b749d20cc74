// POV-Ray 3.7's splines through 2-D points, shared by the lathe (r, h) and the prism (x, z):
// which points make each segment and the cubic polynomials in t in [0, 1] it follows, so a
// scene translated from POV-Ray gets the same curve.
//   linear:    N >= 2 points, N - 1 segments, P[i] to P[i+1].
//   quadratic: N >= 3, N - 2 segments; segment i runs from P[i+1] to P[i+2], its tangent at the
//              start (P[i+2] - P[i]) / 2: the first point is only a control point.
//   cubic:     N >= 4, N - 3 segments; segment i runs from P[i+1] to P[i+2] (Catmull-Rom: the
//              tangents are (P[i+2] - P[i]) / 2 and (P[i+3] - P[i+1]) / 2): the first and last
//              points are only control points.
//   bezier:    N a multiple of 4, N / 4 segments; segment k is the cubic Bezier curve of
//              P[4k] .. P[4k+3] (through the first and last, pulled toward the middle two).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/geometry/tolerances.hpp"
#include "render/scene/scene.hpp"

namespace rts::render {

// "linear", "quadratic", "cubic", "bezier" (the rts property's values); false if none.
inline bool spline_kind_from_name(const std::string& name, SplineKind& out) {
  if (name == "linear") out = SplineKind::Linear;
  else if (name == "quadratic") out = SplineKind::Quadratic;
  else if (name == "cubic") out = SplineKind::Cubic;
  else if (name == "bezier") out = SplineKind::Bezier;
  else return false;
  return true;
}

inline const char* spline_kind_name(SplineKind k) {
  switch (k) {
    case SplineKind::Linear: return "linear";
    case SplineKind::Quadratic: return "quadratic";
    case SplineKind::Cubic: return "cubic";
    case SplineKind::Bezier: return "bezier";
  }
  return "linear";
}

// The point count a spline needs, as a phrase for errors ("at least 4 points"), or "" when n
// points make a valid spline of this kind (min_linear: a linear spline's minimum, which the
// lathe and prism set differently).
inline std::string spline_count_problem(SplineKind k, int n, int min_linear) {
  switch (k) {
    case SplineKind::Linear:
      return n >= min_linear ? "" : "at least " + std::to_string(min_linear) + " points";
    case SplineKind::Quadratic:
      return n >= 3 ? "" : "at least 3 points (the first is a control point)";
    case SplineKind::Cubic:
      return n >= 4 ? "" : "at least 4 points (the first and last are control points)";
    case SplineKind::Bezier:
      return n >= 4 && n % 4 == 0 ? "" : "a multiple of 4 points (4 per segment: end, control, control, end)";
  }
  return "";
}

inline double spline_eval(const double* c, double t) { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }
inline double spline_slope(const double* c, double t) { return (3.0 * c[3] * t + 2.0 * c[2]) * t + c[1]; }

namespace detail {

// The range of the cubic c over t in [0, 1]: its ends and its turning points inside.
inline void spline_range(const double* c, double& lo, double& hi) {
  lo = std::min(c[0], spline_eval(c, 1.0));
  hi = std::max(c[0], spline_eval(c, 1.0));
  auto take = [&](double t) {
    if (t > 0.0 && t < 1.0) {
      double v = spline_eval(c, t);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  };
  // c'(t) = 3 c3 t^2 + 2 c2 t + c1.
  double A = 3.0 * c[3], B = 2.0 * c[2], C = c[1];
  if (A == 0.0) {
    if (B != 0.0) take(-C / B);
  } else {
    double disc = B * B - 4.0 * A * C;
    if (disc >= 0.0) {
      double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
      take(q / A);
      if (q != 0.0) take(C / q);
    }
  }
  // The turning points are rounded: pad by the curve's own size.
  double pad = tol::kSplineBoundPad * (std::abs(c[0]) + std::abs(c[1]) + std::abs(c[2]) + std::abs(c[3]));
  lo -= pad;
  hi += pad;
}

}  // namespace detail

// The segments of the spline through p (x, y of each point), POV-Ray's polynomials.
inline std::vector<SplineSegment> spline_segments(SplineKind k, const std::vector<Vec3>& p) {
  std::vector<SplineSegment> out;
  const int n = static_cast<int>(p.size());
  auto push = [&](const double (&w)[4][4], int i0) {
    // Coefficient j of x (and y): sum over the four points of w[j][m] * P[i0 + m].
    SplineSegment s{};
    for (int j = 0; j < 4; ++j) {
      s.x[j] = s.y[j] = 0.0;
      for (int m = 0; m < 4; ++m) {
        if (w[j][m] == 0.0) continue;
        s.x[j] += w[j][m] * p[i0 + m].x;
        s.y[j] += w[j][m] * p[i0 + m].y;
      }
    }
    detail::spline_range(s.x, s.x_lo, s.x_hi);
    detail::spline_range(s.y, s.y_lo, s.y_hi);
    out.push_back(s);
  };
  switch (k) {
    case SplineKind::Linear: {
      static constexpr double w[4][4] = {{1, 0, 0, 0}, {-1, 1, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
      for (int i = 0; i + 1 < n; ++i) push(w, i);
      break;
    }
    case SplineKind::Quadratic: {
      static constexpr double w[4][4] = {{0, 1, 0, 0}, {-0.5, 0, 0.5, 0}, {0.5, -1, 0.5, 0}, {0, 0, 0, 0}};
      for (int i = 0; i + 2 < n; ++i) push(w, i);
      break;
    }
    case SplineKind::Cubic: {
      static constexpr double w[4][4] = {
          {0, 1, 0, 0}, {-0.5, 0, 0.5, 0}, {1, -2.5, 2, -0.5}, {-0.5, 1.5, -1.5, 0.5}};
      for (int i = 0; i + 3 < n; ++i) push(w, i);
      break;
    }
    case SplineKind::Bezier: {
      static constexpr double w[4][4] = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
      for (int i = 0; i + 3 < n; i += 4) push(w, i);
      break;
    }
  }
  return out;
}

// Where the curve starts and ends (points the spline passes through, exactly as given).
inline Vec3 spline_start(SplineKind k, const std::vector<Vec3>& p) {
  return (k == SplineKind::Quadratic || k == SplineKind::Cubic) ? p[1] : p.front();
}
inline Vec3 spline_end(SplineKind k, const std::vector<Vec3>& p) {
  return k == SplineKind::Cubic ? p[p.size() - 2] : p.back();
}

}  // namespace rts::render
