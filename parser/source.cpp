#include "parser/source.hpp"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "parser/position_space.hpp"

#include <fmt/format.h>

namespace rts {

namespace {

source_detail::PositionSpace& positions() {
  static auto* t = new source_detail::PositionSpace;  // never destroyed: locations outlive static teardown
  return *t;
}

// Fills this thread's cache with the file and line holding position p; returns the line (0
// for no place in a live file).
uint32_t cache_line(uint32_t p) {
  const uint32_t generation = source_detail::space_generation();
  auto [f, first] = positions().find(p);
  if (!f) return 0;
  const uint32_t file_hi = first + static_cast<uint32_t>(f->text().size()) + 1;
  const uint32_t line = f->line_of(p - first);
  const uint32_t line_hi = line < f->line_count() ? first + f->line_start(line + 1) : file_hi;
  source_detail::line_cache = source_detail::LineCache{first, file_hi, first + f->line_start(line), line_hi,
                                                       line, generation, f};
  return line;
}

}  // namespace

SourceFile::SourceFile(std::string path, std::string text)
    : path_(std::move(path)), text_(std::move(text)) {
  if (text_.size() > kMaxSize)
    throw SourceError(fmt::format("{}: error: file is larger than {} bytes, the most rts reads", path_, kMaxSize));
  line_starts_.push_back(0);
  // memchr finds newlines a word at a time; scenes can be tens of megabytes.
  const char* begin = text_.data();
  const char* end = begin + text_.size();
  for (const char* p = begin; p != end;) {
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    if (!nl) break;
    p = static_cast<const char*>(nl) + 1;
    line_starts_.push_back(static_cast<uint32_t>(p - begin));
  }
  first_ = positions().add(this, text_.size() + 1);
}

SourceFile::~SourceFile() {
  positions().remove(first_);
  if (source_detail::line_cache.file == this) source_detail::line_cache = {};
}

std::string_view SourceFile::line_text(uint32_t line) const {
  if (line == 0 || line > line_starts_.size()) return {};
  std::size_t begin = line_starts_[line - 1];
  std::size_t end = line < line_starts_.size() ? line_starts_[line] : text_.size();
  std::string_view s(text_.data() + begin, end - begin);
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

uint32_t SourceFile::line_start(uint32_t line) const {
  if (line == 0) return 0;
  if (line > line_starts_.size()) return static_cast<uint32_t>(text_.size());
  return line_starts_[line - 1];
}

uint32_t SourceFile::line_of(uint32_t offset) const {
  auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  return static_cast<uint32_t>(it - line_starts_.begin());  // line_starts_[0] == 0: at least 1
}

SourceLoc SourceLoc::at(const SourceFile* file, uint32_t line, uint32_t col) {
  if (!file) return {};
  if (line == 0) return whole(file);
  if (line > file->line_count()) line = file->line_count() + 1;  // past the end: the end
  const uint64_t offset = uint64_t{file->line_start(line)} + (col > 0 ? col - 1 : 0);
  return at_offset(file, static_cast<std::size_t>(offset));
}

SourceLoc SourceLoc::at_offset(const SourceFile* file, std::size_t offset) {
  if (!file) return {};
  SourceLoc l;
  l.at_ = file->first_position() + static_cast<uint32_t>(std::min(offset, file->text().size()));
  return l;
}

SourceLoc SourceLoc::whole(const SourceFile* file) {
  SourceLoc l;
  if (file) l.at_ = kWholeFile | file->first_position();
  return l;
}

const SourceFile* SourceLoc::find_file() const {
  if (at_ == 0) return nullptr;
  cache_line(at_ & ~kWholeFile);  // the file's first position is in its first line
  const source_detail::LineCache& c = source_detail::line_cache;
  const uint32_t p = at_ & ~kWholeFile;
  return p >= c.file_lo && p < c.file_hi ? c.file : nullptr;
}

uint32_t SourceLoc::resolve() const { return valid() ? cache_line(at_) : 0; }

uint32_t SourceLoc::offset() const {
  const SourceFile* f = file();
  return f && valid() ? at_ - f->first_position() : 0;
}

std::size_t find_invalid_utf8(std::string_view t) {
  const auto* s = reinterpret_cast<const unsigned char*>(t.data());
  std::size_t n = t.size(), i = 0;
  // Fast path: eight bytes at a time while they are all ASCII and none is NUL.
  constexpr uint64_t kHighBits = 0x8080808080808080ull;
  constexpr uint64_t kLowBits = 0x0101010101010101ull;
  while (i < n) {
    while (i + sizeof(uint64_t) <= n) {
      uint64_t w;
      std::memcpy(&w, s + i, sizeof w);
      bool has_zero = ((w - kLowBits) & ~w & kHighBits) != 0;
      if ((w & kHighBits) != 0 || has_zero) break;
      i += sizeof w;
    }
    if (i >= n) break;
    unsigned char c = s[i];
    if (c == 0) return i;
    if (c < 0x80) { ++i; continue; }
    std::size_t len;
    uint32_t cp;
    if ((c & 0xE0) == 0xC0) { len = 2; cp = c & 0x1F; }
    else if ((c & 0xF0) == 0xE0) { len = 3; cp = c & 0x0F; }
    else if ((c & 0xF8) == 0xF0) { len = 4; cp = c & 0x07; }
    else return i;
    if (i + len > n) return i;
    for (std::size_t k = 1; k < len; ++k) {
      if ((s[i + k] & 0xC0) != 0x80) return i;
      cp = (cp << 6) | (s[i + k] & 0x3F);
    }
    // Reject overlong encodings, surrogates and code points past U+10FFFF.
    if ((len == 2 && cp < 0x80) || (len == 3 && cp < 0x800) || (len == 4 && cp < 0x10000) ||
        (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF)
      return i;
    i += len;
  }
  return std::string_view::npos;
}

const SourceFile* SourceManager::load(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw SourceError(fmt::format("{}: error: no such file", path));
  if (fs::is_directory(status))
    throw SourceError(fmt::format("{}: error: is a directory, not a scene file", path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SourceError(fmt::format("{}: error: cannot open file for reading", path));
  // Read straight into the string (one copy, no stream buffer doubling): scene files can be
  // tens of megabytes. Files whose size is not known up front (pipes) are read in chunks.
  std::string text;
  std::error_code size_ec;
  auto size = fs::is_regular_file(status) ? fs::file_size(path, size_ec) : 0;
  if (!size_ec && size > 0) {
    text.resize(static_cast<std::size_t>(size));
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(in.gcount()));
  }
  constexpr std::size_t kChunk = 1 << 16;
  char chunk[kChunk];
  while (in.read(chunk, kChunk) || in.gcount() > 0) text.append(chunk, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw SourceError(fmt::format("{}: error: read failed", path));
  if (auto bad = find_invalid_utf8(text); bad != std::string_view::npos) {
    // Report the line and column of the offending byte so the user can find it.
    uint32_t line = 1, col = 1;
    for (std::size_t i = 0; i < bad; ++i) {
      if (text[i] == '\n') { ++line; col = 1; } else { ++col; }
    }
    const char* what = text[bad] == '\0' ? "NUL byte in source text" : "invalid UTF-8 in source text";
    throw SourceError(fmt::format("{}:{}:{}: error: {} (byte offset {})", path, line, col, what, bad));
  }
  return add(path, std::move(text));
}

const SourceFile* SourceManager::add(std::string path, std::string text) {
  files_.push_back(std::make_unique<SourceFile>(std::move(path), std::move(text)));
  return files_.back().get();
}

const SourceFile* SourceManager::find(std::string_view path) const {
  for (const auto& f : files_)
    if (f->path() == path) return f.get();
  return nullptr;
}

std::vector<const SourceFile*> SourceManager::files() const {
  std::vector<const SourceFile*> out;
  out.reserve(files_.size());
  for (const auto& f : files_) out.push_back(f.get());
  return out;
}

}  // namespace rts
