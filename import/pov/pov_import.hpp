// `rts import scene.pov`: POV-Ray's scene language translated into a readable rts program.
// `#declare` becomes `let`, `#macro` a macro, `#while`/`#for` loops, `#if` an if; objects,
// textures, lights and the camera become rts blocks with POV-Ray's defaults written out.
// docs/from-povray.md is the mapping.
#pragma once

#include <string>
#include <vector>

namespace rts::import::pov {

// A located message about the input: "file:line:col: warning: message".
struct Diagnostic {
  std::string file;  // as the input was named
  int line = 0, col = 0;
  std::string message;
};

// A syntax error in the POV-Ray text (or an include that cannot be read).
struct PovError {
  Diagnostic where;
};

struct PovOptions {
  std::string source_path;                 // the scene as named on the command line
  std::vector<std::string> include_dirs;   // searched after the including file's folder (Library_Path)
  bool strict = false;                     // warnings become errors (the first is thrown as PovError)
  // rts's standard library folder (runtime/stdlib_path.hpp), read for the names a standard
  // include gives the scene; "" when unknown (every undeclared name is then taken on trust).
  std::string stdlib_dir;
  // Where the translation is written ("": beside the scene). Files the scene names relative to
  // itself (image maps) are then written relative to this folder, so they are still found.
  std::string output_dir;
  // POV-Ray's render options (render_options.hpp), written into the scene's settings.
  int width = 0, height = 0;          // 0: not given
  double antialias_threshold = -1;    // < 0: no antialiasing asked for
};

struct PovOutputFile {
  std::string name;   // file name, written beside the main .rts
  std::string text;
};

struct PovResult {
  std::string rts;                         // the main scene
  std::vector<PovOutputFile> includes;     // the user's own include files, each translated
  std::vector<Diagnostic> warnings;        // what rts cannot express, located
};

// True when `text` looks like POV-Ray's scene language (#include, #declare, #version,
// `camera {`, `light_source {`).
bool looks_like_pov(const std::string& text);

// Translates the scene `text` (read from options.source_path). Throws PovError.
PovResult import_pov(const std::string& text, const PovOptions& options);

}  // namespace rts::import::pov
