// Writing a whole file atomically from bytes in memory: to a temporary file in the target's
// directory, fsync'ed, then renamed over the target, so a failure never leaves a partial file
// nor replaces a good one; Ctrl-C, SIGTERM or SIGHUP while it is written removes the temporary
// file (TempFileGuard). Devices and pipes (/dev/stdout, a FIFO) are written in place. Every
// image writer (PNG, PFM, EXR) encodes to memory and finishes here.
#pragma once

#include <string>
#include <vector>

namespace rts::render {

// Throws RenderError "cannot write 'PATH': why".
void write_file_atomically(const std::string& path, const std::vector<unsigned char>& bytes);

}  // namespace rts::render
