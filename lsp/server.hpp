// The language server: LSP 3.17 requests and notifications in, responses and diagnostics out.
// It is transport-free (`handle` takes one message body, `send` gets each outgoing one), so
// the stdio loop (stdio.cpp), the tests and the fuzz harness drive the same code. Whatever
// arrives, it answers with a response or an error response and goes on: malformed JSON,
// unknown methods, wrong parameter types, positions past the end, huge buffers.
#pragma once

#include <functional>
#include <map>
#include <stdexcept>
#include <memory>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "lsp/analysis.hpp"
#include "lsp/document.hpp"

namespace rts::lsp {

struct ServerOptions {
  AnalysisOptions analysis;
};

// A request that is valid but cannot be done (formatting a buffer that does not parse):
// answered with LSP's RequestFailed and the message.
struct RequestFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Server {
 public:
  using Send = std::function<void(const std::string& body)>;
  Server(ServerOptions options, Send send);

  // One JSON-RPC message (a request, a notification, or a response to us, which is ignored).
  void handle(std::string_view body);
  // A framing error from the reader: answered as a parse error with a null id.
  void framing_error(const std::string& message);
  // Analyses the buffers edited since their last analysis and publishes their diagnostics
  // (the stdio loop calls it when no more input is waiting, so a burst of edits costs one).
  void flush();

  bool exited() const { return exited_; }
  // After `exit`: 0 when `shutdown` came first, 1 otherwise (as LSP says).
  int exit_code() const { return shutdown_ ? 0 : 1; }

 private:
  using json = nlohmann::json;
  void dispatch(const std::string& method, const json& params, const json* id);
  void respond(const json& id, json result);
  void respond_error(const json& id, int code, const std::string& message);
  void notify(const std::string& method, json params);

  json initialize(const json& params);
  void did_open(const json& params);
  void did_change(const json& params);
  void did_close(const json& params);
  // The open document a request names, analysed up to date; throws std::invalid_argument for
  // a document that is not open.
  Document& document_for(const json& params);
  void analyse(Document& doc);
  void publish(Document& doc);
  std::size_t offset_of(const Document& doc, const json& position) const;

  // features.cpp
  json hover(Document& doc, std::size_t offset);
  json completion(Document& doc, std::size_t offset);
  json definition(Document& doc, std::size_t offset);
  json document_symbols(Document& doc);
  json signature_help(Document& doc, std::size_t offset);
  json formatting(Document& doc);

  json range_of(const Document& doc, std::size_t begin, std::size_t end) const;
  json diagnostic_to_json(const Document& doc, const Diagnostic& d) const;
  json location_in(const SourceFile& file, std::size_t begin, std::size_t end) const;

  ServerOptions options_;
  Send send_;
  std::map<std::string, std::unique_ptr<Document>> documents_;  // by URI
  bool initialized_ = false;
  bool shutdown_ = false;
  bool exited_ = false;
  bool utf16_ = true;  // position units: UTF-16 code units unless the client takes UTF-8
};

}  // namespace rts::lsp
