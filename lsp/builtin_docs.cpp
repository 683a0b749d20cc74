#include "lsp/builtin_docs.hpp"

namespace rts::lsp {

namespace {

// As docs/runtime.md#builtins describes them. Trigonometry is in radians.
constexpr BuiltinDoc kBuiltins[] = {
    {"sin", "sin(x)", "Sine of x (radians)."},
    {"cos", "cos(x)", "Cosine of x (radians)."},
    {"tan", "tan(x)", "Tangent of x (radians)."},
    {"asin", "asin(x)", "Arc sine, in radians."},
    {"acos", "acos(x)", "Arc cosine, in radians."},
    {"atan", "atan(x)", "Arc tangent, in radians."},
    {"atan2", "atan2(y, x)", "The angle of the point (x, y), in radians."},
    {"sqrt", "sqrt(x)", "Square root."},
    {"pow", "pow(a, b)", "a to the power b."},
    {"exp", "exp(x)", "e to the power x."},
    {"log", "log(x)", "Natural logarithm."},
    {"abs", "abs(x)", "Absolute value."},
    {"floor", "floor(x)", "The largest whole number not above x."},
    {"ceil", "ceil(x)", "The smallest whole number not below x."},
    {"round", "round(x)", "The nearest whole number (halves away from zero)."},
    {"radians", "radians(degrees)", "Degrees to radians."},
    {"degrees", "degrees(radians)", "Radians to degrees."},
    {"min", "min(a, [b, ...])", "The smallest of numbers given as arguments, or of one list of numbers."},
    {"max", "max(a, [b, ...])", "The largest of numbers given as arguments, or of one list of numbers."},
    {"clamp", "clamp(x, lo, hi)", "x held between lo and hi."},
    {"mix", "mix(a, b, t)", "a + (b - a) * t, on numbers, vectors or colors."},
    {"dot", "dot(a, b)", "Dot product of two vectors."},
    {"cross", "cross(a, b)", "Cross product of two vectors."},
    {"length", "length(v)", "The length of a vector."},
    {"normalize", "normalize(v)", "The vector scaled to length 1."},
    {"rgb", "rgb(r, [g, b])", "A color: rgb(r, g, b), rgb(gray) or rgb(vector)."},
    {"vec", "vec(x, y, z)", "A vector."},
    {"len", "len(x)", "The length of a list, string (bytes) or range."},
    {"select", "select(c, a, b)", "a when the bool c is true, else b (only the chosen one is evaluated)."},
    {"append", "append(xs, v, [more, ...])", "A new list: xs followed by the values (xs is unchanged)."},
    {"with_item", "with_item(xs, i, v)", "A new list: xs with item i (0-based) replaced by v (xs is unchanged)."},
    {"str", "str(x, width, decimals)", "x as text; with width and decimals as POV-Ray's str (printf's %W.Df: width < 0 pads with zeros; decimals < 0 is 6)."},
    {"format", "format(template, [args, ...])", "Text with each {} replaced by the next argument ({{ and }} for braces)."},
    {"print", "print([args, ...])", "Writes file:line:col: print: args to stderr."},
    {"assert", "assert(cond, [message])", "Stops with an error at the call unless cond is true."},
    {"error", "error(message)", "Stops with an error at the call."},
    {"checker", "checker(c1, c2, [scale])", "A checker texture value."},
    {"stripes", "stripes(c1, c2, [scale, axis])", "A stripes texture value."},
    {"gradient", "gradient(c1, c2, [scale, axis])", "A gradient texture value."},
    {"image_texture", "image_texture(file, [mapping])", "An image file as a texture value."},
    {"noise", "noise(p)", "Gradient noise at point p, in [0, 1]."},
    {"fbm", "fbm(p, [octaves, lambda, omega])", "Fractal sum of noise, in [-1, 1]."},
    {"turbulence", "turbulence(p, [octaves, lambda, omega])", "Fractal sum of |noise|, in [0, 1]."},
    {"vturbulence", "vturbulence(lambda, omega, octaves, p)", "POV-Ray's vector turbulence: the displacement a turbulence warp scales."},
    {"cells", "cells(p)", "A random value per unit cell, in [0, 1)."},
    {"worley", "worley(p)", "Cellular (Worley) noise: the distance to the nearest feature point."},
    {"random", "random(seed[, \"povray\"])", "A deterministic random stream (\"povray\": POV-Ray 3.7's sequence for the seed)."},
    {"rand", "rand(r, [lo, hi])", "The next number of stream r, in [0, 1) or [lo, hi)."},
    {"identity", "identity()", "The identity transform."},
    {"vrotate", "vrotate(v, angles)", "v turned as `rotate angles` turns an object (degrees)."},
    {"vaxis_rotate", "vaxis_rotate(v, axis, degrees)", "v turned about axis through the origin."},
    {"distance", "distance(a, b)", "length(a - b)."},
    {"smoothstep", "smoothstep(e0, e1, x)", "0 below e0, 1 above e1, 3t² − 2t³ between."},
    {"spline", "spline(kind, keys, t)", "The curve through keys (a list of [t, value] pairs) at t."},
    {"trace", "trace(object, origin, direction)", "[point, normal] where the ray first meets object, or none."},
    {"vlength", "vlength(v)", "POV-Ray's name for length."},
    {"vnormalize", "vnormalize(v)", "POV-Ray's name for normalize."},
    {"vdot", "vdot(a, b)", "POV-Ray's name for dot."},
    {"vcross", "vcross(a, b)", "POV-Ray's name for cross."},
    {"lerp", "lerp(a, b, t)", "POV-Ray's name for mix."},
};

constexpr std::string_view kKeywords[] = {"let",   "if",    "else",   "for",   "in",        "while",  "macro",
                                          "return", "break", "continue", "include", "true",   "false",  "none",
                                          "and",   "or",    "not",    "with",  "translate", "rotate", "scale",
                                          "matrix", "step"};

}  // namespace

std::span<const BuiltinDoc> builtin_docs() { return kBuiltins; }

const BuiltinDoc* find_builtin_doc(std::string_view name) {
  for (const BuiltinDoc& b : kBuiltins)
    if (b.name == name) return &b;
  return nullptr;
}

std::vector<std::string> signature_params(std::string_view signature) {
  std::vector<std::string> out;
  std::size_t open = signature.find('('), close = signature.rfind(')');
  if (open == std::string_view::npos || close == std::string_view::npos || close <= open + 1) return out;
  std::string_view inside = signature.substr(open + 1, close - open - 1);
  std::string cur;
  for (char c : inside) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != ' ' && c != '[' && c != ']') {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

std::span<const std::string_view> keywords() { return kKeywords; }

}  // namespace rts::lsp
