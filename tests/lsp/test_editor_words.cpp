// The editor packages' word lists (editors/vim/syntax/rts.vim, the VS Code TextMate grammar)
// name every block kind and builtin the language has, so a new one is coloured everywhere.
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "render/builder/scene_builder.hpp"
#include "runtime/interpreter.hpp"

namespace {

std::string read_text(const std::string& relative) {
  std::ifstream in(std::string(RTS_SOURCE_DIR) + "/" + relative, std::ios::binary);
  REQUIRE(in);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// `word` appears as a whole word (delimited by anything but [A-Za-z0-9_]).
bool has_word(const std::string& text, const std::string& word) {
  auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) {
    bool before = at == 0 || !is_word(text[at - 1]);
    bool after = at + word.size() >= text.size() || !is_word(text[at + word.size()]);
    if (before && after) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("editor packages list every block kind and builtin", "[editors]") {
  const std::string vim = read_text("editors/vim/syntax/rts.vim");
  const std::string tm = read_text("editors/vscode/syntaxes/rts.tmLanguage.json");
  for (std::string_view kind : rts::render::SceneBuilder::block_kinds()) {
    CAPTURE(kind);
    CHECK(has_word(vim, std::string(kind)));
    CHECK(has_word(tm, std::string(kind)));
  }
  for (const auto& b : rts::runtime::builtin_table()) {
    CAPTURE(b.name);
    CHECK(has_word(vim, b.name));
    CHECK(has_word(tm, b.name));
  }
}
