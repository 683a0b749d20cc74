#include "lsp/framing.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

namespace rts::lsp {

namespace {

bool equals_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Parses the header (without its final empty line) into the body length, or says why not.
bool parse_header(std::string_view header, std::size_t& length, std::string& error) {
  bool have_length = false;
  while (!header.empty()) {
    std::size_t eol = header.find("\r\n");
    std::string_view line = header.substr(0, eol);
    header.remove_prefix(eol == std::string_view::npos ? header.size() : eol + 2);
    std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) {
      error = "malformed LSP header line (expected 'Name: value')";
      return false;
    }
    std::string_view name = trim(line.substr(0, colon));
    std::string_view value = trim(line.substr(colon + 1));
    if (!equals_ignoring_case(name, "Content-Length")) continue;  // Content-Type and the like
    if (value.empty() || value.size() > 12 ||
        !std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      error = "Content-Length is not a number";
      return false;
    }
    length = 0;
    for (char c : value) length = length * 10 + static_cast<std::size_t>(c - '0');
    have_length = true;
  }
  if (!have_length) {
    error = "LSP header without Content-Length";
    return false;
  }
  return true;
}

}  // namespace

void MessageReader::feed(std::string_view bytes) {
  // Drop what was read before appending, so the buffer holds at most one message and a bit.
  if (pos_ > 0 && pos_ >= buffer_.size() / 2) {
    buffer_.erase(0, pos_);
    pos_ = 0;
  }
  buffer_.append(bytes);
}

MessageReader::Status MessageReader::next(std::string& body, std::string& error) {
  if (skipping_ > 0) {
    std::size_t n = std::min(skipping_, pending());
    pos_ += n;
    skipping_ -= n;
    if (skipping_ > 0) return Status::NeedMore;
  }
  std::string_view rest(buffer_.data() + pos_, pending());
  std::size_t end = rest.find("\r\n\r\n");
  if (end == std::string_view::npos || end > kMaxHeaderBytes) {
    if (rest.size() <= kMaxHeaderBytes && end == std::string_view::npos) return Status::NeedMore;
    error = fmt::format("LSP header longer than {} bytes", kMaxHeaderBytes);
    pos_ += end == std::string_view::npos ? rest.size() : end + 4;  // skip it all
    return Status::Error;
  }
  std::size_t length = 0;
  if (!parse_header(rest.substr(0, end), length, error)) {
    pos_ += end + 4;
    return Status::Error;
  }
  if (length > kMaxBodyBytes) {
    error = fmt::format("message of {} bytes is longer than the {} bytes accepted", length, kMaxBodyBytes);
    pos_ += end + 4;
    skipping_ = length;
    return Status::Error;
  }
  if (rest.size() - end - 4 < length) return Status::NeedMore;
  body.assign(rest.substr(end + 4, length));
  pos_ += end + 4 + length;
  return Status::Message;
}

std::string frame(std::string_view body) {
  std::string out = fmt::format("Content-Length: {}\r\n\r\n", body.size());
  out.append(body);
  return out;
}

}  // namespace rts::lsp
