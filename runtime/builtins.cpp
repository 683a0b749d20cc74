// The builtin functions. Trigonometry works in radians (radians()/degrees() convert);
// `rotate` is the only place the language takes degrees.
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "render/geometry/function/noise.hpp"
#include "runtime/interpreter.hpp"
#include "runtime/builtin_args.hpp"
#include "runtime/ops.hpp"

namespace rts::runtime {

namespace {

using namespace builtin_args;

// A number result that must be finite: "sqrt(-1) produced NaN (not a number)".
Value finite(const BuiltinCall& c, double r) {
  if (!std::isfinite(r)) {
    std::string args;
    for (std::size_t i = 0; i < c.argc; ++i) {
      if (i) args += ", ";
      // An excerpt: the arguments are there to recognise the call, and a list may be huge.
      constexpr std::size_t kShown = 200;
      if (!append_text(args, c.args[i], true, kShown)) {
        std::size_t cut = kShown;
        while (cut > 0 && (static_cast<unsigned char>(args[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
        args.resize(cut);
        args += "…";
        break;
      }
    }
    check_finite(r, c.call.loc, fmt::format("{}({})", c.def.name, args).c_str());
  }
  return Value::number(r);
}

template <double (*F)(double)>
Value math1(BuiltinCall& c) {
  return finite(c, F(num(c, 0)));
}
template <double (*F)(double, double)>
Value math2(BuiltinCall& c) {
  return finite(c, F(num(c, 0), num(c, 1)));
}

double radians(double d) { return d * (M_PI / 180.0); }
double degrees(double r) { return r * (180.0 / M_PI); }
double sin_(double x) { return std::sin(x); }
double cos_(double x) { return std::cos(x); }
double tan_(double x) { return std::tan(x); }
double asin_(double x) { return std::asin(x); }
double acos_(double x) { return std::acos(x); }
double atan_(double x) { return std::atan(x); }
double atan2_(double y, double x) { return std::atan2(y, x); }
double sqrt_(double x) { return std::sqrt(x); }
double pow_(double x, double y) { return std::pow(x, y); }
double exp_(double x) { return std::exp(x); }
double log_(double x) { return std::log(x); }
double abs_(double x) { return std::fabs(x); }
double floor_(double x) { return std::floor(x); }
double ceil_(double x) { return std::ceil(x); }
double round_(double x) { return std::round(x); }

// min/max over numbers given as arguments, or over one list of numbers.
template <bool Max>
Value extreme(BuiltinCall& c) {
  const Value* items = c.args;
  std::size_t n = c.argc;
  if (n == 1 && c.args[0].type == Type::List) {
    items = as_list(c.args[0]).data();
    n = as_list(c.args[0]).size();
    if (n == 0) c.in.fail(arg_loc(c, 0), fmt::format("'{}' of an empty list", c.def.name));
  }
  if (n > 0 && items[0].type == Type::Vector) {
    // Vectors: component by component (a box's corners from two points in any order).
    glm::dvec3 best = items[0].v;
    for (std::size_t i = 1; i < n; ++i) {
      if (items[i].type != Type::Vector)
        c.in.fail(arg_loc(c, c.argc == n ? i : 0),
                  fmt::format("'{}' of vectors needs vectors only, got {}", c.def.name, with_article(items[i].type)));
      best = Max ? glm::max(best, items[i].v) : glm::min(best, items[i].v);
    }
    return Value::vector(best);
  }
  double best = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (items[i].type != Type::Number)
      c.in.fail(arg_loc(c, c.argc == n ? i : 0),
                fmt::format("'{}' needs numbers, got {}", c.def.name, with_article(items[i].type)));
    double x = items[i].v.x;
    if (i == 0 || (Max ? x > best : x < best)) best = x;
  }
  return Value::number(best);
}

Value clamp(BuiltinCall& c) {
  double x = num(c, 0), lo = num(c, 1), hi = num(c, 2);
  if (lo > hi) c.in.fail(c.call.loc, fmt::format("clamp: lower bound {} is above upper bound {}", lo, hi));
  return Value::number(std::min(std::max(x, lo), hi));
}

Value mix(BuiltinCall& c) {
  const Value& a = c.args[0];
  const Value& b = c.args[1];
  double t = num(c, 2);
  if (a.type != b.type || (a.type != Type::Number && a.type != Type::Vector && a.type != Type::Color))
    c.in.fail(c.call.loc, fmt::format("'mix' needs two numbers, vectors or colors of the same kind, got {} and {}",
                                      with_article(a.type), with_article(b.type)));
  Value r = a;
  r.v = a.v + (b.v - a.v) * t;
  return r;
}

Value dot(BuiltinCall& c) { return finite(c, glm::dot(vec(c, 0), vec(c, 1))); }
Value cross(BuiltinCall& c) { return Value::vector(glm::cross(vec(c, 0), vec(c, 1))); }
Value length(BuiltinCall& c) { return finite(c, glm::length(vec(c, 0))); }
Value normalize(BuiltinCall& c) {
  glm::dvec3 v = vec(c, 0);
  double len = glm::length(v);
  if (len == 0.0) c.in.fail(arg_loc(c, 0), "cannot normalize a zero-length vector");
  return Value::vector(v / len);
}

Value rgb(BuiltinCall& c) {
  if (c.argc == 1) {
    if (c.args[0].type == Type::Vector || c.args[0].type == Type::Color) return Value::color(c.args[0].v);
    return Value::color(glm::dvec3(num(c, 0)));
  }
  if (c.argc != 3) c.in.fail(c.call.loc, fmt::format("'rgb' takes 1 or 3 arguments, got {}", c.argc));
  return Value::color({num(c, 0), num(c, 1), num(c, 2)});
}

Value vec_(BuiltinCall& c) { return Value::vector({num(c, 0), num(c, 1), num(c, 2)}); }

Value len(BuiltinCall& c) {
  const Value& v = c.args[0];
  if (v.type == Type::List) return Value::number(static_cast<double>(as_list(v).size()));
  if (v.type == Type::String) return Value::number(static_cast<double>(as_string(v).size()));
  if (v.type == Type::Range) return Value::number(static_cast<double>(range_count(v)));
  bad_arg(c, 0, "a list, a string or a range");
}

// select(c, a, b): a when c is true, b when false. eval_call evaluates only the chosen
// argument (the builtin is `lazy`); this is the same choice for already evaluated arguments.
Value select(BuiltinCall& c) {
  if (c.args[0].type != Type::Bool) bad_select_condition(c.in, c.call, c.args[0]);
  return c.args[0].truth() ? c.args[1] : c.args[2];
}

// append(xs, v, ...): a new list, xs followed by the values (xs itself is not changed; to
// push onto a variable's list in place, `xs += [v]`).
Value append(BuiltinCall& c) {
  if (c.args[0].type != Type::List) bad_arg(c, 0, "a list");
  return c.in.concat(c.args[0], Value::list(std::vector<Value>(c.args + 1, c.args + c.argc)), c.call.loc);
}

// A copy of the list with item `i` replaced: rts's lists are values, so this is how an element
// changes (`a = with_item(a, 2, v)`; POV-Ray's `#declare A[2] = v` imports to it).
Value with_item(BuiltinCall& c) {
  if (c.args[0].type != Type::List) bad_arg(c, 0, "a list");
  const std::vector<Value>& items = as_list(c.args[0]);
  const double i = num(c, 1);
  if (i != std::floor(i) || i < 0 || i >= static_cast<double>(items.size()))
    c.in.fail(arg_loc(c, 1), fmt::format("index {} out of range for a list of {} element{}", c.in.text_of(c.args[1], c.call.loc),
                                         items.size(), items.size() == 1 ? "" : "s"));
  std::vector<Value> copy = items;
  copy[static_cast<std::size_t>(i)] = c.args[2];
  return Value::list(std::move(copy));
}

// str(x), or with a width and decimals as POV-Ray's str(x, width, decimals) (C's printf
// "%W.Df"): width > 0 pads with spaces, < 0 with zeros to |width|; decimals < 0 is 6.
Value str_(BuiltinCall& c) {
  if (c.argc == 1) return Value::string(c.in.text_of(c.args[0], c.call.loc));
  const double x = num(c, 0);
  const double w = c.argc > 1 ? num(c, 1) : 0.0, d = c.argc > 2 ? num(c, 2) : -1.0;
  if (!(std::fabs(w) <= 1000.0) || !(d <= 100.0))
    c.in.fail(arg_loc(c, std::fabs(w) <= 1000.0 ? 2 : 1), "str(x, width, decimals): width from -1000 to 1000, decimals at most 100");
  const int width = static_cast<int>(w), decimals = d < 0 ? 6 : static_cast<int>(d);
  std::string out = std::isfinite(x) ? fmt::format("{:.{}f}", x, decimals) : fmt::format("{}", x);
  const std::size_t want = static_cast<std::size_t>(std::abs(width));
  if (out.size() < want) {
    if (width > 0 || !std::isfinite(x)) {
      out.insert(0, want - out.size(), ' ');
    } else {
      const std::size_t at = out[0] == '-' ? 1 : 0;  // zeros after the sign, as printf's
      out.insert(at, want - out.size(), '0');
    }
  }
  return Value::string(std::move(out));
}

Value format(BuiltinCall& c) {
  const std::string& f = str(c, 0);
  std::string out;
  std::size_t next = 1;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i] == '{' && i + 1 < f.size() && f[i + 1] == '{') {
      out += '{';
      ++i;
    } else if (f[i] == '}' && i + 1 < f.size() && f[i + 1] == '}') {
      out += '}';
      ++i;
    } else if (f[i] == '{' && i + 1 < f.size() && f[i + 1] == '}') {
      if (next >= c.argc)
        c.in.fail(arg_loc(c, 0), fmt::format("format string has more '{{}}' than the {} value{} given", c.argc - 1,
                                             c.argc == 2 ? "" : "s"));
      out += c.in.text_of(c.args[next++], c.call.loc);
      ++i;
    } else {
      out += f[i];
    }
  }
  if (next != c.argc)
    c.in.fail(arg_loc(c, next),
              fmt::format("format string has {} '{{}}' but {} values were given", next - 1, c.argc - 1));
  c.in.spend(out.size(), c.call.loc, "string bytes built");
  return Value::string(std::move(out));
}

Value print(BuiltinCall& c) {
  std::string text;
  for (std::size_t i = 0; i < c.argc; ++i) {
    if (i) text += " ";
    text += c.in.text_of(c.args[i], c.call.loc);
  }
  const SourceLoc& l = c.call.loc;
  std::cerr << fmt::format("{}:{}:{}: print: {}\n", l.file() ? l.file()->path() : "", l.line(), l.col(), text);
  return Value::none();
}

Value assert_(BuiltinCall& c) {
  if (c.args[0].type != Type::Bool) bad_arg(c, 0, "a bool");
  if (!c.args[0].truth()) {
    std::string msg = "assertion failed";
    if (c.argc > 1) msg += ": " + c.in.text_of(c.args[1], c.call.loc);
    c.in.fail(c.call.loc, msg);
  }
  return Value::none();
}

Value error(BuiltinCall& c) { c.in.fail(c.call.loc, c.in.text_of(c.args[0], c.call.loc)); }

// checker(c1, c2, scale), stripes(c1, c2, scale, axis), gradient(...), image_texture(file, mapping):
// the same properties as the block forms, checked by the builder when the texture is used.
Value texture(BuiltinCall& c, const char* kind, std::initializer_list<const char*> names) {
  std::vector<Property> props;
  std::size_t i = 0;
  for (const char* n : names) {
    if (i >= c.argc) break;
    props.push_back(Property{ast::intern(n), c.args[i], arg_loc(c, i)});
    ++i;
  }
  return c.in.make_texture(ast::intern(kind), std::move(props), c.call.loc);
}
Value checker(BuiltinCall& c) { return texture(c, "checker", {"color1", "color2", "scale"}); }
Value stripes(BuiltinCall& c) { return texture(c, "stripes", {"color1", "color2", "scale", "axis"}); }
Value gradient(BuiltinCall& c) { return texture(c, "gradient", {"color1", "color2", "scale", "axis"}); }
Value image_texture(BuiltinCall& c) { return texture(c, "image_texture", {"file", "mapping"}); }

// The noise family (render/geometry/function/noise.hpp, the same functions the renderer and
// compiled pattern functions call): noise(p) in [0, 1], fbm(p, octaves, lambda, omega) in
// [-1, 1], turbulence(p, octaves, lambda, omega) in [0, 1], cells(p) in [0, 1), worley(p).
Value noise(BuiltinCall& c) { return finite(c, render::pattern::noise01(vec(c, 0))); }
Value cells(BuiltinCall& c) { return finite(c, render::pattern::cells(vec(c, 0))); }
Value worley(BuiltinCall& c) { return finite(c, render::pattern::worley(vec(c, 0))); }
template <bool Turbulence>
Value noise_sum(BuiltinCall& c) {
  const glm::dvec3 p = vec(c, 0);
  const double octaves = c.argc > 1 ? num(c, 1) : 6.0;
  if (!(octaves >= 1 && octaves <= render::pattern::kMaxOctaves) || std::floor(octaves) != octaves)
    c.in.fail(arg_loc(c, 1), fmt::format("the octaves of '{}' must be a whole number from 1 to {}, got {}", c.def.name,
                                         render::pattern::kMaxOctaves, octaves));
  const double lambda = c.argc > 2 ? num(c, 2) : 2.0;
  const double omega = c.argc > 3 ? num(c, 3) : 0.5;
  const int n = static_cast<int>(octaves);
  return finite(c, Turbulence ? render::pattern::turbulence(p, n, lambda, omega)
                              : render::pattern::fbm(p, n, lambda, omega));
}

// vturbulence(lambda, omega, octaves, p): POV-Ray's vector turbulence (its argument order), the
// displacement a `turbulence` warp scales: sum over octaves of omega^i * vector noise at
// lambda^i * p (render/geometry/function/noise.hpp).
Value vturbulence(BuiltinCall& c) {
  const double lambda = num(c, 0), omega = num(c, 1), octaves = num(c, 2);
  if (!(octaves >= 1 && octaves <= render::pattern::kMaxOctaves) || std::floor(octaves) != octaves)
    c.in.fail(arg_loc(c, 2), fmt::format("the octaves of 'vturbulence' must be a whole number from 1 to {}, got {}",
                                         render::pattern::kMaxOctaves, octaves));
  const glm::dvec3 v = render::pattern::vector_turbulence(vec(c, 3), static_cast<int>(octaves), lambda, omega);
  for (int k = 0; k < 3; ++k) finite(c, v[k]);
  return Value::vector(v);
}

// random(seed) makes a stream; rand(r) draws from it in [0, 1), rand(r, lo, hi) in [lo, hi).
// random(seed, "povray") draws POV-Ray 3.7's sequence for that seed instead (rts import).
Value random(BuiltinCall& c) {
  // Seeds are whole numbers a double holds exactly, so the same text is the same seed.
  constexpr double kMaxExactWhole = 9007199254740992.0;  // 2^53
  double seed = num(c, 0);
  bool povray = false;
  if (c.argc == 2) {
    if (c.args[1].type != Type::String || as_string(c.args[1]) != "povray")
      bad_arg(c, 1, "\"povray\" (POV-Ray's own sequence)");
    povray = true;
  }
  if (povray) {
    // POV-Ray takes the seed as a C int: whole numbers, negative ones wrapping.
    if (!(std::abs(seed) <= kMaxExactWhole) || std::floor(seed) != seed) bad_arg(c, 0, "a whole number");
    seed = std::fmod(seed, 4294967296.0);
    if (seed < 0) seed += 4294967296.0;
  } else if (seed < 0 || seed > kMaxExactWhole || std::floor(seed) != seed) {
    bad_arg(c, 0, "a whole number from 0 to 2^53");
  }
  Value v;
  v.type = Type::Random;
  v.ref = std::make_shared<RandomValue>(static_cast<uint64_t>(seed), povray);
  return v;
}
Value rand(BuiltinCall& c) {
  if (c.args[0].type != Type::Random) bad_arg(c, 0, "a random stream (from random(seed))");
  if (c.argc == 2) c.in.fail(c.call.loc, "'rand' takes 1 or 3 arguments: rand(r) or rand(r, lo, hi)");
  double u = as_random(c.args[0]).next_unit();
  if (c.argc == 1) return Value::number(u);
  double lo = num(c, 1), hi = num(c, 2);
  return Value::number(lo + (hi - lo) * u);
}

Value identity(BuiltinCall&) {
  Value v;
  v.type = Type::Transform;
  v.ref = std::make_shared<TransformValue>(render::Mat4(1.0));
  return v;
}

}  // namespace

const std::vector<Builtin>& builtin_table() {
  static const std::vector<Builtin> table = with_math_builtins({
      {"sin", 1, 1, math1<sin_>},
      {"cos", 1, 1, math1<cos_>},
      {"tan", 1, 1, math1<tan_>},
      {"asin", 1, 1, math1<asin_>},
      {"acos", 1, 1, math1<acos_>},
      {"atan", 1, 1, math1<atan_>},
      {"atan2", 2, 2, math2<atan2_>},
      {"sqrt", 1, 1, math1<sqrt_>},
      {"pow", 2, 2, math2<pow_>},
      {"exp", 1, 1, math1<exp_>},
      {"log", 1, 1, math1<log_>},
      {"abs", 1, 1, math1<abs_>},
      {"floor", 1, 1, math1<floor_>},
      {"ceil", 1, 1, math1<ceil_>},
      {"round", 1, 1, math1<round_>},
      {"radians", 1, 1, math1<radians>},
      {"degrees", 1, 1, math1<degrees>},
      {"min", 1, -1, extreme<false>},
      {"max", 1, -1, extreme<true>},
      {"clamp", 3, 3, clamp},
      {"mix", 3, 3, mix},
      {"dot", 2, 2, dot},
      {"cross", 2, 2, cross},
      {"length", 1, 1, length},
      {"normalize", 1, 1, normalize},
      {"rgb", 1, 3, rgb},
      {"vec", 3, 3, vec_},
      {"len", 1, 1, len},
      {"select", 3, 3, select, true},
      {"append", 2, -1, append},
      {"with_item", 3, 3, with_item},
      {"str", 1, 3, str_},
      {"format", 1, -1, format},
      {"print", 0, -1, print},
      {"assert", 1, 2, assert_},
      {"error", 1, 1, error},
      {"checker", 2, 3, checker},
      {"stripes", 2, 4, stripes},
      {"gradient", 2, 4, gradient},
      {"image_texture", 1, 2, image_texture},
      {"noise", 1, 1, noise},
      {"fbm", 1, 4, noise_sum<false>},
      {"turbulence", 1, 4, noise_sum<true>},
      {"vturbulence", 4, 4, vturbulence},
      {"cells", 1, 1, cells},
      {"worley", 1, 1, worley},
      {"random", 1, 2, random},
      {"rand", 1, 3, rand},
      {"identity", 0, 0, identity},
  });
  return table;
}

}  // namespace rts::runtime
