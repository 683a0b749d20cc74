// Eval goldens: every tests/golden/eval/*.rts evaluates to the dump in the .dump beside it;
// every tests/golden/eval-errors/*.rts fails with the diagnostic its `// error:` and
// `// note:` comments describe. Conventions: tests/README.md, "Eval goldens".
// Regenerate on purpose with scripts/update-golden-eval.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "eval_helpers.hpp"
#include "runtime/evaluator.hpp"

namespace fs = std::filesystem;
using namespace rts;

namespace {

const fs::path kGolden = fs::path(RTS_SOURCE_DIR) / "tests" / "golden";

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<fs::path> scenes(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".rts") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// Lines of `text` starting with `prefix`, prefix removed.
std::vector<std::string> comment_lines(const std::string& text, const std::string& prefix) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(prefix, 0) == 0) out.push_back(line.substr(prefix.size()));
  return out;
}

// `// defines: q=2 name="x"`: words separated by spaces.
EvalOptions options_for(const std::string& text) {
  EvalOptions opts;
  for (const std::string& line : comment_lines(text, "// defines: ")) {
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      Define d;
      REQUIRE(parse_define(w, d));
      opts.defines.push_back(d);
    }
  }
  // `// limits: max_iterations=1000 max_recursion=50 max_objects=10 max_mesh_triangles=5`
  for (const std::string& line : comment_lines(text, "// limits: ")) {
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      std::size_t eq = w.find('=');
      REQUIRE(eq != std::string::npos);
      std::string name = w.substr(0, eq);
      unsigned long long value = std::stoull(w.substr(eq + 1));
      if (name == "max_iterations")
        opts.limits.max_iterations = value;
      else if (name == "max_recursion")
        opts.limits.max_recursion = static_cast<unsigned>(value);
      else if (name == "max_objects")
        opts.limits.max_objects = value;
      else if (name == "max_mesh_triangles")
        opts.limits.max_mesh_triangles = value;
      else
        FAIL("unknown limit '" << name << "' in a golden's // limits: line");
    }
  }
  return opts;
}

// A location as the goldens write it: "line:col" in the scene itself, else the file's path
// relative to the scene's folder, then ":line:col".
std::string where(const SourceLoc& loc, const fs::path& scene) {
  if (!loc.valid()) return "";
  std::string file;
  if (fs::path(loc.file()->path()) != scene)
    file = fs::path(loc.file()->path()).lexically_relative(scene.parent_path()).generic_string() + ":";
  return fmt::format("{}{}:{}: ", file, loc.line(), loc.col());
}

// A line-by-line diff, enough to see what changed.
std::string diff(const std::string& expected, const std::string& actual) {
  std::istringstream a(expected), b(actual);
  std::string la, lb, out;
  int line = 0, shown = 0;
  constexpr int kMaxDiffLines = 20;
  while (true) {
    bool ha = static_cast<bool>(std::getline(a, la));
    bool hb = static_cast<bool>(std::getline(b, lb));
    if (!ha && !hb) break;
    ++line;
    if (ha && hb && la == lb) continue;
    if (++shown > kMaxDiffLines) {
      out += "...\n";
      break;
    }
    out += fmt::format("line {}:\n  - {}\n  + {}\n", line, ha ? la : "(end)", hb ? lb : "(end)");
  }
  return out;
}

}  // namespace

TEST_CASE("eval goldens", "[golden]") {
  auto files = scenes(kGolden / "eval");
  REQUIRE(!files.empty());
  for (const fs::path& scene : files) {
    DYNAMIC_SECTION(scene.filename().string()) {
      fs::path expected_path = fs::path(scene).replace_extension(".dump");
      INFO("scene: " << scene.string());
      REQUIRE(fs::exists(expected_path));  // run scripts/update-golden-eval to create it
      SourceManager sm;
      std::ostringstream warnings;
      DiagnosticSink sink(warnings);
      std::string actual;
      try {
        actual = test::dump(evaluate_file(sm, scene.string(), options_for(read(scene)), sink).scene);
      } catch (const LanguageError& e) {
        FAIL("unexpected error:\n" << format_diagnostic(e.diag));
      }
      std::string expected = read(expected_path);
      INFO("diff (- expected, + actual):\n" << diff(expected, actual));
      CHECK(actual == expected);
    }
  }
}

TEST_CASE("eval error goldens", "[golden]") {
  auto files = scenes(kGolden / "eval-errors");
  REQUIRE(!files.empty());
  for (const fs::path& scene : files) {
    DYNAMIC_SECTION(scene.filename().string()) {
      std::string text = read(scene);
      std::vector<std::string> expected = comment_lines(text, "// error: ");
      REQUIRE(expected.size() == 1);  // run scripts/update-golden-eval to write it
      for (const std::string& n : comment_lines(text, "// note: ")) expected.push_back(n);
      SourceManager sm;
      std::ostringstream warnings;
      DiagnosticSink sink(warnings);
      std::vector<std::string> actual;
      try {
        evaluate_file(sm, scene.string(), options_for(text), sink);
      } catch (const LanguageError& e) {
        actual.push_back(where(e.diag.loc, scene) + "error: " + e.diag.message);
        for (const Note& n : e.diag.notes) actual.push_back(where(n.loc, scene) + "note: " + n.message);
      }
      REQUIRE(!actual.empty());  // the scene must fail
      std::string want, got;
      for (auto& l : expected) want += l + "\n";
      for (auto& l : actual) got += l + "\n";
      INFO("diff (- expected, + actual):\n" << diff(want, got));
      CHECK(got == want);
    }
  }
}
