// libFuzzer harness: the language server's message reader and dispatch. The input is a byte
// stream as an editor would write to `rts lsp` (Content-Length framed JSON-RPC), fed in two
// pieces cut at a point the first byte picks (so messages split across reads are exercised).
// Every framed body goes to the server, which must answer everything with valid JSON and never
// crash or hang; evaluation is off (fuzz_eval covers the evaluator), parsing and the features
// (hover, completion, symbols... over whatever text arrives) are on.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "lsp/framing.hpp"
#include "lsp/server.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::size_t cut = bytes.empty() ? 0 : data[0] % (bytes.size() + 1);

  rts::lsp::ServerOptions options;
  options.analysis.evaluate = false;
  rts::lsp::Server server(options, [](const std::string& body) {
    // Every message the server writes is one JSON object.
    nlohmann::json out = nlohmann::json::parse(body, nullptr, false);
    if (out.is_discarded() || !out.is_object()) std::abort();
  });
  rts::lsp::MessageReader reader;
  std::string body, error;
  for (std::string_view piece : {bytes.substr(0, cut), bytes.substr(cut)}) {
    reader.feed(piece);
    for (;;) {
      auto status = reader.next(body, error);
      if (status == rts::lsp::MessageReader::Status::NeedMore) break;
      if (status == rts::lsp::MessageReader::Status::Error) {
        if (error.empty()) std::abort();  // an error always says what
        server.framing_error(error);
      } else {
        server.handle(body);
      }
      if (server.exited()) return 0;
    }
    server.flush();
  }
  return 0;
}
