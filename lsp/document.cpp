#include "lsp/document.hpp"

#include <algorithm>
#include <filesystem>

namespace rts::lsp {

namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::string uri_to_path(const std::string& uri) {
  constexpr std::string_view kFile = "file://";
  if (uri.compare(0, kFile.size(), kFile) != 0) {
    std::size_t cut = uri.find_last_of(":/");
    return cut == std::string::npos ? uri : uri.substr(cut + 1);
  }
  std::string path;
  for (std::size_t i = kFile.size(); i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex_value(uri[i + 1]) >= 0 && hex_value(uri[i + 2]) >= 0) {
      path += static_cast<char>(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
      i += 2;
    } else {
      path += uri[i];
    }
  }
  // file://host/path: a host part other than localhost is kept (and will not be found).
  if (path.compare(0, 9, "localhost") == 0) path.erase(0, 9);
  return path;
}

std::string path_to_uri(const std::string& path) {
  std::string abs = path;
  std::error_code ec;
  if (!path.empty() && path[0] != '/') abs = std::filesystem::absolute(path, ec).lexically_normal().string();
  std::string uri = "file://";
  static const char* kHex = "0123456789ABCDEF";
  for (unsigned char c : abs) {
    bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '/' ||
                 c == '-' || c == '_' || c == '.' || c == '~';
    if (plain) {
      uri += static_cast<char>(c);
    } else {
      uri += '%';
      uri += kHex[c >> 4];
      uri += kHex[c & 15];
    }
  }
  return uri;
}

void apply_change(std::string& text, const LineIndex& lines, bool utf16, bool has_range, Position start,
                  Position end, const std::string& new_text) {
  if (!has_range) {
    text = new_text;
    return;
  }
  std::size_t a = lines.offset(start, utf16), b = lines.offset(end, utf16);
  if (b < a) std::swap(a, b);
  text.replace(a, b - a, new_text);
}

}  // namespace rts::lsp
