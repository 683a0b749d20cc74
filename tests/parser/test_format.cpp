// The formatter (parser/format.hpp): over every scene in the repository it keeps the syntax
// tree (the `rts parse` dump) and every comment, and is idempotent; files that do not parse
// fail with their located error; and the layout rules of docs/language.md hold.
#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "parser/format.hpp"
#include "parser/parser.hpp"
#include "golden_runner.hpp"
#include "parser_test_support.hpp"

namespace fs = std::filesystem;

namespace {

std::string tree(const rts::SourceFile& f) {
  std::ostringstream out;
  rts::print_ast(out, rts::parse(f));
  return out.str();
}

std::string fmt(const std::string& text) {
  rts::SourceManager sources;
  return rts::format_source(*sources.add("t.rts", text));
}

// The comments of a text, in order, each without trailing blanks.
std::vector<std::string> comments(const std::string& text) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '"') {
      for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; i += text[i] == '\\' ? 2 : 1) {}
      ++i;
    } else if (text.compare(i, 2, "//") == 0) {
      std::size_t e = text.find('\n', i);
      if (e == std::string::npos) e = text.size();
      std::string c = text.substr(i, e - i);
      while (!c.empty() && (c.back() == ' ' || c.back() == '\t' || c.back() == '\r')) c.pop_back();
      out.push_back(c);
      i = e;
    } else if (text.compare(i, 2, "/*") == 0) {
      std::size_t e = text.find("*/", i + 2);
      e = e == std::string::npos ? text.size() : e + 2;
      std::string c;  // blanks before a line break inside are dropped by the formatter
      std::istringstream lines(text.substr(i, e - i));
      for (std::string l; std::getline(lines, l);) {
        while (!l.empty() && (l.back() == ' ' || l.back() == '\t' || l.back() == '\r')) l.pop_back();
        c += l + "\n";
      }
      out.push_back(c);
      i = e;
    } else {
      ++i;
    }
  }
  return out;
}

