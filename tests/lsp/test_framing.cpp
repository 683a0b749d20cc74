// lsp/framing: Content-Length framing in, whole bodies out, whatever the chunking; malformed
// headers reported and skipped.
#include <catch2/catch.hpp>

#include "lsp/framing.hpp"

using rts::lsp::MessageReader;
using Status = MessageReader::Status;

TEST_CASE("framing: messages split anywhere come out whole and in order", "[framing]") {
  const std::string stream = rts::lsp::frame("{\"a\":1}") + rts::lsp::frame("{\"b\":\"é\"}") + rts::lsp::frame("");
  for (std::size_t step = 1; step <= stream.size(); ++step) {
    MessageReader r;
    std::vector<std::string> got;
    std::string body, error;
    for (std::size_t i = 0; i < stream.size(); i += step) {
      r.feed(std::string_view(stream).substr(i, step));
      while (r.next(body, error) == Status::Message) got.push_back(body);
    }
    CAPTURE(step);
    REQUIRE(got == std::vector<std::string>{"{\"a\":1}", "{\"b\":\"é\"}", ""});
    CHECK(r.pending() == 0);
  }
}

TEST_CASE("framing: header names are case-insensitive and other headers are ignored", "[framing]") {
  MessageReader r;
  r.feed("content-length: 2\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n{}");
  std::string body, error;
  REQUIRE(r.next(body, error) == Status::Message);
  CHECK(body == "{}");
}

TEST_CASE("framing: malformed headers are errors and the reader goes on after them", "[framing]") {
  MessageReader r;
  std::string body, error;
  r.feed("Content-Length: x\r\n\r\n");
  REQUIRE(r.next(body, error) == Status::Error);
  CHECK(error == "Content-Length is not a number");
  r.feed("Bogus\r\n\r\n");
  REQUIRE(r.next(body, error) == Status::Error);
  CHECK(error.find("malformed") != std::string::npos);
  r.feed("X-Other: 1\r\n\r\n");
  REQUIRE(r.next(body, error) == Status::Error);
  CHECK(error.find("without Content-Length") != std::string::npos);
  r.feed(rts::lsp::frame("[]"));
  REQUIRE(r.next(body, error) == Status::Message);
  CHECK(body == "[]");
}

TEST_CASE("framing: an oversize body is refused and skipped as it arrives", "[framing]") {
  MessageReader r;
  std::string body, error;
  const std::size_t n = rts::lsp::kMaxBodyBytes + 10;
  r.feed("Content-Length: " + std::to_string(n) + "\r\n\r\n");
  REQUIRE(r.next(body, error) == Status::Error);
  CHECK(error.find("longer than") != std::string::npos);
  std::string chunk(1 << 20, 'x');
  std::size_t sent = 0;
  while (sent < n) {
    std::size_t k = std::min(chunk.size(), n - sent);
    r.feed(std::string_view(chunk).substr(0, k));
    sent += k;
    CHECK(r.next(body, error) == Status::NeedMore);
  }
  r.feed(rts::lsp::frame("{}"));
  REQUIRE(r.next(body, error) == Status::Message);
  CHECK(body == "{}");
}

TEST_CASE("framing: a header that never ends is an error, not unbounded growth", "[framing]") {
  MessageReader r;
  std::string body, error;
  r.feed(std::string(rts::lsp::kMaxHeaderBytes + 1, 'a'));
  CHECK(r.next(body, error) == Status::Error);
  CHECK(r.pending() == 0);
}
