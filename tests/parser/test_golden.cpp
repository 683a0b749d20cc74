// Golden files. tests/golden/parse/NAME.rts parses to exactly NAME.ast beside it (printed
// with locations when the file's first line is `// golden: locations`).
// tests/golden/parse-errors/NAME.rts fails with exactly the diagnostic its comments name:
//   // error: LINE:COL: error: MESSAGE     (the first line, without the file path)
//   // note: LINE:COL: note: MESSAGE       (each note, in order; none means no notes)
// The conventions are documented in tests/README.md.
#include <catch2/catch.hpp>

#include <sstream>

#include "golden_runner.hpp"
#include "parser_test_support.hpp"

namespace fs = std::filesystem;
using namespace rts::testing;

namespace {

const fs::path kGoldenDir = fs::path(RTS_SOURCE_DIR) / "tests" / "golden";
constexpr std::size_t kMinParseGoldens = 30;
constexpr std::size_t kMinErrorGoldens = 15;

std::string print(const rts::ast::Program& program, bool locations) {
  std::ostringstream out;
  rts::print_ast(out, program, locations);
  return out.str();
}

// The comment lines starting with `// <tag>: `, in order, with the prefix removed.
std::vector<std::string> tagged_comments(const std::string& text, const std::string& tag) {
  std::vector<std::string> out;
  std::istringstream in(text);
  const std::string prefix = "// " + tag + ": ";
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    auto at = line.find(prefix);
    if (at != std::string::npos) out.push_back(line.substr(at + prefix.size()));
  }
  return out;
}

// "path:3:7: error: ..." -> "3:7: error: ..."
std::string without_path(const std::string& line, const std::string& path) {
  return line.rfind(path + ":", 0) == 0 ? line.substr(path.size() + 1) : line;
}

}  // namespace

TEST_CASE("every parse golden prints exactly its .ast", "[golden]") {
  auto inputs = files_with_extension(kGoldenDir / "parse", ".rts");
  CHECK(inputs.size() >= kMinParseGoldens);
  for (const fs::path& input : inputs) {
    SECTION(input.filename().string()) {
      rts::SourceManager sources;
      const rts::SourceFile* file = sources.load(input.string());
      bool locations = file->line_text(1) == "// golden: locations";
      std::string actual;
      try {
        actual = print(rts::parse(*file), locations);
      } catch (const rts::LanguageError& e) {
        FAIL("unexpected syntax error:\n" << rts::format_diagnostic(e.diag));
      }
      fs::path golden = fs::path(input).replace_extension(".ast");
      if (updating_golden()) {
        write_file(golden, actual);
        continue;
      }
      REQUIRE(fs::exists(golden));
      std::string expected = read_file(golden);
      INFO("golden file: " << golden.string() << "\n" << line_diff(expected, actual)
                           << "(regenerate on purpose with scripts/update-golden-parse)");
      CHECK(expected == actual);
    }
  }
}

TEST_CASE("every parse-error golden fails with exactly the diagnostic it names", "[golden]") {
  auto inputs = files_with_extension(kGoldenDir / "parse-errors", ".rts");
  CHECK(inputs.size() >= kMinErrorGoldens);
  for (const fs::path& input : inputs) {
    SECTION(input.filename().string()) {
      rts::SourceManager sources;
      const rts::SourceFile* file = sources.load(input.string());
      auto expected_error = tagged_comments(file->text(), "error");
      auto expected_notes = tagged_comments(file->text(), "note");
      REQUIRE(expected_error.size() == 1);
      std::string diagnostic;
      try {
        rts::parse(*file);
      } catch (const rts::LanguageError& e) {
        diagnostic = rts::format_diagnostic(e.diag);
      }
      INFO("full diagnostic:\n" << diagnostic);
      REQUIRE_FALSE(diagnostic.empty());
      std::vector<std::string> lines;
      std::istringstream in(diagnostic);
      for (std::string line; std::getline(in, line);) lines.push_back(line);
      CHECK(without_path(lines.at(0), file->path()) == expected_error[0]);
      std::vector<std::string> notes;
      for (const std::string& line : lines) {
        std::string rest = without_path(line, file->path());
        if (rest != line && rest.find(": note: ") != std::string::npos) notes.push_back(rest);
      }
      CHECK(notes == expected_notes);
    }
  }
}

TEST_CASE("the golden diff shows removed, added and context lines", "[golden]") {
  CHECK(line_diff("a\nb\nc\n", "a\nb\nc\n") == "");
  CHECK(line_diff("a\nb\nc\n", "a\nB\nc\n") == "--- expected\n+++ actual\n a\n-b\n+B\n c\n");
  CHECK(line_diff("1\n2\n3\n4\n5\n6\n7\n8\n9\n", "1\n2\n3\n4\n5\n6\n7\n8\n9\nX\n") ==
        "--- expected\n+++ actual\n 8\n 9\n+X\n");
  CHECK(line_diff("x\n1\n2\n3\n4\n5\n6\n7\ny\n", "X\n1\n2\n3\n4\n5\n6\n7\nY\n") ==
        "--- expected\n+++ actual\n-x\n+X\n 1\n 2\n@@\n 6\n 7\n-y\n+Y\n");
}
