// Source files and locations. Every AST node and every diagnostic points into a SourceFile
// through a SourceLoc; the SourceManager owns the files for the life of the program, so a
// SourceLoc (a position in the space the loaded files share) is cheap to copy.
#pragma once

#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rts {

class SourceFile;

namespace source_detail {
// The file and line last resolved on this thread, in the process-wide position space (see
// SourceLoc): the evaluator resolves a location for each object it places (the scene's
// SourceRef) and diagnostics resolve runs of nearby ones, so most lookups are two compares
// here instead of a locked table lookup and a binary search. `generation` is the position
// space's at the time: it changes when a freed file's positions are given to another file.
struct LineCache {
  uint32_t file_lo = 0, file_hi = 0;  // [file_lo, file_hi) are `file`'s positions
  uint32_t line_lo = 0, line_hi = 0;  // [line_lo, line_hi) are line `line`'s
  uint32_t line = 0;
  uint32_t generation = 0;
  const SourceFile* file = nullptr;
};
inline thread_local LineCache line_cache;
inline std::atomic<uint32_t> generation{1};
inline uint32_t space_generation() { return generation.load(std::memory_order_acquire); }
}  // namespace source_detail

// A place in a source file, 4 bytes: a position in one space that all the process's loaded
// files share (clang's SourceLocation; each file holds a run of positions, one per byte and
// one for its end). Every AST node carries one, so its size is the parser's memory (issue 24:
// a 16-byte pointer, line and column per node was a tenth of a large scene's peak). File,
// line and column are computed when asked (diagnostics, the language server, the scene's
// SourceRefs), through the per-thread cache above; passing a location around costs nothing.
// A default SourceLoc is "no location"; `SourceLoc::whole(file)` names a file but no place
// in it (the top bit marks it). Positions of a file that is gone are not given to another
// file until the space (2^31 positions) has run out, so until then such a location resolves
// to nothing.
class SourceLoc {
 public:
  SourceLoc() = default;
  // Line and column are 1-based, the column in bytes; line 0 names the whole file.
  static SourceLoc at(const SourceFile* file, uint32_t line, uint32_t col);
  static SourceLoc at_offset(const SourceFile* file, std::size_t offset);
  static SourceLoc whole(const SourceFile* file);

  // The file, or null for no location (or a file that no longer exists).
  const SourceFile* file() const {
    if (at_ == 0) return nullptr;
    const source_detail::LineCache& c = source_detail::line_cache;
    const uint32_t p = at_ & ~kWholeFile;
    if (p >= c.file_lo && p < c.file_hi && c.generation == source_detail::space_generation()) return c.file;
    return find_file();
  }
  // 0 when there is no place in the file.
  uint32_t line() const { return cached() ? source_detail::line_cache.line : resolve(); }
  uint32_t col() const {
    if (!cached() && resolve() == 0) return 0;
    return at_ - source_detail::line_cache.line_lo + 1;  // resolve() left the line cached
  }
  // Byte offset into the file's text (0 when there is no place in a file).
  uint32_t offset() const;
  // Names a place in a file (not only the file).
  bool valid() const { return at_ != 0 && (at_ & kWholeFile) == 0; }
  // A copy `bytes` further on (back, when negative) in the same file: a place inside a token.
  SourceLoc advanced(int32_t bytes) const {
    SourceLoc l = *this;
    if (valid()) l.at_ = static_cast<uint32_t>(static_cast<int64_t>(at_) + bytes);
    return l;
  }
  // How many bytes `later` lies after this place, or -1 when either is not a place (for a node
  // that keeps a second place as a short distance from its first; both in one file).
  int64_t bytes_to(SourceLoc later) const {
    return valid() && later.valid() ? static_cast<int64_t>(later.at_) - static_cast<int64_t>(at_) : -1;
  }
  friend bool operator==(const SourceLoc& a, const SourceLoc& b) { return a.at_ == b.at_; }
  friend bool operator!=(const SourceLoc& a, const SourceLoc& b) { return a.at_ != b.at_; }

 private:
  static constexpr uint32_t kWholeFile = 0x80000000u;
  bool cached() const {
    const source_detail::LineCache& c = source_detail::line_cache;
    return valid() && at_ >= c.line_lo && at_ < c.line_hi && c.generation == source_detail::space_generation();
  }
  const SourceFile* find_file() const;
  uint32_t resolve() const;  // the line, after caching it; 0 when it cannot
  uint32_t at_ = 0;  // the position; 0 for none; kWholeFile | the file's first position for a whole file
};

class SourceFile {
 public:
  // The largest text a location can point into: all loaded files share 2^31 positions.
  static constexpr std::size_t kMaxSize = 0x7FFFFFF0u;

  // Throws SourceError when `text` is larger than kMaxSize, or when the files loaded at once
  // would hold more than 2^31 bytes.
  SourceFile(std::string path, std::string text);
  ~SourceFile();
  SourceFile(const SourceFile&) = delete;
  SourceFile& operator=(const SourceFile&) = delete;

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }
  // The text of 1-based line `line`, without its line terminator; empty when out of range.
  std::string_view line_text(uint32_t line) const;
  uint32_t line_count() const { return static_cast<uint32_t>(line_starts_.size()); }
  // Byte offset of the first character of 1-based line `line` (the text's size past the end).
  uint32_t line_start(uint32_t line) const;
  // The 1-based line holding byte `offset` (the last line for offsets at or past the end).
  uint32_t line_of(uint32_t offset) const;
  // This file's first position in the space SourceLoc resolves through (its text's byte k
  // is position first_position() + k; its end, one past).
  uint32_t first_position() const { return first_; }

 private:
  std::string path_;
  std::string text_;
  std::vector<uint32_t> line_starts_;  // byte offset of each line's first character
  uint32_t first_;
};

class SourceManager {
 public:
  // Reads a file from disk. Throws SourceError (with a message fit for the user) when the
  // path is missing, a directory, unreadable, or not valid UTF-8 / contains NUL bytes.
  const SourceFile* load(const std::string& path);
  // Registers in-memory text (tests, -D defines, stdin).
  const SourceFile* add(std::string path, std::string text);
  // The file loaded or added under exactly this path, or null.
  const SourceFile* find(std::string_view path) const;
  // Every file loaded or added, in load order (the main file first when loaded first).
  std::vector<const SourceFile*> files() const;

 private:
  std::deque<std::unique_ptr<SourceFile>> files_;
};

struct SourceError : std::exception {
  std::string message;
  explicit SourceError(std::string m) : message(std::move(m)) {}
  const char* what() const noexcept override { return message.c_str(); }
};

// Checks text for NUL bytes and invalid UTF-8; returns the byte offset of the first bad
// byte, or npos when the text is clean.
std::size_t find_invalid_utf8(std::string_view text);

}  // namespace rts
