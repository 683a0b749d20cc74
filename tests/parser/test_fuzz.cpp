// Mutated scenes never crash the parser: every input either parses or fails with a
// LanguageError whose location lies inside the file. Deterministic (fixed seed).
#include <catch2/catch.hpp>

#include <iterator>
#include <random>
#include <sstream>
#include <string>

#include "golden_runner.hpp"
#include "parser_test_support.hpp"

namespace fs = std::filesystem;

namespace {

constexpr int kMutantsPerFile = 200;
constexpr unsigned kSeed = 20261121;
// Characters that matter to the grammar, plus some that do not belong in it at all.
const std::string kAlphabet = "{}()[]<>,;=+-*/%^.\"\\ \n\tabcxyz019eE_#@$!&|?~`'";
const char* const kFragments[] = {"let ", "if ", "else ", "for ", " in ", "while ", "macro ",
                                  "return ", "with ", " translate ", " step ", "..", "..=",
                                  "/*", "*/", "//", "\\u{", "sphere {", "}", "(((", "]]"};

std::string mutate(std::string text, std::mt19937& rng) {
  std::uniform_int_distribution<int> how(0, 3);
  int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    std::size_t pos = text.empty() ? 0 : rng() % (text.size() + 1);
    switch (how(rng)) {
      case 0:  // delete a few bytes
        if (pos < text.size()) text.erase(pos, 1 + rng() % 3);
        break;
      case 1:  // insert a character
        text.insert(pos, 1, kAlphabet[rng() % kAlphabet.size()]);
        break;
      case 2:  // replace a character
        if (pos < text.size()) text[pos] = kAlphabet[rng() % kAlphabet.size()];
        break;
      default:  // insert a keyword or bracket run
        text.insert(pos, kFragments[rng() % std::size(kFragments)]);
        break;
    }
  }
  return text;
}

}  // namespace

TEST_CASE("mutated golden scenes parse or fail cleanly", "[fuzz]") {
  std::mt19937 rng(kSeed);
  int parsed = 0, failed = 0;
  auto inputs = rts::testing::files_with_extension(fs::path(RTS_SOURCE_DIR) / "tests/golden/parse", ".rts");
  REQUIRE_FALSE(inputs.empty());
  for (const fs::path& input : inputs) {
    std::string original = rts::testing::read_file(input);
    for (int i = 0; i < kMutantsPerFile; ++i) {
      std::string text = mutate(original, rng);
      rts::SourceManager sources;
      const rts::SourceFile* file = sources.add("fuzz.rts", text);
      try {
        rts::ast::Program program = rts::parse(*file);
        std::ostringstream sink;
        rts::print_ast(sink, program, true);
        ++parsed;
      } catch (const rts::LanguageError& e) {
        ++failed;
        INFO("input:\n" << text);
        REQUIRE(e.diag.loc.file() == file);
        REQUIRE(e.diag.loc.line() >= 1);
        REQUIRE(e.diag.loc.line() <= file->line_count());
        REQUIRE(e.diag.loc.col() >= 1);
        REQUIRE(e.diag.loc.col() <= file->line_text(e.diag.loc.line()).size() + 1);
        REQUIRE_FALSE(e.diag.message.empty());
      }
    }
  }
  // Both outcomes occur: the mutations are neither all harmless nor all fatal.
  CHECK(parsed > 0);
  CHECK(failed > 0);
}
