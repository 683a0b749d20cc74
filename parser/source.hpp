// Source files and locations. Every AST node and every diagnostic points into a SourceFile
// through a SourceLoc; the SourceManager owns the files for the life of the program, so a
// SourceLoc (a pointer and two integers) is cheap to copy and never dangles.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rts {

class SourceFile {
 public:
  SourceFile(std::string path, std::string text);

  const std::string& path() const { return path_; }
  const std::string& text() const { return text_; }
  // The text of 1-based line `line`, without its line terminator; empty when out of range.
  std::string_view line_text(uint32_t line) const;
  uint32_t line_count() const { return static_cast<uint32_t>(line_starts_.size()); }

 private:
  std::string path_;
  std::string text_;
  std::vector<uint32_t> line_starts_;  // byte offset of each line's first character
};

// 1-based line and column; the column counts bytes, so a caret is placed by copying the
// line's own bytes (tabs included) up to it. file == nullptr means "no location".
struct SourceLoc {
  const SourceFile* file = nullptr;
  uint32_t line = 0;
  uint32_t col = 0;

  bool valid() const { return file != nullptr && line > 0; }
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
