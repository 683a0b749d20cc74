// libFuzzer harness: parse + evaluate with the default limits (EvalOptions{}), as `rts check`
// does. Every input builds a scene or fails with a located LanguageError.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "runtime/evaluator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  std::string text;
  if (!rts::fuzz::scene_text(data, size, text)) return -1;
  // Relative paths in the scene (include, mesh, image textures) resolve in the private
  // directory, which holds nothing: the fuzzer explores the language, not this machine's files.
  const std::string path = (rts::fuzz::work_dir() / "fuzz.rts").string();
  rts::SourceManager sources;
  const rts::SourceFile* file = sources.add(path, std::move(text));
  rts::DiagnosticSink warnings(rts::fuzz::null_stream());
  try {
    rts::EvalResult result = rts::evaluate_source(sources, *file, rts::fuzz::eval_options(), warnings);
    (void)result;
  } catch (const rts::LanguageError& e) {
    rts::fuzz::check_error(e);
  } catch (const rts::SourceError&) {
    // an include the scene names cannot be read: a reported error, fine
  }
  return 0;
}
