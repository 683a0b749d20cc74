// ParamSet: typed, located block properties with use tracking and "did you mean" checks.
#include "render/scene/params.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rts::render {

namespace {

// Names farther than this many edits (or than a third of the word) are not suggested.
constexpr std::size_t kMaxSuggestDistance = 3;

// Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
// neighbouring letters each cost 1 ("raduis" is one edit from "radius", not two).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

// "a number", "an image"... for messages.
std::string with_article(const char* noun) {
  char c = noun[0];
  bool vowel = c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u';
  return fmt::format("{} {}", vowel ? "an" : "a", noun);
}

// Builders look names up a dozen times per block: reject by length and first letter before
// comparing bytes.
inline bool same_name(const std::string& a, std::string_view b) {
  return a.size() == b.size() && (b.empty() || a[0] == b[0]) &&
         std::char_traits<char>::compare(a.data(), b.data(), b.size()) == 0;
}

}  // namespace

std::string closest_name(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::string_view best;
  std::size_t best_distance = kMaxSuggestDistance + 1;
  // One edit per three letters: "fog" may be one edit off ("for"), never two ("box").
  std::size_t limit = std::min(kMaxSuggestDistance, std::max<std::size_t>(1, word.size() / 3));
  for (std::string_view c : candidates) {
    std::size_t d = edit_distance(word, c);
    if (d < best_distance && d <= limit && d < std::max(word.size(), c.size())) {
      best = c;
      best_distance = d;
    }
  }
  return std::string(best);
}

const char* param_type_name(const ParamValue& v) {
  switch (v.index()) {
    case 0:
      return "number";
    case 1:
      return "bool";
    case 2:
      return "string";
    case 3:
      return "vector";
    case 4:
      return "color";
    case 5:
      return "texture";
    case 6:
      return "material";
    case 7:
      return "list of vectors";
    case 8:
      return "list of numbers";
    case 9:
      return "color map";
    case 10:
      return "function";
    case 11:
      return "container";
    case 12:
      return "list of lists";
    case 13:
      return "list of textures";
    case 14:
      return "list of materials";
  }
  return "value";
}

void ParamSet::add(std::string name, ParamValue value, SourceRef loc) {
  for (Param& p : params_) {
    if (same_name(p.name, name)) {
      p.value = std::move(value);
      p.loc = loc;
      p.used = false;
      return;
    }
  }
  params_.push_back(Param{std::move(name), std::move(value), loc, false});
}

bool ParamSet::has(std::string_view name) const {
  return std::any_of(params_.begin(), params_.end(), [&](const Param& p) { return same_name(p.name, name); });
}

const Param* ParamSet::find(std::string_view name) {
  for (Param& p : params_) {
    if (same_name(p.name, name)) {
      p.used = true;
      return &p;
    }
  }
  return nullptr;
}

const ParamValue* ParamSet::value(std::string_view name) {
  const Param* p = find(name);
  return p ? &p->value : nullptr;
}

void ParamSet::fail(const Param& p, const std::string& message) const { throw SceneError(p.loc, message); }

void ParamSet::fail_block(const std::string& message) const {
  if (valid_ != nullptr) check_unused(*valid_);  // throws at an unknown property, if any
  throw SceneError(loc_, message);
}

namespace {
[[noreturn]] void wrong_type(const ParamSet& ps, const Param& p, const char* expected) {
  ps.fail(p, fmt::format("property '{}' of {} expects {}, got {}", p.name, ps.kind(), with_article(expected),
                         with_article(param_type_name(p.value))));
}

// Property `name` when it holds a T, `def` when it is absent; any other type is an error.
template <typename T>
T typed(ParamSet& ps, std::string_view name, const T& def, const char* expected) {
  const Param* p = ps.find(name);
  if (!p) return def;
  if (auto* v = std::get_if<T>(&p->value)) return *v;
  wrong_type(ps, *p, expected);
}

// For the require_* getters: "sphere needs property 'radius'".
void require_present(const ParamSet& ps, std::string_view name) {
  if (!ps.has(name)) ps.fail_block(fmt::format("{} needs property '{}'", ps.kind(), name));
}
}  // namespace

double ParamSet::number(std::string_view name, double def) {
  return typed<double>(*this, name, def, "number");
}

