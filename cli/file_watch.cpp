#include "cli/file_watch.hpp"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace rts::cli {
namespace {

namespace fs = std::filesystem;

// The events that mean a file's contents may differ: written and closed, moved or created
// under its name (an editor's atomic save), deleted (then re-created: the next event).
constexpr uint32_t kEvents = IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_MOVED_FROM;

std::string absolute_path(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::absolute(path, ec);
  if (ec) return path;
  return p.lexically_normal().string();
}

}  // namespace

FileWatcher::FileWatcher() : fd_(inotify_init1(IN_CLOEXEC | IN_NONBLOCK)) {
  if (fd_ < 0) throw std::runtime_error(std::string("cannot watch files: inotify: ") + std::strerror(errno));
}

FileWatcher::~FileWatcher() {
  if (fd_ >= 0) close(fd_);
}

std::size_t FileWatcher::watch(const std::vector<std::string>& files) {
  for (const std::string& f : files) {
    if (f.empty()) continue;
    std::string path = absolute_path(f);
    if (!files_.insert(path).second) continue;
    std::string dir = fs::path(path).parent_path().string();
    bool known = false;
    for (const auto& d : dirs_) known = known || d.second == dir;
    if (known) continue;
    int wd = inotify_add_watch(fd_, dir.c_str(), kEvents);
    if (wd >= 0) dirs_.emplace_back(wd, dir);
  }
  return files_.size();
}

bool FileWatcher::read_events(int timeout_ms) {
  pollfd p{fd_, POLLIN, 0};
  int n = poll(&p, 1, timeout_ms);
  if (n <= 0) return false;  // timed out (or interrupted: treated as no change)
  bool hit = false;
  alignas(inotify_event) char buf[64 * 1024];
  for (;;) {
    ssize_t len = read(fd_, buf, sizeof buf);
    if (len <= 0) break;
    for (char* at = buf; at < buf + len;) {
      const auto* ev = reinterpret_cast<const inotify_event*>(at);
      if (ev->len > 0) {
        for (const auto& d : dirs_)
          if (d.first == ev->wd && files_.count(d.second + "/" + ev->name)) hit = true;
      }
      at += sizeof(inotify_event) + ev->len;
    }
  }
  return hit;
}

void FileWatcher::wait_for_change(std::chrono::milliseconds settle) {
  while (!read_events(-1)) {
  }
  while (read_events(static_cast<int>(settle.count()))) {
  }
}

bool FileWatcher::changed() { return read_events(0); }

}  // namespace rts::cli
