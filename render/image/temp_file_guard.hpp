// Removes a temporary output file when the process is interrupted (SIGINT, SIGTERM, SIGHUP)
// while the file exists, so that Ctrl-C during an atomic write leaves neither a broken
// output nor a stray OUT.png.tmp-* beside it. One guard at a time (writes are sequential).
#pragma once

#include <string>

namespace rts::render {

class TempFileGuard {
 public:
  // Arms the guard for `path` (before the file is created) and installs the handlers.
  explicit TempFileGuard(const std::string& path);
  // Disarms and restores the previous signal handlers (after rename or unlink).
  ~TempFileGuard();
  TempFileGuard(const TempFileGuard&) = delete;
  TempFileGuard& operator=(const TempFileGuard&) = delete;
};

}  // namespace rts::render
