// The golden-image scene conventions: extra `rts render` arguments from `// args:` lines and
// the AOV images those arguments ask for.
#pragma once

#include <string>
#include <vector>

namespace rts::images {

// Words of every line that starts with `// args:` (whitespace-separated, no quoting), in
// order. E.g. "// args: --aov normal,depth" → {"--aov", "normal,depth"}.
std::vector<std::string> scene_args(const std::string& scene_text);

// The AOV names requested by `--aov a,b` or `--aov=a,b` in args (repeats allowed).
std::vector<std::string> requested_aovs(const std::vector<std::string>& args);

// The file an AOV goes to next to the main output: "dir/name.png" + "normal" →
// "dir/name.normal.png" (the rts render convention).
std::string aov_path(const std::string& output_png, const std::string& aov);

}  // namespace rts::images
