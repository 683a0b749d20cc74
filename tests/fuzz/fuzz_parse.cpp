// libFuzzer harness: the parser. Every input parses (and prints) or fails with a LanguageError
// located inside the text.
#include <cstddef>
#include <cstdint>
#include <sstream>

#include "fuzz_support.hpp"
#include "parser/parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string text;
  if (!rts::fuzz::scene_text(data, size, text)) return -1;  // not a loadable file: not in corpus
  rts::SourceManager sources;
  const rts::SourceFile* file = sources.add("fuzz.rts", std::move(text));
  try {
    rts::ast::Program program = rts::parse(*file);
    std::ostringstream out;
    rts::print_ast(out, program, true);
  } catch (const rts::LanguageError& e) {
    if (e.diag.loc.file() != file) std::abort();
    rts::fuzz::check_error(e);
  }
  return 0;
}
