// Where rts's standard library (stdlib/: colors.rts, metals.rts, shapes.rts ...) is found, and
// which files of it an `include` name can mean. The interpreter searches it after the
// including file's folder and the -I folders, so a scene's own colors.rts still wins.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rts::runtime {

// The standard library's folder, or "" when there is none. In order: $RTS_STDLIB when set;
// share/rts/stdlib beside the executable's bin/ folder (an installed rts, wherever it was
// moved); the source tree's stdlib/ when the executable lives in the build tree (running
// uninstalled); the folder `cmake --install` puts it in.
std::string find_standard_library();

// The files in the library folder `dir` that `include "name"` may mean, best first:
//   "std/colors.rts"  → dir/colors.rts (the prefix says: the library's, never a local file)
//   "colors.rts"      → dir/colors.rts
//   "colors.inc"      → dir/colors.inc, then dir/colors.rts (POV-Ray's include names map onto
//                       the library file of the same stem)
// Names with a folder part (other than std/) or absolute ones are never looked up there.
std::vector<std::filesystem::path> standard_library_candidates(const std::string& dir, const std::string& name);

// True when `name` is written with the std/ prefix (searched in the library only).
bool names_standard_library(const std::string& name);

}  // namespace rts::runtime
