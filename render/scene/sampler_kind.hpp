// Which sampler a scene asks for (settings { sampler = ... }): part of the description, so the
// scene needs nothing from render/sample/ to name it.
#pragma once

#include <cstdint>
#include <string_view>

namespace rts::render {

// How a pixel's sample points are placed: independently at random, on a jittered grid per
// dimension pair (padded, randomly paired strata), or on an Owen-scrambled Sobol
// (0,2)-sequence per dimension pair with a shuffled index (best at powers of two).
enum class SamplerKind : uint8_t { Random, Stratified, Sobol };

inline const char* sampler_name(SamplerKind k) {
  switch (k) {
    case SamplerKind::Random: return "random";
    case SamplerKind::Stratified: return "stratified";
    case SamplerKind::Sobol: return "sobol";
  }
  return "?";
}

// "random", "stratified" or "sobol"; false for anything else.
inline bool parse_sampler(std::string_view name, SamplerKind& out) {
  for (SamplerKind k : {SamplerKind::Random, SamplerKind::Stratified, SamplerKind::Sobol})
    if (name == sampler_name(k)) {
      out = k;
      return true;
    }
  return false;
}

}  // namespace rts::render
