// Source files and locations. Every AST node and every diagnostic points into a SourceFile
// through a SourceLoc; the SourceManager owns the files for the life of the program, so a
// SourceLoc (a file number and an offset) is cheap to copy and never dangles.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rts {

class SourceFile;

namespace source_detail {
// The line last resolved on this thread: the evaluator resolves a location for each object
// it places (the scene's SourceRef), diagnostics resolve runs of nearby ones, so most
// lookups are a compare here instead of a table lookup and a binary search. File numbers
// are never reused, so an entry cannot name another file's line.
struct LineCache {
  uint32_t file_id = 0;
  uint32_t begin = 0, end = 0;  // [begin, end) is line `line` of `file`
  uint32_t line = 0;
  const SourceFile* file = nullptr;
};
inline thread_local LineCache line_cache;
}  // namespace source_detail

// A place in a source file: the file's number and a byte offset into its text, 8 bytes. Every
// AST node carries one, so its size is the parser's memory (issue 24: a 16-byte pointer, line
// and column per node was a tenth of a large scene's peak). Line and column are computed when
// asked, from the file's line table (diagnostics, the language server, the scene's
// SourceRefs); passing a location around costs nothing. A default SourceLoc is "no
// location"; one made with `SourceLoc::whole(file)` names a file but no place in it.
class SourceLoc {
 public:
  SourceLoc() = default;
  // Line and column are 1-based, the column in bytes; line 0 names the whole file.
  static SourceLoc at(const SourceFile* file, uint32_t line, uint32_t col);
  static SourceLoc at_offset(const SourceFile* file, std::size_t offset);
  static SourceLoc whole(const SourceFile* file);

  // The file, or null for no location (or a file that no longer exists).
  const SourceFile* file() const {
    const source_detail::LineCache& c = source_detail::line_cache;
    return file_id_ != 0 && c.file_id == file_id_ ? c.file : find_file();
  }
  // 0 when there is no place in the file.
  uint32_t line() const { return cached() ? source_detail::line_cache.line : resolve(); }
  uint32_t col() const {
    if (!cached() && resolve() == 0) return 0;
    return offset_ - source_detail::line_cache.begin + 1;  // resolve() left the line cached
  }
  uint32_t offset() const { return offset_; }
  // Names a place in a file (not only the file).
  bool valid() const { return file_id_ != 0 && offset_ != kWholeFile; }
  // A copy `bytes` further on (back, when negative) in the same file: a place inside a token.
  SourceLoc advanced(int32_t bytes) const {
    SourceLoc l = *this;
    if (valid()) l.offset_ = static_cast<uint32_t>(static_cast<int64_t>(offset_) + bytes);
    return l;
  }
  friend bool operator==(const SourceLoc& a, const SourceLoc& b) {
    return a.file_id_ == b.file_id_ && a.offset_ == b.offset_;
  }
  friend bool operator!=(const SourceLoc& a, const SourceLoc& b) { return !(a == b); }

 private:
  static constexpr uint32_t kWholeFile = 0xFFFFFFFFu;
  bool cached() const {
    const source_detail::LineCache& c = source_detail::line_cache;
    return valid() && c.file_id == file_id_ && offset_ >= c.begin && offset_ < c.end;
  }
  const SourceFile* find_file() const;
  uint32_t resolve() const;  // the line, after caching it; 0 when it cannot
  uint32_t file_id_ = 0;  // SourceFile::id(); 0 for none
  uint32_t offset_ = kWholeFile;
};

class SourceFile {
 public:
  // The largest text a location can point into (offsets are 32 bits, one value reserved).
  static constexpr std::size_t kMaxSize = 0xFFFFFFFEu;

  // Throws SourceError when `text` is larger than kMaxSize.
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
  // This file's number in the process-wide table SourceLoc resolves through; never reused.
  uint32_t id() const { return id_; }

 private:
  std::string path_;
  std::string text_;
  std::vector<uint32_t> line_starts_;  // byte offset of each line's first character
  uint32_t id_;
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
