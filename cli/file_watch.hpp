// Waiting for files to change (Linux inotify), for `rts render --watch`. The folders of the
// files are watched rather than the files: editors save by writing a new file and renaming it
// over the old one, which a watch on the old file's inode would never see.
#pragma once

#include <chrono>
#include <set>
#include <string>
#include <vector>

namespace rts::cli {

class FileWatcher {
 public:
  FileWatcher();  // throws std::runtime_error when inotify is not available
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  // Adds these files to the watched set (a file that does not exist yet is watched for
  // its creation). Returns how many files are watched in all.
  std::size_t watch(const std::vector<std::string>& files);
  // Blocks until a watched file is written, created, renamed into place or deleted, then
  // waits until `settle` passes with no further change (an editor's save is several events).
  void wait_for_change(std::chrono::milliseconds settle);
  // Whether a watched file changed since the last wait (consumes the events; non-blocking).
  bool changed();

 private:
  bool read_events(int timeout_ms);  // true when an event concerned a watched file

  int fd_ = -1;
  std::set<std::string> files_;             // absolute, normalised paths
  std::vector<std::pair<int, std::string>> dirs_;  // watch descriptor, folder
};

}  // namespace rts::cli
