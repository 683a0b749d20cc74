// The frame manifest: one JSON object per rendered frame, appended as one line (JSON Lines)
// to a file beside the frames, so that a scheduler's tasks and a rerun after a crash can all
// append to it. Each record says what made the frame (scene hash, command line), what it cost
// (seconds) and how good it is (error estimate), and the image's checksum.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rts {
class SourceManager;
}

namespace rts::cli {

// FNV-1a, 64 bits: a checksum to compare frames and scenes, not a cryptographic hash.
uint64_t fnv1a64(std::string_view bytes, uint64_t h = 0xcbf29ce484222325ull);
// "fnv1a64:<16 hex digits>" of a file's bytes, or an empty string when it cannot be read.
std::string file_checksum(const std::string& path);
// Of every source file the scene read (path and text, in load order): another include or
// another -D gives another hash.
std::string scene_hash(const SourceManager& sources);

struct FrameRecord {
  int64_t frame = 0;
  double clock = 0.0;
  std::string file, checksum, scene, scene_hash;
  std::vector<std::string> args;  // the command line (without the program name)
  double seconds = 0.0;           // evaluation + render + write of this frame
  double error_rmse = -1.0;       // the render's error estimate; < 0: not known (1 spp)
  double samples_per_pixel = 0.0;
  int64_t task_index = 0, task_count = 1;
};

// Appends `r` as one line with a single write on a file opened O_APPEND, so records of tasks
// that share the file do not interleave (on a local file system; see docs/scale-out.md).
// Throws render::RenderError when the file cannot be written.
void append_manifest(const std::string& path, const FrameRecord& r);

}  // namespace rts::cli
