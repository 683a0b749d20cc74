#include "render/scene/resource_limits.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

namespace rts::render {

namespace fs = std::filesystem;

std::size_t resident_bytes() {
  // /proc/self/statm: total program size, then resident pages.
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0;
  unsigned long size = 0, resident = 0;
  int n = std::fscanf(f, "%lu %lu", &size, &resident);
  std::fclose(f);
  if (n != 2) return 0;
  return static_cast<std::size_t>(resident) * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

std::size_t default_max_memory() {
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page <= 0) return std::size_t(4) << 30;  // unknown: 4 GiB
  return static_cast<std::size_t>(pages) / 2 * static_cast<std::size_t>(page);
}

std::string size_in_words(std::size_t bytes) {
  constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB"};
  if (bytes < 1024) return fmt::format("{} bytes", bytes);
  double v = static_cast<double>(bytes) / 1024;
  int u = 0;
  while (v >= 1024 && u < 4) {
    v /= 1024;
    ++u;
  }
  return v < 10 && v != static_cast<double>(static_cast<long>(v)) ? fmt::format("{:.1f} {}", v, kUnits[u])
                                                                   : fmt::format("{:.0f} {}", v, kUnits[u]);
}

bool memory_fits(std::size_t max_bytes, std::size_t extra) {
  if (max_bytes == 0) return true;
  if (extra > max_bytes) return false;
  return resident_bytes() <= max_bytes - extra;
}

namespace {

std::string canonical_or_absolute(const std::string& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(fs::path(path), ec), ec);
  if (ec) p = fs::absolute(fs::path(path), ec).lexically_normal();
  std::string s = p.string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

}  // namespace

ReadPolicy::ReadPolicy(const std::vector<std::string>& folders) : restricted_(true) {
  for (const std::string& f : folders) {
    std::string root = canonical_or_absolute(f.empty() ? "." : f);
    if (root == "/") {
      restricted_ = false;
      roots_.clear();
      return;
    }
    roots_.push_back(root);
  }
}

bool ReadPolicy::allows(const std::string& path) const {
  if (!restricted_) return true;
  std::string p = canonical_or_absolute(path);
  for (const std::string& root : roots_)
    if (p == root || (p.size() > root.size() && p.compare(0, root.size(), root) == 0 && p[root.size()] == '/'))
      return true;
  return false;
}

std::string ReadPolicy::refusal(const std::string& shown, const std::string& path) const {
  std::string dir = fs::path(canonical_or_absolute(path)).parent_path().string();
  return fmt::format(
      "reading '{}' is not allowed: it is outside the scene's folder, the -I folders and the current folder "
      "(allow it with --allow-read {})",
      shown, dir.empty() ? "/" : dir);
}

std::string non_regular_kind(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return {};
  if (S_ISDIR(st.st_mode)) return "a directory";
  if (S_ISFIFO(st.st_mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
  if (S_ISSOCK(st.st_mode)) return "a socket";
  return "not a regular file";
}

}  // namespace rts::render
