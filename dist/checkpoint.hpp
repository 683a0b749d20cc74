// The checkpoint journal of a distributed still (--checkpoint DIR): every finished tile is
// appended as a record (tile, size, bytes, checksum), so that after a crash, a killed rank or
// the job's time limit the same command resumes with the tiles already rendered. The header
// carries a key (the scene's hash and the options that change pixels): a journal made for
// another scene or other options is refused, never mixed in. A torn last record (the process
// died while writing it) fails its checksum and is cut off.
#pragma once

#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace rts::dist {

class Checkpoint {
 public:
  // Opens (or creates) DIR/rts-checkpoint.journal for `key`. Throws render::RenderError when
  // the folder cannot be made or written, or when the journal there has another key.
  Checkpoint(const std::string& dir, const std::string& key);
  ~Checkpoint();
  Checkpoint(const Checkpoint&) = delete;
  Checkpoint& operator=(const Checkpoint&) = delete;

  // The tiles read back from the journal (tile → payload).
  const std::map<int, std::vector<unsigned char>>& finished() const { return finished_; }
  std::size_t torn_bytes() const { return torn_bytes_; }  // cut off the end when opened
  // Appends one tile; flushed to the disk at most every half second (and at close).
  void append(int tile, const std::vector<unsigned char>& payload);
  void sync();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::map<int, std::vector<unsigned char>> finished_;
  std::size_t torn_bytes_ = 0;
  double last_sync_ = 0;
};

}  // namespace rts::dist
