// Real roots of a polynomial of degree <= 6 inside an interval, by isolation on the
// derivative's roots (the derivative's roots split the interval into pieces on which the
// polynomial is monotone; each piece whose ends differ in sign holds exactly one root, found
// by safeguarded Newton). Unlike the closed forms (Ferrari, Cardano), which lose every digit
// to cancellation for a thin torus or a grazing ray, this never misses a sign change it can
// evaluate and never returns a root outside its bracket. A double root (a tangent ray) has no
// sign change and is not reported: for a solid that is a graze, not a crossing.
#pragma once

#include <cmath>

namespace rts::render {

// The highest degree poly_roots takes: a lathe's cubic spline segment against a ray is a
// sextic (the torus and sor are quartics). Only the arrays' sizes depend on it, so results
// for lower degrees are the same as before it was raised.
inline constexpr int kPolyMaxDegree = 6;

// c[0] + c[1] s + ... + c[n] s^n.
inline double poly_eval(const double* c, int n, double s) {
  double v = c[n];
  for (int i = n - 1; i >= 0; --i) v = v * s + c[i];
  return v;
}

// The single root of the polynomial in [a, b], given that its values at a and b differ in
// sign (f(a) < 0 <=> a_negative) and that it is monotone there. kWide: the bracket may be
// enormous (a poly's Cauchy bound, render/geometry/shapes/poly.hpp), where Newton from far
// away creeps in by (n - 1) / n a step: every other step bisects, so the bracket at least
// halves every two steps whatever Newton does.
template <bool kWide = false>
inline double poly_bracketed_root(const double* c, int n, double a, double b, bool a_negative) {
  double d[kPolyMaxDegree];
  for (int i = 1; i <= n; ++i) d[i - 1] = i * c[i];
  double s = 0.5 * (a + b);
  // Bisection halves the bracket each step: 80 steps reach a double's last bit from any
  // bracket a torus can produce; Newton, when its step stays inside, gets there in a handful.
  // A wide bracket (up to 1e300 across) needs 2 x 2100 steps at most.
  constexpr int kSteps = kWide ? 4400 : 80;
  for (int iter = 0; iter < kSteps; ++iter) {
    double f = poly_eval(c, n, s);
    if (f == 0.0) return s;
    if ((f < 0.0) == a_negative) a = s; else b = s;
    double df = poly_eval(d, n - 1, s);
    double next = df != 0.0 ? s - f / df : 0.5 * (a + b);
    if (!(next > a && next < b) || (kWide && iter % 2 == 1)) next = 0.5 * (a + b);
    if (next == s || b - a <= 0.0) return next;
    s = next;
    if (!(a < s && s < b)) break;
  }
  return s;
}

// The roots in (lo, hi) where the polynomial changes sign, ascending; returns how many
// (at most n <= kPolyMaxDegree). The leading coefficient must not be zero. kWide: for an
// interval far wider than the roots' spread (see poly_bracketed_root).
template <bool kWide = false>
inline int poly_roots(const double* c, int n, double lo, double hi, double* out) {
  if (n < 1 || !(lo < hi)) return 0;
  if (n == 1) {
    double s = -c[0] / c[1];
    if (s > lo && s < hi) { out[0] = s; return 1; }
    return 0;
  }
  double d[kPolyMaxDegree];
  for (int i = 1; i <= n; ++i) d[i - 1] = i * c[i];
  double crit[kPolyMaxDegree];
  int nc = poly_roots<kWide>(d, n - 1, lo, hi, crit);
  double ends[kPolyMaxDegree + 2];
  int ne = 0;
  ends[ne++] = lo;
  for (int i = 0; i < nc; ++i) ends[ne++] = crit[i];
  ends[ne++] = hi;
  int count = 0;
  double f_prev = poly_eval(c, n, ends[0]);
  for (int i = 1; i < ne; ++i) {
    double f = poly_eval(c, n, ends[i]);
    bool neg_prev = f_prev < 0.0, neg = f < 0.0;  // zero counts as positive (outside)
    if (neg_prev != neg) out[count++] = poly_bracketed_root<kWide>(c, n, ends[i - 1], ends[i], neg_prev);
    f_prev = f;
  }
  return count;
}

}  // namespace rts::render
