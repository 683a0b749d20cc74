// JSON-RPC message framing as LSP carries it over stdio: a header of `Name: value` lines
// ending in an empty line, of which Content-Length (the body's bytes) is required, then the
// body. The reader is fed bytes as they arrive and hands out whole bodies; anything malformed
// is reported and skipped, never trusted (tests/fuzz/fuzz_lsp_reader.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rts::lsp {

// A header longer than this is not a header (nothing legitimate sends more than a few lines).
inline constexpr std::size_t kMaxHeaderBytes = 8 * 1024;
// A body longer than this is refused and skipped: a 10 MB scene, JSON-escaped, fits.
inline constexpr std::size_t kMaxBodyBytes = 64u << 20;

class MessageReader {
 public:
  enum class Status { Message, NeedMore, Error };

  void feed(std::string_view bytes);
  // The next whole body (Message), or NeedMore, or Error with a message: the offending header
  // (and an oversize body, as it arrives) is skipped and the reader goes on after it.
  Status next(std::string& body, std::string& error);
  // Bytes held that are not yet a whole message.
  std::size_t pending() const { return buffer_.size() - pos_; }

 private:
  std::string buffer_;
  std::size_t pos_ = 0;       // where the unread bytes start
  std::size_t skipping_ = 0;  // bytes of a refused body still to drop
};

// `body` with its Content-Length header.
std::string frame(std::string_view body);

}  // namespace rts::lsp
