// docs/language.md stays in step with grammar/: every rule struct is named in its grammar
// section, and its list of reserved words is exactly the grammar's.
#include <catch2/catch.hpp>

#include <cctype>
#include <filesystem>
#include <set>
#include <string>

#include "golden_runner.hpp"
#include "grammar/lexical.hpp"

namespace fs = std::filesystem;
using rts::testing::read_file;

namespace {

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The word starting at `pos` ([a-z_][a-z0-9_]*), or "" when there is none.
std::string word_at(const std::string& text, std::size_t pos) {
  std::size_t end = pos;
  while (end < text.size() && is_word_char(text[end])) ++end;
  return text.substr(pos, end - pos);
}

// True when `name` occurs in `text` as a whole word.
bool contains_word(const std::string& text, const std::string& name) {
  for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
    bool starts = at == 0 || !is_word_char(text[at - 1]);
    bool ends = at + name.size() == text.size() || !is_word_char(text[at + name.size()]);
    if (starts && ends) return true;
  }
  return false;
}

const fs::path kRoot = fs::path(RTS_SOURCE_DIR);

// Names of the rule structs defined (not just declared) in grammar/*.hpp.
std::set<std::string> grammar_rule_names() {
  // Helpers in grammar/ that are not rules.
  const std::set<std::string> not_rules = {"errors", "analyze_traits"};
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(kRoot / "grammar")) {
    if (entry.path().extension() != ".hpp") continue;
    std::string text = read_file(entry.path());
    const std::string keyword = "struct ";
    for (std::size_t at = text.find(keyword); at != std::string::npos; at = text.find(keyword, at + 1)) {
      std::string name = word_at(text, at + keyword.size());
      std::size_t after = text.find_first_not_of(" \n", at + keyword.size() + name.size());
      // A definition (`struct x : ...`, `struct x {`, a specialization `struct x<true> : ...`),
      // not a declaration `struct x;`.
      bool defined = after != std::string::npos && (text[after] == ':' || text[after] == '{' || text[after] == '<');
      if (!name.empty() && defined && !not_rules.count(name)) names.insert(name);
    }
  }
  return names;
}

std::string section(const std::string& doc, const std::string& begin, const std::string& end) {
  auto b = doc.find(begin);
  REQUIRE(b != std::string::npos);
  auto e = doc.find(end, b + begin.size());
  REQUIRE(e != std::string::npos);
  return doc.substr(b + begin.size(), e - b - begin.size());
}

}  // namespace

TEST_CASE("every grammar rule is named in docs/language.md's grammar", "[docs]") {
  std::string doc = read_file(kRoot / "docs" / "language.md");
  std::string grammar = section(doc, "```peg", "```");
  auto names = grammar_rule_names();
  CHECK(names.size() > 100);  // the scan found the rules
  for (const std::string& name : names) {
    INFO("rule struct '" << name << "' is missing from the grammar section of docs/language.md");
    CHECK(contains_word(grammar, name));
  }
}

TEST_CASE("the documented reserved words are exactly the grammar's", "[docs]") {
  std::string doc = read_file(kRoot / "docs" / "language.md");
  std::string list = section(doc, "**Reserved words**:", "The five operator words");
  std::set<std::string> documented;
  for (std::size_t at = list.find('`'); at != std::string::npos; at = list.find('`', at + 1)) {
    std::string w = word_at(list, at + 1);
    if (!w.empty() && at + 1 + w.size() < list.size() && list[at + 1 + w.size()] == '`') {
      documented.insert(w);
      at += w.size() + 1;  // skip the closing backquote
    }
  }
  CHECK(documented.size() == 23);
  for (const std::string& w : documented) {
    INFO(w);
    CHECK(rts::grammar::is_reserved_word(w));
  }
  // Every kw_ rule of the grammar is documented.
  for (const std::string& name : grammar_rule_names()) {
    if (name.rfind("kw_", 0) == 0) {
      INFO(name);
      CHECK(documented.count(name.substr(3)) == 1);
    }
  }
  for (const char* name : {"letter", "iffy", "scaled", "sphere", "group", "In", "LET"}) {
    INFO(name);
    CHECK_FALSE(rts::grammar::is_reserved_word(name));
  }
}
