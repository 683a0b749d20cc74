#include "render/image/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include <fmt/format.h>

#include "render/image/temp_file_guard.hpp"
#include "render/scene/source_ref.hpp"

namespace rts::render {
namespace {

[[noreturn]] void fail_write(const std::string& path, const std::string& why) {
  throw RenderError({}, fmt::format("cannot write '{}': {}", path, why));
}

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Writes all of `bytes` to fd; false (errno set) on failure. Retries short writes and EINTR.
bool write_all(int fd, const std::vector<unsigned char>& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

void write_file_atomically(const std::string& path, const std::vector<unsigned char>& bytes) {
  struct stat target {};
  if (::stat(path.c_str(), &target) == 0 && !S_ISREG(target.st_mode)) {
    if (S_ISDIR(target.st_mode)) fail_write(path, "it is a directory");
    if (!S_ISCHR(target.st_mode) && !S_ISFIFO(target.st_mode)) fail_write(path, "not a regular file, device or pipe");
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) fail_write(path, std::strerror(errno));
    const bool ok = write_all(fd, bytes);
    const int err = errno;
    ::close(fd);
    if (!ok) fail_write(path, std::strerror(err));
    return;
  }

  static thread_local std::mt19937_64 rng{std::random_device{}()};
  const std::string temp = fmt::format("{}.tmp-{}-{:016x}", path, static_cast<long>(getpid()), rng());
  TempFileGuard guard(temp);  // Ctrl-C or kill while writing removes the temp file
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int err = errno;
    const std::string dir = directory_of(path);
    if (err == ENOENT) fail_write(path, fmt::format("directory '{}' does not exist", dir));
    if (err == EACCES || err == EROFS || err == EPERM)
      fail_write(path, fmt::format("directory '{}' is not writable ({})", dir, std::strerror(err)));
    if (err == ENOTDIR) fail_write(path, fmt::format("'{}' is not a directory", dir));
    fail_write(path, std::strerror(err));
  }
  // fsync before rename: a crash afterwards must not leave an empty file under the name.
  bool ok = write_all(fd, bytes) && ::fsync(fd) == 0;
  int err = errno;
  if (::close(fd) != 0 && ok) ok = false, err = errno;
  if (!ok) {
    ::unlink(temp.c_str());
    fail_write(path, std::strerror(err));
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    err = errno;
    ::unlink(temp.c_str());
    fail_write(path, std::strerror(err));
  }
}

}  // namespace rts::render
