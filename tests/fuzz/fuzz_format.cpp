// libFuzzer harness: the formatter. An input that parses formats to text with the same
// syntax tree (format_source checks that itself and throws std::logic_error otherwise) and
// formatting is idempotent; an input that does not parse fails with its located error.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#include "fuzz_support.hpp"
#include "parser/format.hpp"
#include "parser/parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string text;
  if (!rts::fuzz::scene_text(data, size, text)) return -1;  // not a loadable file: not in corpus
  rts::SourceManager sources;
  const rts::SourceFile* file = sources.add("fuzz.rts", std::move(text));
  std::string once;
  try {
    once = rts::format_source(*file);
  } catch (const rts::LanguageError& e) {
    if (e.diag.loc.file() != file) std::abort();
    rts::fuzz::check_error(e);
    return 0;
  } catch (const std::logic_error&) {
    std::abort();  // the formatter changed the meaning of a valid scene
  }
  const rts::SourceFile* again = sources.add("fuzz-formatted.rts", once);
  if (rts::format_source(*again) != once) std::abort();  // not idempotent
  return 0;
}
