// POV-Ray's render options that change the picture, read from a .ini file (`rts import
// --ini FILE`, `rts render scene.pov --ini FILE`): `Width`, `Height`, `Antialias`,
// `Antialias_Threshold`, and the same as switches on an .ini line (`+W320 +H240 +A0.3`, `-A`).
// The translation writes them into the scene's settings, so `rts render scene.rts` alone
// renders what `povray scene.ini` would. Other keys (file names, display, ...) are left alone;
// those that change the picture and are not read (`Clock`, `Antialias_Depth`, ...) are warned
// about.
#pragma once

#include <string>
#include <vector>

#include "import/pov/pov_import.hpp"

namespace rts::import::pov {

// Reads `text` (the .ini file `path`) into options.width, .height and .antialias_threshold.
// Appends a located warning for each key that changes POV-Ray's picture but is not read; throws
// PovError for a value that is not a number where one is needed.
void read_render_options(const std::string& text, const std::string& path, PovOptions& options,
                         std::vector<Diagnostic>& warnings);

}  // namespace rts::import::pov
