// The warnings about an evaluated scene that every front end shows alike: `rts check`,
// `rts render` (before it renders) and the language server. They come after evaluation,
// which reports its own warnings (unused declarations, unmatched -D) as it runs:
//   - what the scene builder skipped or changed (zero-area triangles, mesh faces, normals);
//   - a scene that places no objects, or no lights (in Whitted mode; in path mode emission
//     and the sky light it too);
//   - a camera inside a closed object (sphere, box, capped cylinder or cone, torus), which
//     then sees only that object's inside.
// Warnings found while rendering (max_depth capped, path-mode energy) stay with the render.
#pragma once

#include <string_view>
#include <vector>

#include "parser/diagnostics.hpp"
#include "parser/source.hpp"
#include "runtime/evaluator.hpp"

namespace rts {

// `main` is the scene file (whole-file warnings point at it); `integrator` overrides the
// scene's settings.integrator when not empty ("whitted" or "path", as --integrator).
std::vector<Diagnostic> scene_warnings(const EvalResult& result, const SourceManager& sources,
                                       const SourceFile* main, std::string_view integrator = {});

}  // namespace rts
