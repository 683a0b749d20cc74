// Files that cannot be scene text are refused by the loader with a clear message.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "parser_test_support.hpp"

namespace fs = std::filesystem;

namespace {
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("rts_parser_test_" + std::to_string(::getpid()));
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  std::string write(const std::string& name, const std::string& bytes) const {
    fs::path p = path / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
};

std::string load_error(const std::string& path) {
  rts::SourceManager sources;
  try {
    sources.load(path);
  } catch (const rts::SourceError& e) {
    return e.message;
  }
  return "";
}
}  // namespace

TEST_CASE("missing files and directories", "[loading]") {
  TempDir dir;
  std::string missing = (dir.path / "nope.rts").string();
  CHECK(load_error(missing) == missing + ": error: no such file");
  CHECK(load_error(dir.path.string()) == dir.path.string() + ": error: is a directory, not a scene file");
}

TEST_CASE("NUL bytes and invalid UTF-8 are located", "[loading]") {
  TempDir dir;
  std::string nul = dir.write("nul.rts", std::string("let a = 1\nlet \0b = 2\n", 22));
  CHECK(load_error(nul) == nul + ":2:5: error: NUL byte in source text (byte offset 14)");
  std::string bad = dir.write("bad.rts", "let s = \"\xff\"\n");
  CHECK(load_error(bad) == bad + ":1:10: error: invalid UTF-8 in source text (byte offset 9)");
  std::string overlong = dir.write("overlong.rts", "// \xc0\xaf\n");
  CHECK(load_error(overlong).find("invalid UTF-8") != std::string::npos);
  // A bad byte after a long ASCII run (the loader checks eight bytes at a time).
  std::string late = dir.write("late.rts", std::string(1000, ' ') + "\xe2\x82");
  CHECK(load_error(late).find("byte offset 1000") != std::string::npos);
}

TEST_CASE("valid files load intact, empty ones too", "[loading]") {
  TempDir dir;
  std::string text = "let s = \"caf\xc3\xa9 \xf0\x9f\x98\x80\"\r\n// end";
  std::string ok = dir.write("ok.rts", text);
  rts::SourceManager sources;
  const rts::SourceFile* f = sources.load(ok);
  CHECK(f->text() == text);
  CHECK(f->line_count() == 2);
  CHECK(f->line_text(1) == "let s = \"caf\xc3\xa9 \xf0\x9f\x98\x80\"");
  CHECK(f->line_text(2) == "// end");
  std::string empty = dir.write("empty.rts", "");
  const rts::SourceFile* e = sources.load(empty);
  CHECK(e->text().empty());
  CHECK(rts::parse(*e).stmts().empty());
}
