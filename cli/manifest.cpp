#include "cli/manifest.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "parser/source.hpp"
#include "render/scene/source_ref.hpp"

namespace rts::cli {

uint64_t fnv1a64(std::string_view bytes, uint64_t h) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

std::string file_checksum(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return fmt::format("fnv1a64:{:016x}", fnv1a64(bytes));
}

std::string scene_hash(const SourceManager& sources) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (const SourceFile* f : sources.files()) {
    h = fnv1a64(f->path(), h);
    h = fnv1a64(std::string_view("\0", 1), h);
    h = fnv1a64(f->text(), h);
  }
  return fmt::format("fnv1a64:{:016x}", h);
}

void append_manifest(const std::string& path, const FrameRecord& r) {
  nlohmann::ordered_json j;
  j["frame"] = r.frame;
  j["clock"] = r.clock;
  j["file"] = r.file;
  j["checksum"] = r.checksum;
  j["scene"] = r.scene;
  j["scene_hash"] = r.scene_hash;
  j["args"] = r.args;
  j["seconds"] = r.seconds;
  if (r.error_rmse >= 0)
    j["error_rmse"] = r.error_rmse;
  else
    j["error_rmse"] = nullptr;
  j["samples_per_pixel"] = r.samples_per_pixel;
  j["task"] = {{"index", r.task_index}, {"count", r.task_count}};
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) == 0) j["host"] = std::string(host);
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char when[32];
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", &utc);
  j["finished"] = std::string(when);
  // Invalid UTF-8 in a path must not throw: replace it.
  const std::string line = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";

  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0666);
  if (fd < 0) throw render::RenderError({}, fmt::format("cannot write manifest '{}': {}", path, std::strerror(errno)));
  ssize_t n;
  do {
    n = ::write(fd, line.data(), line.size());
  } while (n < 0 && errno == EINTR);
  const int err = errno;
  ::close(fd);
  if (n != static_cast<ssize_t>(line.size()))
    throw render::RenderError({}, fmt::format("cannot write manifest '{}': {}", path,
                                              n < 0 ? std::strerror(err) : "short write"));
}

}  // namespace rts::cli
