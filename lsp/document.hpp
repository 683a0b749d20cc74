// An open buffer: its text as the editor last sent it, and the analysis of that text (redone
// lazily: after edits, before the next request or when the input goes quiet).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "lsp/analysis.hpp"
#include "lsp/text_scan.hpp"

namespace rts::lsp {

struct Document {
  std::string uri;
  std::string path;  // the file the URI names (includes resolve relative to it)
  std::string text;
  int64_t version = 0;
  bool dirty = true;  // edited since the last analysis
  // The last analysis and the line index of ITS text (the file it owns), which positions in
  // results refer to.
  std::unique_ptr<Analysis> analysis;
  LineIndex lines;
};

// file:///a%20b/c.rts ↔ /a b/c.rts. Other schemes (untitled:) give the URI's last part, so a
// new buffer's includes resolve from the current folder.
std::string uri_to_path(const std::string& uri);
std::string path_to_uri(const std::string& path);

// Applies one LSP content change (a range edit, or the whole text) to `text`.
void apply_change(std::string& text, const LineIndex& lines, bool utf16, bool has_range, Position start,
                  Position end, const std::string& new_text);

}  // namespace rts::lsp
