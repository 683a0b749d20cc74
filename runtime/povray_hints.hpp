// Hints for people who write POV-Ray (or course) spellings: `light_source`, `union`,
// `pigment`... are not rts words, and a "did you mean" by edit distance would mislead.
#pragma once

#include <string>
#include <string_view>

namespace rts::runtime {

// "; POV-Ray's 'union' is 'group' in rts" for a known foreign word, "" otherwise.
std::string povray_hint(std::string_view word);

}  // namespace rts::runtime