int ParamSet::integer(std::string_view name, int def) {
  const Param* p = find(name);
  if (!p) return def;
  auto* d = std::get_if<double>(&p->value);
  if (!d) wrong_type(*this, *p, "whole number");
  if (std::floor(*d) != *d || std::fabs(*d) > 2147483647.0)
    fail(*p, fmt::format("property '{}' of {} expects a whole number, got {}", p->name, kind_, *d));
  return static_cast<int>(*d);
}

bool ParamSet::boolean(std::string_view name, bool def) {
  return typed<bool>(*this, name, def, "bool");
}

std::string ParamSet::string(std::string_view name, const std::string& def) {
  return typed<std::string>(*this, name, def, "string");
}

Vec3 ParamSet::vec3(std::string_view name, Vec3 def) {
  return typed<Vec3>(*this, name, def, "vector");
}

Color ParamSet::color(std::string_view name, Color def) {
  const Param* p = find(name);
  if (!p) return def;
  if (auto* c = std::get_if<Color>(&p->value)) return *c;
  if (auto* d = std::get_if<double>(&p->value)) return Color(*d);
  if (auto* v = std::get_if<Vec3>(&p->value)) return Color(v->x, v->y, v->z);
  wrong_type(*this, *p, "color");
}

double ParamSet::require_number(std::string_view name) {
  require_present(*this, name);
  return number(name, 0.0);
}

Vec3 ParamSet::require_vec3(std::string_view name) {
  require_present(*this, name);
  return vec3(name, Vec3(0.0));
}

std::string ParamSet::require_string(std::string_view name) {
  require_present(*this, name);
  return string(name, "");
}

void ParamSet::check_unused(const std::vector<std::string_view>& valid) const {
  for (const Param& p : params_) {
    if (p.used) continue;
    // A valid name the builder did not need (e.g. `u` on a disc-less light) is not unknown.
    if (std::find(valid.begin(), valid.end(), std::string_view(p.name)) != valid.end()) continue;
    std::string msg = fmt::format("unknown property '{}' for {}", p.name, kind_);
    std::string hint = closest_name(p.name, valid);
    if (!hint.empty()) msg += fmt::format("; did you mean '{}'?", hint);
    msg += fmt::format(" ({} takes {})", kind_, fmt::join(valid, ", "));
    throw SceneError(p.loc, msg);
  }
}

SourceRef loc_of(ParamSet& ps, std::string_view name) {
  const Param* p = ps.find(name);
  return p ? p->loc : ps.loc();
}

// Range checks: "property 'radius' of sphere must be > 0, got -1".
void require(ParamSet& ps, std::string_view name, bool ok, std::string_view what, double got) {
  if (ok) return;
  throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} must be {}, got {}", name, ps.kind(), what, got));
}
double positive(ParamSet& ps, std::string_view name, double v) {
  require(ps, name, v > 0, "> 0", v);
  return v;
}
double non_negative(ParamSet& ps, std::string_view name, double v) {
  require(ps, name, v >= 0, ">= 0", v);
  return v;
}
namespace {
// Not zero and not NaN, however short: glm::length would round 1e-200 to 0.
bool nonzero(const Vec3& v) { return max_abs_component(v) > 0.0 && !std::isnan(v.x + v.y + v.z); }
}  // namespace

// Any non-zero length is a direction: a scene modelled at 1e-13 units has edges that short
// (unit_vector normalises them without underflow).
Vec3 direction(ParamSet& ps, std::string_view name, Vec3 v) {
  if (!nonzero(v))
    throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} must be a non-zero vector", name, ps.kind()));
  return v;
}
void distinct(ParamSet& ps, std::string_view name, std::string_view other, const Vec3& difference) {
  if (!nonzero(difference))
    throw SceneError(loc_of(ps, name),
                     fmt::format("property '{}' of {} must differ from '{}'", name, ps.kind(), other));
}
void non_negative_color(ParamSet& ps, std::string_view name, const Color& c) {
  if (c.r < 0 || c.g < 0 || c.b < 0)
    throw SceneError(loc_of(ps, name), fmt::format("property '{}' of {} must not be negative", name, ps.kind()));
}

}  // namespace rts::render
