// POV-Ray scenes on the command line: `rts import scene.pov` and `rts render scene.pov`
// (translated in memory, import/pov/). Only a scene named *.pov (or given --format pov)
// reaches the POV-Ray front end: an .rts scene never does.
#pragma once

#include <string>
#include <vector>

#include "import/pov/pov_import.hpp"

namespace rts::cli {

// A .pov file, by its extension.
bool is_pov_path(const std::string& path);

// Prints "file:line:col: warning|error: message", the source line and a caret (the line is
// read from the file when it can be).
void print_pov_diagnostic(const import::pov::Diagnostic& d, const char* severity);

// Reads and translates `path`. On success returns true and fills `result` (warnings already
// printed); on failure prints the located error and returns false.
bool import_pov_file(const std::string& path, const import::pov::PovOptions& options,
                     import::pov::PovResult& result, std::string& why);

// Reads POV-Ray's render options from the .ini file `path` (--ini) into `options`, printing
// its warnings. False (with `why`, or with the located error printed) when it cannot.
bool read_pov_ini(const std::string& path, import::pov::PovOptions& options, std::string& why);

}  // namespace rts::cli
