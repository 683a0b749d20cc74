// Limits on what a scene may make the process do: how much memory it may hold and which
// files it may read. Shared by the evaluator (lists, strings, includes) and the builder and
// renderer (meshes, image textures, the image), so one flag governs every place.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rts::render {

// Bytes of physical memory the process holds now (resident set size); 0 when unknown.
std::size_t resident_bytes();

// The default for --max-memory: half of the machine's physical memory, so that a runaway
// scene ends with an error before the system starts swapping or killing processes (and
// leaves room for the rest of the machine).
std::size_t default_max_memory();

// "1.5 GiB", "512 MiB", "12 KiB", "100 bytes": sizes in messages.
std::string size_in_words(std::size_t bytes);

// True when the process may hold `extra` more bytes without passing `max_bytes` (0: no limit).
// Reads the resident size, so call it where something big is about to be made, not per value.
bool memory_fits(std::size_t max_bytes, std::size_t extra);

// Which files a scene may read (POV-Ray's read restrictions): files under one of the allowed
// folders. The scene's own folder, the -I folders and the current folder are allowed by
// default; --allow-read adds folders ("/" allows everything).
class ReadPolicy {
 public:
  ReadPolicy() = default;  // allows everything (library use, unit tests)
  // Restricts reading to the given folders (made absolute, symlinks resolved).
  explicit ReadPolicy(const std::vector<std::string>& folders);

  bool unrestricted() const { return !restricted_; }
  // Whether `path` (as the scene resolved it) lies under an allowed folder, after
  // resolving `..` and symbolic links.
  bool allows(const std::string& path) const;
  // "reading '/etc/passwd' is not allowed: it is outside the scene's folder, ... (allow it
  // with --allow-read /etc)"; `shown` is the name as the scene wrote it.
  std::string refusal(const std::string& shown, const std::string& path) const;

 private:
  bool restricted_ = false;
  std::vector<std::string> roots_;  // canonical, each ending without a trailing '/'
};

// What a path that is not a regular file is: "a directory", "a FIFO (named pipe)", "a device",
// "a socket"; empty for a regular file or a path that does not exist.
std::string non_regular_kind(const std::string& path);

}  // namespace rts::render
