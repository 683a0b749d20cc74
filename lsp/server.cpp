// The protocol side of the server: lifecycle, dispatch, open documents and diagnostics. The
// features (hover, completion, ...) are in features.cpp.
#include "lsp/server.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>

namespace rts::lsp {

namespace {

// JSON-RPC and LSP error codes.
constexpr int kParseError = -32700;
constexpr int kInvalidRequest = -32600;
constexpr int kMethodNotFound = -32601;
constexpr int kInvalidParams = -32602;
constexpr int kInternalError = -32603;
constexpr int kServerNotInitialized = -32002;
constexpr int kRequestFailed = -32803;

// LSP's DiagnosticSeverity and TextDocumentSyncKind.
constexpr int kSeverityError = 1, kSeverityWarning = 2, kSeverityInformation = 3;
constexpr int kSyncIncremental = 2;

// An editor has no use for thousands of diagnostics; the first ones are the ones to fix.
constexpr std::size_t kMaxDiagnostics = 200;

uint32_t position_field(const nlohmann::json& p, const char* name) {
  const nlohmann::json& v = p.at(name);
  if (!v.is_number()) throw std::invalid_argument(std::string("position.") + name + " is not a number");
  double d = v.get<double>();
  if (!(d >= 0)) return 0;  // negative or NaN: the start
  return d > 4294967295.0 ? UINT32_MAX : static_cast<uint32_t>(d);
}

Position to_position(const nlohmann::json& p) {
  if (!p.is_object()) throw std::invalid_argument("position is not an object");
  return Position{position_field(p, "line"), position_field(p, "character")};
}

}  // namespace

Server::Server(ServerOptions options, Send send) : options_(std::move(options)), send_(std::move(send)) {}

void Server::respond(const json& id, json result) {
  json msg = {{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}};
  send_(msg.dump(-1, ' ', false, json::error_handler_t::replace));
}

void Server::respond_error(const json& id, int code, const std::string& message) {
  json msg = {{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}};
  send_(msg.dump(-1, ' ', false, json::error_handler_t::replace));
}

void Server::notify(const std::string& method, json params) {
  json msg = {{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}};
  send_(msg.dump(-1, ' ', false, json::error_handler_t::replace));
}

void Server::framing_error(const std::string& message) { respond_error(nullptr, kParseError, message); }

void Server::handle(std::string_view body) {
  json msg = json::parse(body.begin(), body.end(), nullptr, /*allow_exceptions=*/false);
  if (msg.is_discarded()) {
    respond_error(nullptr, kParseError, "the message is not valid JSON");
    return;
  }
  if (!msg.is_object()) {
    // A batch (array) or a bare value: LSP sends neither.
    respond_error(nullptr, kInvalidRequest, "expected a JSON-RPC request or notification object");
    return;
  }
  const json* id = nullptr;
  if (auto it = msg.find("id"); it != msg.end()) {
    if (!it->is_number_integer() && !it->is_string()) {
      respond_error(nullptr, kInvalidRequest, "the request id must be a number or a string");
      return;
    }
    id = &*it;
  }
  auto method_it = msg.find("method");
  if (method_it == msg.end()) {
    if (!id) respond_error(nullptr, kInvalidRequest, "a message without a method or an id");
    return;  // a response to a request of ours (we send none that wait): ignored
  }
  if (!method_it->is_string()) {
    respond_error(id ? *id : json(nullptr), kInvalidRequest, "the method must be a string");
    return;
  }
  static const json kNoParams = json::object();
  auto params_it = msg.find("params");
  const json& params = params_it == msg.end() ? kNoParams : *params_it;
  const std::string method = method_it->get<std::string>();
  try {
    dispatch(method, params, id);
  } catch (const RequestFailed& e) {
    if (id) respond_error(*id, kRequestFailed, e.what());
  } catch (const json::exception& e) {
    if (id) respond_error(*id, kInvalidParams, std::string("invalid parameters: ") + e.what());
  } catch (const std::invalid_argument& e) {
    if (id) respond_error(*id, kInvalidParams, e.what());
  } catch (const std::bad_alloc&) {
    if (id) respond_error(*id, kInternalError, "out of memory");
  } catch (const std::exception& e) {
    if (id) respond_error(*id, kInternalError, std::string("internal error: ") + e.what());
  }
}

void Server::dispatch(const std::string& method, const json& params, const json* id) {
  if (method == "exit") {
    exited_ = true;
    return;
  }
  if (!initialized_ && method != "initialize") {
    if (id) respond_error(*id, kServerNotInitialized, "the server is not initialized");
    return;
  }
  if (shutdown_) {
    if (id) respond_error(*id, kInvalidRequest, "the server is shut down");
    return;
  }
  if (!id) {  // notifications
    if (method == "textDocument/didOpen") did_open(params);
    else if (method == "textDocument/didChange") did_change(params);
    else if (method == "textDocument/didClose") did_close(params);
    // initialized, didSave, $/cancelRequest, $/setTrace, workspace/...: nothing to do
    return;
  }
  if (method == "initialize") {
    if (initialized_) return respond_error(*id, kInvalidRequest, "initialize was already received");
    respond(*id, initialize(params));
    initialized_ = true;
  } else if (method == "shutdown") {
    shutdown_ = true;
    respond(*id, nullptr);
  } else if (method == "textDocument/hover") {
    Document& doc = document_for(params);
    respond(*id, hover(doc, offset_of(doc, params.at("position"))));
  } else if (method == "textDocument/completion") {
    Document& doc = document_for(params);
    respond(*id, completion(doc, offset_of(doc, params.at("position"))));
  } else if (method == "textDocument/definition") {
    Document& doc = document_for(params);
    respond(*id, definition(doc, offset_of(doc, params.at("position"))));
  } else if (method == "textDocument/documentSymbol") {
    respond(*id, document_symbols(document_for(params)));
  } else if (method == "textDocument/signatureHelp") {
    Document& doc = document_for(params);
    respond(*id, signature_help(doc, offset_of(doc, params.at("position"))));
  } else if (method == "textDocument/formatting") {
    respond(*id, formatting(document_for(params)));
  } else {
    respond_error(*id, kMethodNotFound, "unknown method '" + method + "'");
  }
}

nlohmann::json Server::initialize(const json& params) {
  // UTF-8 positions when the client offers them (LSP 3.17), else the mandatory UTF-16.
  utf16_ = true;
  if (auto g = params.find("capabilities"); g != params.end() && g->is_object())
    if (auto gen = g->find("general"); gen != g->end() && gen->is_object())
      if (auto enc = gen->find("positionEncodings"); enc != gen->end() && enc->is_array())
        for (const json& e : *enc)
          if (e == "utf-8") utf16_ = false;
  json caps = {
      {"positionEncoding", utf16_ ? "utf-16" : "utf-8"},
      {"textDocumentSync", {{"openClose", true}, {"change", kSyncIncremental}}},
      {"hoverProvider", true},
      {"completionProvider", {{"triggerCharacters", json::array({".", "\""})}}},
      {"definitionProvider", true},
      {"documentSymbolProvider", true},
      {"signatureHelpProvider", {{"triggerCharacters", json::array({"(", ","})}}},
      {"documentFormattingProvider", true},
  };
  return {{"capabilities", caps}, {"serverInfo", {{"name", "rts"}, {"version", RTS_VERSION}}}};
}

void Server::did_open(const json& params) {
  const json& td = params.at("textDocument");
  auto doc = std::make_unique<Document>();
  doc->uri = td.at("uri").get<std::string>();
  doc->path = uri_to_path(doc->uri);
  doc->text = td.at("text").get<std::string>();
  if (auto v = td.find("version"); v != td.end() && v->is_number_integer()) doc->version = v->get<int64_t>();
  documents_[doc->uri] = std::move(doc);
}

void Server::did_change(const json& params) {
  const json& td = params.at("textDocument");
  auto it = documents_.find(td.at("uri").get<std::string>());
  if (it == documents_.end()) return;  // not open: nothing to change
  Document& doc = *it->second;
  for (const json& change : params.at("contentChanges")) {
    const std::string& text = change.at("text").get_ref<const std::string&>();
    auto range = change.find("range");
    if (range == change.end() || range->is_null()) {
      doc.text = text;
      continue;
    }
    LineIndex lines(doc.text);
    apply_change(doc.text, lines, utf16_, true, to_position(range->at("start")), to_position(range->at("end")), text);
  }
  if (auto v = td.find("version"); v != td.end() && v->is_number_integer()) doc.version = v->get<int64_t>();
  doc.dirty = true;
}

void Server::did_close(const json& params) {
  const std::string uri = params.at("textDocument").at("uri").get<std::string>();
  if (documents_.erase(uri)) notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", json::array()}});
}

Document& Server::document_for(const json& params) {
  const std::string uri = params.at("textDocument").at("uri").get<std::string>();
  auto it = documents_.find(uri);
  if (it == documents_.end()) throw std::invalid_argument("document not open: " + uri);
  Document& doc = *it->second;
  if (doc.dirty) {
    analyse(doc);
    publish(doc);
  }
  return doc;
}

void Server::analyse(Document& doc) {
  // Free the old analysis first (a 10 MB buffer's tree is large), keeping its names for a
  // text that does not parse.
  SymbolIndex previous;
  if (doc.analysis) previous = std::move(doc.analysis->symbols);
  doc.analysis.reset();
  // Analysis::file is a copy of the text; the line index points into that copy.
  auto a = std::make_unique<Analysis>();
  {
    LineIndex text_lines(doc.text);
    *a = analyze(doc.path, doc.text, text_lines, options_.analysis, std::move(previous));
  }
  doc.analysis = std::move(a);
  doc.lines = LineIndex(doc.analysis->file->text());
  doc.dirty = false;
}

void Server::flush() {
  for (auto& [uri, doc] : documents_)
    if (doc->dirty) {
      analyse(*doc);
      publish(*doc);
    }
}

std::size_t Server::offset_of(const Document& doc, const json& position) const {
  return doc.lines.offset(to_position(position), utf16_);
}

nlohmann::json Server::range_of(const Document& doc, std::size_t begin, std::size_t end) const {
  Position a = doc.lines.position(begin, utf16_), b = doc.lines.position(std::max(begin, end), utf16_);
  return {{"start", {{"line", a.line}, {"character", a.character}}},
          {"end", {{"line", b.line}, {"character", b.character}}}};
}

nlohmann::json Server::location_in(const SourceFile& file, std::size_t begin, std::size_t end) const {
  LineIndex lines(file.text());  // (a buffer's own locations go through its document's index)
  Position a = lines.position(begin, utf16_), b = lines.position(std::max(begin, end), utf16_);
  return {{"uri", path_to_uri(file.path())},
          {"range",
           {{"start", {{"line", a.line}, {"character", a.character}}},
            {"end", {{"line", b.line}, {"character", b.character}}}}}};
}

nlohmann::json Server::diagnostic_to_json(const Document& doc, const Diagnostic& d) const {
  const Analysis& a = *doc.analysis;
  // The buffer's own line index, built once: a 10 MB buffer is not rescanned per diagnostic.
  auto bytes_of = [&](const SourceFile& f, SourceLoc loc) {
    std::size_t begin =
        &f == a.file ? doc.lines.offset_of_loc(loc.line(), loc.col()) : LineIndex(f.text()).offset_of_loc(loc.line(), loc.col());
    return std::pair{begin, loc.line() == 0 ? begin : token_end(f.text(), begin)};
  };
  auto location = [&](const SourceFile& f, std::size_t b, std::size_t e) {
    if (&f != a.file) return location_in(f, b, e);
    return json{{"uri", doc.uri}, {"range", range_of(doc, b, e)}};
  };
  json related = json::array();
  std::string message = d.message;
  std::size_t begin = 0, end = 0;
  if (d.loc.file() == a.file || !d.loc.file()) {
    if (d.loc.file()) std::tie(begin, end) = bytes_of(*a.file, d.loc);
  } else {
    // In an included file: shown at the include (the outermost note in this buffer), with the
    // place itself as related information.
    auto [b, e] = bytes_of(*d.loc.file(), d.loc);
    related.push_back({{"location", location(*d.loc.file(), b, e)}, {"message", d.message}});
    for (auto n = d.notes.rbegin(); n != d.notes.rend(); ++n)
      if (n->loc.file() == a.file) {
        std::tie(begin, end) = bytes_of(*a.file, n->loc);
        break;
      }
    message = d.message + " (in " + d.loc.file()->path() + ")";
  }
  if (end == begin && begin < a.file->text().size() && a.file->text()[begin] != '\n') ++end;
  for (const Note& n : d.notes) {
    if (!n.loc.file()) continue;
    auto [b, e] = bytes_of(*n.loc.file(), n.loc);
    related.push_back({{"location", location(*n.loc.file(), b, e)}, {"message", n.message}});
  }
  json out = {{"range", range_of(doc, begin, end)},
              {"severity", d.severity == Severity::Error     ? kSeverityError
                           : d.severity == Severity::Warning ? kSeverityWarning
                                                             : kSeverityInformation},
              {"source", "rts"},
              {"message", message}};
  if (!related.empty()) out["relatedInformation"] = std::move(related);
  return out;
}

void Server::publish(Document& doc) {
  json list = json::array();
  for (const Diagnostic& d : doc.analysis->diagnostics) {
    if (list.size() >= kMaxDiagnostics) break;
    list.push_back(diagnostic_to_json(doc, d));
  }
  notify("textDocument/publishDiagnostics", {{"uri", doc.uri}, {"version", doc.version}, {"diagnostics", list}});
}

}  // namespace rts::lsp
