// Where a scene item came from, as the renderer sees it: a file name and a position, no
// syntax. The runtime fills it in from its own SourceLoc; `file` points at a string that
// lives as long as the process (the runtime's SourceManager owns it).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rts::render {

struct SourceRef {
  const char* file = "";
  uint32_t line = 0;
  uint32_t col = 0;
};

// Something the scene asked for that is skipped or changed rather than refused (a zero-area
// triangle, NaN normals, max_depth above the cap): shown as "file:line:col: warning: ...".
struct Warning {
  SourceRef where;
  std::string message;
};

// A scene that cannot be built: unknown/missing/mistyped property, unreadable mesh file...
// `where` is the most precise location known (the property, else the block).
struct SceneError : std::runtime_error {
  SourceRef where;
  SceneError(SourceRef w, const std::string& msg) : std::runtime_error(msg), where(w) {}
};

// A scene that was built but cannot be rendered or written: unreadable texture image, image
// size over the limit, output not writable. `where` may be empty (file == "").
struct RenderError : std::runtime_error {
  SourceRef where;
  RenderError(SourceRef w, const std::string& msg) : std::runtime_error(msg), where(w) {}
};

}  // namespace rts::render
