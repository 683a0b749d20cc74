// Pattern texture blocks: see pattern_builder.hpp.
#include "render/builder/pattern_builder.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "render/geometry/function/noise.hpp"

namespace rts::render {

namespace {

struct PatternKindName {
  std::string_view name;
  PatternKind kind;
};
constexpr PatternKindName kPatterns[] = {
    {"bozo", PatternKind::Bozo},         {"spotted", PatternKind::Spotted},   {"granite", PatternKind::Granite},
    {"marble", PatternKind::Marble},     {"wood", PatternKind::Wood},         {"agate", PatternKind::Agate},
    {"onion", PatternKind::Onion},       {"leopard", PatternKind::Leopard},   {"wrinkles", PatternKind::Wrinkles},
    {"crackle", PatternKind::Crackle},   {"cells", PatternKind::Cells},       {"bumps", PatternKind::Bumps},
    {"dents", PatternKind::Dents},       {"ripples", PatternKind::Ripples},   {"waves", PatternKind::Waves},
    {"pattern", PatternKind::Function},  {"radial", PatternKind::Radial},     {"spiral1", PatternKind::Spiral1},
    {"spiral2", PatternKind::Spiral2},   {"boxed", PatternKind::Boxed},       {"cylindrical", PatternKind::Cylindrical},
    {"planar", PatternKind::Planar},     {"spherical", PatternKind::Spherical},
};

struct WaveName {
  std::string_view name;
  WaveKind wave;
};
constexpr WaveName kWaves[] = {{"ramp", WaveKind::Ramp},       {"triangle", WaveKind::Triangle},
                               {"sine", WaveKind::Sine},       {"scallop", WaveKind::Scallop},
                               {"cubic", WaveKind::Cubic},     {"clamp", WaveKind::Clamp}};

const std::vector<std::string_view> kCommonNames = {"color_map", "color1",    "color2", "turbulence", "octaves",
                                                    "omega",     "lambda",    "wave",   "frequency",  "phase"};

std::vector<std::string_view> names_for(PatternKind kind) {
  std::vector<std::string_view> names = kCommonNames;
  if (kind == PatternKind::Agate) names.push_back("agate_turb");
  if (kind == PatternKind::Function) names.push_back("function");
  if (kind == PatternKind::Gradient) names.push_back("axis");
  if (kind == PatternKind::Spiral1 || kind == PatternKind::Spiral2) names.push_back("arms");
  return names;
}

[[noreturn]] void fail_at(ParamSet& ps, std::string_view name, const std::string& message) {
  ps.fail(*ps.find(name), message);
}

double finite_number(ParamSet& ps, std::string_view name, double def) {
  const double x = ps.number(name, def);
  if (!std::isfinite(x)) fail_at(ps, name, fmt::format("property '{}' of {} must be finite", name, ps.kind()));
  return x;
}

}  // namespace

const std::vector<std::string_view>& pattern_kinds() {
  static const std::vector<std::string_view> names = [] {
    std::vector<std::string_view> out;
    for (const PatternKindName& k : kPatterns) out.push_back(k.name);
    return out;
  }();
  return names;
}

bool is_pattern_kind(std::string_view kind) {
  return std::any_of(std::begin(kPatterns), std::end(kPatterns), [&](const PatternKindName& k) { return k.name == kind; });
}

std::vector<std::string_view> pattern_property_names(std::string_view kind) {
  for (const PatternKindName& k : kPatterns)
    if (k.name == kind) return names_for(k.kind);
  return {};
}

void build_pattern_texture(std::string_view kind, ParamSet& ps, TextureDesc& t) {
  t.kind = TextureKind::Pattern;
  PatternDesc& d = t.pattern;
  for (const PatternKindName& k : kPatterns)
    if (k.name == kind) d.kind = k.kind;
  if (kind == "gradient") d.kind = PatternKind::Gradient;   // with a color_map (scene_builder.cpp)
  const std::vector<std::string_view> valid = names_for(d.kind);
  ps.set_valid_names(&valid);

  // Marble, wood and the spirals are triangle waves in POV-Ray; a user function's values are clamped.
  d.wave = d.kind == PatternKind::Marble || d.kind == PatternKind::Wood || d.kind == PatternKind::Spiral1 ||
                   d.kind == PatternKind::Spiral2
               ? WaveKind::Triangle
           : d.kind == PatternKind::Function                           ? WaveKind::Clamp
                                                                       : WaveKind::Ramp;
  if (ps.has("wave")) {
    const std::string w = ps.string("wave", "ramp");
    auto it = std::find_if(std::begin(kWaves), std::end(kWaves), [&](const WaveName& x) { return x.name == w; });
    if (it == std::end(kWaves))
      fail_at(ps, "wave",
              fmt::format("property 'wave' of {} must be \"ramp\", \"triangle\", \"sine\", \"scallop\", \"cubic\" or "
                          "\"clamp\", got \"{}\"",
                          kind, w));
    d.wave = it->wave;
  }

  // turbulence: a number (the same on every axis) or a vector.
  if (const ParamValue* v = ps.value("turbulence")) {
    if (auto* x = std::get_if<double>(v))
      d.turbulence = Vec3(*x);
    else if (auto* vec = std::get_if<Vec3>(v))
      d.turbulence = *vec;
    else
      fail_at(ps, "turbulence", fmt::format("property 'turbulence' of {} expects a number or a vector, got a {}", kind,
                                            param_type_name(*v)));
    if (!std::isfinite(d.turbulence.x) || !std::isfinite(d.turbulence.y) || !std::isfinite(d.turbulence.z))
      fail_at(ps, "turbulence", fmt::format("property 'turbulence' of {} must be finite", kind));
  }
  d.octaves = ps.integer("octaves", d.octaves);
  if (d.octaves < 1 || d.octaves > pattern::kMaxOctaves)
    fail_at(ps, "octaves", fmt::format("property 'octaves' of {} must be from 1 to {}, got {}", kind,
                                       pattern::kMaxOctaves, d.octaves));
  if (d.kind == PatternKind::Spiral1 || d.kind == PatternKind::Spiral2) d.arms = finite_number(ps, "arms", d.arms);
  d.omega = finite_number(ps, "omega", d.omega);
  d.lambda = finite_number(ps, "lambda", d.lambda);
  d.frequency = finite_number(ps, "frequency", d.frequency);
  d.phase = finite_number(ps, "phase", d.phase);
  if (d.kind == PatternKind::Agate) d.agate_turb = finite_number(ps, "agate_turb", d.agate_turb);

  if (d.kind == PatternKind::Function) {
    const ParamValue* f = ps.value("function");
    if (!f) ps.fail_block("pattern needs property 'function' (a macro of one point, e.g. macro f(p) { return noise(p) })");
    auto* ref = std::get_if<FunctionRef>(f);
    if (!ref || !ref->function)
      fail_at(ps, "function", fmt::format("property 'function' of pattern expects a macro of one point, got a {}",
                                          param_type_name(*f)));
    d.function = ref->function;
  }

  // The color map; without one, color1 (default black) at 0 to color2 (default white) at 1.
  if (const ParamValue* v = ps.value("color_map")) {
    auto* map = std::get_if<ColorMapParam>(v);
    if (!map)
      fail_at(ps, "color_map",
              fmt::format("property 'color_map' of {} expects a list of [value, color] pairs, got a {}", kind,
                          param_type_name(*v)));
    if (map->entries.empty()) fail_at(ps, "color_map", fmt::format("the color_map of {} has no entries", kind));
    for (std::size_t i = 0; i < map->entries.size(); ++i) {
      const double x = map->entries[i].value;
      if (!std::isfinite(x))
        fail_at(ps, "color_map", fmt::format("entry {} of the color_map of {} has a value that is not finite", i + 1, kind));
      const double t = map->entries[i].transmit;
      if (!(t >= 0.0 && t <= 1.0))
        fail_at(ps, "color_map",
                fmt::format("entry {} of the color_map of {} has transmit {}: it must be from 0 (opaque) to 1 "
                            "(clear)",
                            i + 1, kind, t));
      if (i > 0 && x < map->entries[i - 1].value)
        fail_at(ps, "color_map",
                fmt::format("the color_map of {} must list its values in ascending order: entry {} ({}) comes after {}",
                            kind, i + 1, x, map->entries[i - 1].value));
    }
    if (ps.has("color1") || ps.has("color2"))
      fail_at(ps, ps.has("color1") ? "color1" : "color2",
              fmt::format("{} takes a 'color_map' or 'color1'/'color2', not both", kind));
    d.color_map = map->entries;
  } else {
    const Color c1 = ps.color("color1", Color(0.0)), c2 = ps.color("color2", Color(1.0));
    d.color_map = {{0.0, {c1.r, c1.g, c1.b}}, {1.0, {c2.r, c2.g, c2.b}}};
  }
  ps.check_unused(valid);
  ps.set_valid_names(nullptr);
}

}  // namespace rts::render
