#include "runtime/povray_hints.hpp"

#include <fmt/format.h>

namespace rts::runtime {
namespace {

struct Hint {
  std::string_view pov;
  std::string_view rts;  // completes "POV-Ray's 'X' is ..."
};

// docs/from-povray.md lists the same mapping. Each text is followed by " in rts": none says
// it again.
constexpr Hint kHints[] = {
    {"light_source", "'point_light' (or 'spot_light', 'area_light')"},
    {"object", "a value placed as a statement (write the variable's name alone)"},
    {"pigment", "'material { color = ... }'"},
    {"finish", "'material { diffuse = ... specular = ... reflect = ... }'"},
    {"texture", "'material { ... }' (a texture such as 'checker { ... }' goes in its 'color')"},
    {"interior", "'material { transmit = ... ior = ... }'"},
    {"global_settings", "'settings { ... }'"},
    {"background", "'settings { background = ... }'"},
    {"declare", "'let'"},
    {"local", "'let'"},
    {"smooth_triangle", "'triangle { ... n0 = ... n1 = ... n2 = ... }'"},
    {"mesh2", "'mesh { vertices = [...] faces = [...] }'"},
};

}  // namespace

std::string povray_hint(std::string_view word) {
  for (const Hint& h : kHints)
    if (h.pov == word) return fmt::format("; POV-Ray's '{}' is {} in rts", h.pov, h.rts);
  return "";
}

}  // namespace rts::runtime
