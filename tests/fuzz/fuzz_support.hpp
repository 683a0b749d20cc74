// Shared by the libFuzzer harnesses: turning fuzz bytes into a scene file or a file on disk,
// and the one rule every harness checks: an input either succeeds or fails with one of rts's
// own located errors. Anything else escaping (std::bad_alloc, std::logic_error...) is a bug and
// is left to propagate, so libFuzzer reports it as a crash with the input that caused it.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>

#include "parser/diagnostics.hpp"
#include "parser/source.hpp"
#include "runtime/evaluator.hpp"

namespace rts::fuzz {

// Discards everything (warnings are part of normal operation, not findings).
class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return c; }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// The evaluation options of the harnesses: the defaults of `rts check`, except the memory
// budget, which `rts` sets from the machine's RAM and EvalOptions leaves unlimited: it is set
// below libFuzzer's -rss_limit_mb (scripts/fuzz: 2048), so a scene that the budget allows is
// never reported as an out-of-memory finding, and one that it refuses ends as a located error.
// The budget counts the scene's own memory only. Under ASan the process also holds the shadow
// (an eighth of what the scene touches), the quarantine of freed blocks (256 MB) and the
// corpus. With a 1.5 GB budget, fuzz_eval's peak reached 2,024 MB of the 2,048 (2026-11-23,
// one hour). With 1 GB there is room for all three.
//
// RTS_FUZZ_MAX_STEPS lowers the step budget for the suite's replays only (CTest sets it), so a
// runaway finding that the default budget ends after 100 million steps (20 s in a release
// build, minutes under the sanitizers) ends within a second there. Fuzzing never sets it.
inline rts::EvalOptions eval_options() {
  rts::EvalOptions options;
  options.limits.max_memory = std::size_t(1024) << 20;
  if (const char* steps = std::getenv("RTS_FUZZ_MAX_STEPS")) options.limits.max_steps = std::strtoull(steps, nullptr, 10);
  return options;
}

inline std::ostream& null_stream() {
  static NullBuffer buffer;
  static std::ostream stream(&buffer);
  return stream;
}

// The scene text for `data`, or false when SourceManager::load would refuse the bytes
// (NUL bytes, invalid UTF-8): the parser never sees such text from a real file.
inline bool scene_text(const uint8_t* data, std::size_t size, std::string& text) {
  text.assign(reinterpret_cast<const char*>(data), size);
  return find_invalid_utf8(text) == std::string_view::npos;
}

// A private directory for the files harnesses write (removed at exit), so parallel fuzzers
// never share a file and a scene's relative paths resolve inside it.
inline const std::filesystem::path& work_dir() {
  static const std::filesystem::path dir = [] {
    std::filesystem::path d = std::filesystem::temp_directory_path() /
                              ("rts-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] { std::error_code ec; std::filesystem::remove_all(work_dir(), ec); });
    return d;
  }();
  return dir;
}

// Writes the fuzz bytes to work_dir()/name and returns the path.
inline std::string write_input(const std::string& name, const uint8_t* data, std::size_t size) {
  std::string path = (work_dir() / name).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) std::abort();  // the harness itself failed, not rts
  return path;
}

// An error's location must point into the file it names (a caret past the text is a bug).
inline void check_location(const SourceLoc& loc) {
  if (!loc.valid()) return;
  if (loc.line() > loc.file()->line_count() || loc.col() < 1 ||
      loc.col() > loc.file()->line_text(loc.line()).size() + 1)
    std::abort();
}

inline void check_error(const LanguageError& e) {
  check_location(e.diag.loc);
  for (const Note& n : e.diag.notes) check_location(n.loc);
  if (e.diag.message.empty()) std::abort();
}

}  // namespace rts::fuzz
