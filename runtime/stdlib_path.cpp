#include "runtime/stdlib_path.hpp"

#include <cstdlib>
#include <system_error>

namespace fs = std::filesystem;

namespace rts::runtime {

namespace {

constexpr const char* kPrefix = "std/";

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

// `inner` is `outer` or below it (both canonical).
bool is_within(const fs::path& inner, const fs::path& outer) {
  auto o = outer.begin();
  for (auto i = inner.begin(); o != outer.end(); ++i, ++o)
    if (i == inner.end() || *i != *o) return false;
  return true;
}

}  // namespace

std::string find_standard_library() {
  if (const char* env = std::getenv("RTS_STDLIB"); env && *env) return env;
  std::error_code ec;
  fs::path exe = fs::canonical("/proc/self/exe", ec);
  if (!ec) {
    fs::path installed = exe.parent_path().parent_path() / "share" / "rts" / "stdlib";
    if (is_dir(installed)) return installed.string();
#if defined(RTS_BUILD_DIR) && defined(RTS_STDLIB_SOURCE_DIR)
    fs::path build = fs::weakly_canonical(RTS_BUILD_DIR, ec);
    if (!ec && is_within(exe, build) && is_dir(RTS_STDLIB_SOURCE_DIR)) return RTS_STDLIB_SOURCE_DIR;
#endif
  }
#ifdef RTS_STDLIB_INSTALL_DIR
  if (is_dir(RTS_STDLIB_INSTALL_DIR)) return RTS_STDLIB_INSTALL_DIR;
#endif
  return "";
}

bool names_standard_library(const std::string& name) { return name.rfind(kPrefix, 0) == 0; }

std::vector<fs::path> standard_library_candidates(const std::string& dir, const std::string& name) {
  std::vector<fs::path> out;
  if (dir.empty()) return out;
  fs::path rel(names_standard_library(name) ? name.substr(4) : name);
  // Only a plain file name: the library is flat, and "../x" must not climb out of it.
  if (rel.empty() || rel.has_parent_path() || rel.is_absolute() || rel == "." || rel == "..") return out;
  out.push_back(fs::path(dir) / rel);
  if (rel.extension() == ".inc") out.push_back(fs::path(dir) / fs::path(rel).replace_extension(".rts"));
  return out;
}

}  // namespace rts::runtime
