// The vector and interpolation builtins POV-Ray users reach for: vrotate, vaxis_rotate, the
// v-prefixed aliases (vlength, vnormalize, vdot, vcross), lerp, smoothstep, distance, and
// spline (linear, cubic, natural) for paths and animation. Angles are in degrees where
// POV-Ray takes degrees (vrotate, vaxis_rotate), as rts's `rotate` does.
#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "runtime/interpreter.hpp"
#include "runtime/builtin_args.hpp"
#include "runtime/ops.hpp"

namespace rts::runtime {

namespace {

using namespace builtin_args;

Value finite_vector(const BuiltinCall& c, glm::dvec3 v) {
  for (int k = 0; k < 3; ++k) check_finite(v[k], c.call.loc, c.def.name);
  return Value::vector(v);
}

// The rotation `rotate <ax, ay, az>` applies (about x, then y, then z; degrees).
glm::dmat3 euler_rotation(glm::dvec3 deg) {
  const glm::dmat4 one(1.0);
  glm::dmat4 m = glm::rotate(one, glm::radians(deg.z), glm::dvec3(0, 0, 1)) *
                 glm::rotate(one, glm::radians(deg.y), glm::dvec3(0, 1, 0)) *
                 glm::rotate(one, glm::radians(deg.x), glm::dvec3(1, 0, 0));
  return glm::dmat3(m);
}

// vrotate(v, <ax, ay, az>): v turned as `rotate <ax, ay, az>` turns an object.
Value vrotate(BuiltinCall& c) { return finite_vector(c, euler_rotation(vec(c, 1)) * vec(c, 0)); }

// vaxis_rotate(v, axis, degrees): v turned about `axis` (through the origin), in the sense
// `rotate` uses for the coordinate axes: vaxis_rotate(v, <0, 1, 0>, a) == vrotate(v, <0, a, 0>).
Value vaxis_rotate(BuiltinCall& c) {
  glm::dvec3 axis = vec(c, 1);
  double len = glm::length(axis);
  if (!(len > 0.0)) c.in.fail(arg_loc(c, 1), "vaxis_rotate: the axis must not be the zero vector");
  glm::dmat3 r(glm::rotate(glm::dmat4(1.0), glm::radians(num(c, 2)), axis / len));
  return finite_vector(c, r * vec(c, 0));
}

Value distance(BuiltinCall& c) { return Value::number(glm::length(vec(c, 0) - vec(c, 1))); }

// smoothstep(e0, e1, x): 0 below e0, 1 above e1, 3t² − 2t³ between (t = (x − e0) / (e1 − e0)).
Value smoothstep(BuiltinCall& c) {
  double e0 = num(c, 0), e1 = num(c, 1), x = num(c, 2);
  if (!(e0 < e1)) c.in.fail(c.call.loc, fmt::format("smoothstep: edge {} must be below edge {}", e0, e1));
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return Value::number(t * t * (3.0 - 2.0 * t));
}

// ---- spline(kind, keys, t) -----------------------------------------------------------------
// keys: a list of [t, value] pairs with increasing t; values all numbers, all vectors or all
// colors. Outside the keys' range, t is clamped (the curve stops at its ends).
struct Key {
  double t;
  glm::dvec3 v;
};

std::vector<Key> spline_keys(const BuiltinCall& c, Type& type) {
  if (c.args[1].type != Type::List) bad_arg(c, 1, "a list of [t, value] pairs");
  const auto& items = as_list(c.args[1]);
  // Each call walks every key: count them, so a loop over a huge key list meets --max-steps.
  c.in.spend(items.size(), c.call.loc, "spline keys read");
  std::vector<Key> keys;
  keys.reserve(items.size());
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Value& it = items[i];
    if (it.type != Type::List || as_list(it).size() != 2 || as_list(it)[0].type != Type::Number)
      c.in.fail(arg_loc(c, 1), fmt::format("spline: key {} must be a pair [t, value], got {}", i, with_article(it.type)));
    const Value& t = as_list(it)[0];
    const Value& v = as_list(it)[1];
    if (i == 0) type = v.type;
    if (v.type != type || (type != Type::Number && type != Type::Vector && type != Type::Color))
      c.in.fail(arg_loc(c, 1), fmt::format("spline: key {} has {}; the values must be all numbers, all vectors or "
                                           "all colors",
                                           i, with_article(v.type)));
    if (i > 0 && !(t.v.x > keys.back().t))
      c.in.fail(arg_loc(c, 1), fmt::format("spline: the keys' t must increase, but key {} has t = {} after {}", i,
                                           t.v.x, keys.back().t));
    keys.push_back(Key{t.v.x, v.v});
  }
  return keys;
}

// The segment [keys[i], keys[i+1]] that holds t (t already clamped to the range).
std::size_t segment(const std::vector<Key>& k, std::size_t first, std::size_t last, double t) {
  std::size_t i = first;
  while (i + 1 < last && t > k[i + 1].t) ++i;
  return i;
}

glm::dvec3 hermite(const Key& a, const Key& b, glm::dvec3 ma, glm::dvec3 mb, double t) {
  double h = b.t - a.t, s = (t - a.t) / h;
  double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * a.v + (s3 - 2 * s2 + s) * h * ma + (-2 * s3 + 3 * s2) * b.v + (s3 - s2) * h * mb;
}

// Catmull-Rom through keys 1 .. n-2, the end keys setting the end tangents (POV-Ray's
// cubic_spline: the first and last points are control points only).
glm::dvec3 cubic(const std::vector<Key>& k, double t) {
  std::size_t n = k.size();
  t = std::clamp(t, k[1].t, k[n - 2].t);
  std::size_t i = segment(k, 1, n - 2, t);
  auto tangent = [&](std::size_t j) { return (k[j + 1].v - k[j - 1].v) / (k[j + 1].t - k[j - 1].t); };
  return hermite(k[i], k[i + 1], tangent(i), tangent(i + 1), t);
}

// The natural cubic spline through every key (second derivative zero at both ends): the
// tridiagonal system for the second derivatives M, solved by the Thomas algorithm.
glm::dvec3 natural(const std::vector<Key>& k, double t) {
  std::size_t n = k.size();
  t = std::clamp(t, k.front().t, k.back().t);
  std::vector<glm::dvec3> m(n, glm::dvec3(0.0)), d(n, glm::dvec3(0.0));
  std::vector<double> diag(n, 1.0), upper(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    double h0 = k[i].t - k[i - 1].t, h1 = k[i + 1].t - k[i].t;
    double lower = h0;
    diag[i] = 2 * (h0 + h1);
    upper[i] = h1;
    d[i] = 6.0 * ((k[i + 1].v - k[i].v) / h1 - (k[i].v - k[i - 1].v) / h0);
    // Eliminate the lower diagonal (row i-1 is already reduced; row 0 is M0 = 0).
    double w = lower / diag[i - 1];
    diag[i] -= w * upper[i - 1];
    d[i] -= w * d[i - 1];
  }
  for (std::size_t i = n - 1; i-- > 1;) m[i] = (d[i] - upper[i] * m[i + 1]) / diag[i];
  std::size_t i = segment(k, 0, n - 1, t);
  double h = k[i + 1].t - k[i].t;
  double a = k[i + 1].t - t, b = t - k[i].t;
  return m[i] * (a * a * a) / (6 * h) + m[i + 1] * (b * b * b) / (6 * h) + (k[i].v / h - m[i] * h / 6.0) * a +
         (k[i + 1].v / h - m[i + 1] * h / 6.0) * b;
}

Value spline(BuiltinCall& c) {
  if (c.args[0].type != Type::String) bad_arg(c, 0, "a string: \"linear\", \"cubic\" or \"natural\"");
  const std::string& kind = as_string(c.args[0]);
  Type type = Type::Number;
  std::vector<Key> keys = spline_keys(c, type);
  double t = num(c, 2);
  std::size_t need = kind == "linear" ? 2 : kind == "cubic" ? 4 : kind == "natural" ? 3 : 0;
  if (need == 0)
    c.in.fail(arg_loc(c, 0), fmt::format("spline: unknown kind '{}' (\"linear\", \"cubic\" or \"natural\")", kind));
  if (keys.size() < need)
    c.in.fail(arg_loc(c, 1), fmt::format("spline: a {} spline needs at least {} keys, got {}", kind, need, keys.size()));
  glm::dvec3 r;
  if (kind == "linear") {
    t = std::clamp(t, keys.front().t, keys.back().t);
    std::size_t i = segment(keys, 0, keys.size() - 1, t);
    double s = (t - keys[i].t) / (keys[i + 1].t - keys[i].t);
    r = keys[i].v + (keys[i + 1].v - keys[i].v) * s;
  } else if (kind == "cubic") {
    r = cubic(keys, t);
  } else {
    r = natural(keys, t);
  }
  for (int k = 0; k < 3; ++k) check_finite(r[k], c.call.loc, "spline");
  Value out;
  out.type = type;
  out.v = type == Type::Number ? glm::dvec3(r.x, 0, 0) : r;
  return out;
}

// trace(object, origin, direction): [point, normal] where the ray first meets the object, or
// none when it misses.
Value trace(BuiltinCall& c) {
  if (c.args[0].type != Type::Object) bad_arg(c, 0, "an object (a shape or a group)");
  return c.in.trace_object(c.args[0], vec(c, 1), vec(c, 2), c.call.loc);
}

}  // namespace

std::vector<Builtin> with_math_builtins(std::vector<Builtin> table) {
  auto alias = [&](const char* name, const char* of) {
    for (const Builtin& b : table)
      if (std::string_view(b.name) == of) return Builtin{name, b.min_args, b.max_args, b.fn};
    return Builtin{name, 0, 0, nullptr};  // unreachable: every alias names a builtin above
  };
  std::vector<Builtin> more = {
      {"vrotate", 2, 2, vrotate},
      {"vaxis_rotate", 3, 3, vaxis_rotate},
      {"distance", 2, 2, distance},
      {"smoothstep", 3, 3, smoothstep},
      {"spline", 3, 3, spline},
      {"trace", 3, 3, trace},
      // POV-Ray's names for builtins rts already has.
      alias("vlength", "length"),
      alias("vnormalize", "normalize"),
      alias("vdot", "dot"),
      alias("vcross", "cross"),
      alias("lerp", "mix"),
  };
  table.insert(table.end(), more.begin(), more.end());
  return table;
}

}  // namespace rts::runtime