std::vector<fs::path> every_scene() {
  std::vector<fs::path> out;
  fs::path root(RTS_SOURCE_DIR);
  for (const char* dir : {"examples", "stdlib", "tests", "bench", "docs"}) {
    if (!fs::exists(root / dir)) continue;
    for (const auto& e : fs::recursive_directory_iterator(root / dir))
      if (e.is_regular_file() && e.path().extension() == ".rts") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("every scene in the repository formats to the same tree, idempotently", "[format]") {
  int formatted = 0, refused = 0;
  for (const fs::path& path : every_scene()) {
    INFO(path.string());
    std::string text = rts::testing::read_file(path);
    rts::SourceManager sources;
    const rts::SourceFile* file = sources.add(path.string(), text);
    std::string before;
    try {
      before = tree(*file);
    } catch (const rts::LanguageError& parse_error) {
      // A file that does not parse: the formatter reports the same located error.
      try {
        (void)rts::format_source(*file);
        FAIL("formatted a file that does not parse");
      } catch (const rts::LanguageError& e) {
        CHECK(e.diag.loc.line() == parse_error.diag.loc.line());
        CHECK(e.diag.loc.col() == parse_error.diag.loc.col());
        CHECK(e.diag.message == parse_error.diag.message);
      }
      ++refused;
      continue;
    }
    std::string once = rts::format_source(*file);
    const rts::SourceFile* f1 = sources.add(path.string() + ".1", once);
    REQUIRE(tree(*f1) == before);
    REQUIRE(comments(once) == comments(text));
    REQUIRE(rts::format_source(*f1) == once);
    ++formatted;
  }
  // The repository holds hundreds of valid scenes and the parse-error goldens.
  CHECK(formatted > 200);
  CHECK(refused > 20);
}

TEST_CASE("layout: indentation, spacing, blank lines", "[format]") {
  CHECK(fmt("sphere{center=<0,1,0> radius=1}") == "sphere { center = <0, 1, 0>  radius = 1 }\n");
  CHECK(fmt("let  x=-1+ 2*f( a ,b=3 )[0].y") == "let x = -1 + 2 * f(a, b = 3)[0].y\n");
  // Negative literals are numbers in the AST (no unary node): their minus still binds tight.
  CHECK(fmt("let v=<1,-2,- 3>\nlet w = a - -2 - 3*-x\nlet z=--2\nlet r=-(2)") ==
        "let v = <1, -2, -3>\nlet w = a - -2 - 3 * -x\nlet z = --2\nlet r = -(2)\n");
  CHECK(fmt("\n\n\nlet a = 1\n\n\n\nlet b = a - -2\n\n") == "let a = 1\n\nlet b = a - -2\n");
  CHECK(fmt("group {\n\n  sphere {\n radius = 1\n  }\n\n}\n") ==
        "group {\n    sphere {\n        radius = 1\n    }\n}\n");
  CHECK(fmt("for i in 0..3 step 1 { if i<2 { x += i } else if i==2 {} else { break } }") ==
        "for i in 0 .. 3 step 1 { if i < 2 { x += i } else if i == 2 {} else { break } }\n");
  // A line that does not start a property continues the one before: one level deeper.
  CHECK(fmt("let m = material {\ncolor = rgb(1,\n0, 0)\ndiffuse = 0.5 +\n0.2 }") ==
        "let m = material {\n    color = rgb(1,\n        0, 0)\n    diffuse = 0.5 +\n        0.2 }\n");
  CHECK(fmt("macro m(a, b = 2) { return [a, b] }\nm(1)") == "macro m(a, b = 2) { return [a, b] }\nm(1)\n");
  CHECK(fmt("let t = checker { scale = 2 } translate <1,0,0> rotate <0, 90,0>") ==
        "let t = checker { scale = 2 } translate <1, 0, 0> rotate <0, 90, 0>\n");
  // Allman braces and a lone `else` stay at their statement's level.
  CHECK(fmt("if a {\n}\nelse\n{\nprint(1)\n}\nmacro m()\n{\nreturn 1\n}") ==
        "if a {\n}\nelse\n{\n    print(1)\n}\nmacro m()\n{\n    return 1\n}\n");
  CHECK(fmt("") == "");
  CHECK(fmt("\n\n") == "");
}

TEST_CASE("comments stay where they were written", "[format]") {
  CHECK(fmt("let a = 1 // one\nlet bb = 22    // two\n\nlet c = 3 // three\n") ==
        "let a = 1    // one\nlet bb = 22  // two\n\nlet c = 3  // three\n");
  CHECK(fmt("sphere { /* r */ radius = 1 }") == "sphere { /* r */ radius = 1 }\n");
  CHECK(fmt("  // lead\nlet a = [\n1, // first\n  2\n]\n// end") ==
        "// lead\nlet a = [\n    1,  // first\n    2\n]\n// end\n");
  CHECK(fmt("/* a\n   b */\nlet a = 1") == "/* a\n   b */\nlet a = 1\n");
}

TEST_CASE("a file that does not parse is an error, located", "[format]") {
  rts::SourceManager sources;  // alive while the error is read: its location resolves through it
  try {
    (void)rts::format_source(*sources.add("t.rts", "sphere { radius = 1\n"));
    FAIL("no error");
  } catch (const rts::LanguageError& e) {
    CHECK(e.diag.loc.line() == 1);
    CHECK(e.diag.message.find("'}'") != std::string::npos);
  }
}

TEST_CASE("mutated scenes format to the same tree or fail cleanly", "[format]") {
  // Random edits to valid scenes make odd but valid programs too (a deleted newline glues
  // two statements); each must keep its tree, and formatting its output changes nothing.
  std::mt19937 rng(20261125);
  const std::string alphabet = "{}()[]<>,;=+-*/.\" \n\tax019e_";
  auto inputs = rts::testing::files_with_extension(fs::path(RTS_SOURCE_DIR) / "tests/golden/parse", ".rts");
  REQUIRE_FALSE(inputs.empty());
  int valid = 0;
  for (const fs::path& input : inputs) {
    std::string original = rts::testing::read_file(input);
    for (int i = 0; i < 60; ++i) {
      std::string text = original;
      std::size_t pos = rng() % (text.size() + 1);
      switch (rng() % 3) {
        case 0: if (pos < text.size()) text.erase(pos, 1); break;
        case 1: text.insert(pos, 1, alphabet[rng() % alphabet.size()]); break;
        default: if (pos < text.size()) text[pos] = alphabet[rng() % alphabet.size()]; break;
      }
      INFO(text);
      std::string once;
      try {
        once = fmt(text);
      } catch (const rts::LanguageError&) {
        continue;
      }
      REQUIRE(fmt(once) == once);
      ++valid;
    }
  }
  CHECK(valid > 100);
}
