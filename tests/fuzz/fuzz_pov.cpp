// libFuzzer harness: the POV-Ray front end (import/pov/). Every input translates or fails
// with a located PovError; a translation is rts text that parses (the importer never writes
// what rts cannot read).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_support.hpp"
#include "import/pov/pov_import.hpp"
#include "parser/parser.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  rts::import::pov::PovOptions options;
  options.source_path = "/nonexistent/fuzz.pov";  // #include finds no user files
  try {
    rts::import::pov::PovResult result = rts::import::pov::import_pov(text, options);
    for (const auto& w : result.warnings)
      if (w.message.empty()) std::abort();
    rts::SourceManager sources;
    const rts::SourceFile* file = sources.add("fuzz.rts", result.rts);
    try {
      rts::parse(*file);
    } catch (const rts::LanguageError& e) {
      // Deep nesting is refused by both readers at different depths; anything else is a
      // translation rts cannot read.
      if (std::string(e.what()).find("too deep") == std::string::npos) std::abort();
    }
  } catch (const rts::import::pov::PovError& e) {
    if (e.where.message.empty() || e.where.line < 0 || e.where.col < 0) std::abort();
  }
  return 0;
}
