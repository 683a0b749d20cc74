// Writing a whole file atomically from bytes in memory: to a temporary file in the target's
// directory, fsync'ed, then renamed over the target, so a failure never leaves a partial file
// nor replaces a good one. Devices and pipes (/dev/stdout, a FIFO) are written in place.
// The float-image writers (PFM, EXR) encode to memory and finish here.
#pragma once

#include <string>
#include <vector>

namespace rts::render {

// Throws RenderError "cannot write 'PATH': why".
void write_file_atomically(const std::string& path, const std::vector<unsigned char>& bytes);

}  // namespace rts::render
