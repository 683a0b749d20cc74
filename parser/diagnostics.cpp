#include "parser/diagnostics.hpp"

#include <sstream>

#include <fmt/format.h>

namespace rts {
namespace {

// Source lines longer than this are shown as kExcerptContext bytes either side of the column.
constexpr std::size_t kMaxExcerptBytes = 200;
constexpr std::size_t kExcerptContext = 80;

const char* severity_name(Severity s) {
  switch (s) {
    case Severity::Error: return "error";
    case Severity::Warning: return "warning";
    case Severity::Note: return "note";
  }
  return "error";
}

void print(std::ostream& out, bool color, Severity sev, SourceLoc loc, const std::string& message,
           bool with_source) {
  const char* bold = color ? "\x1b[1m" : "";
  const char* reset = color ? "\x1b[0m" : "";
  const char* sev_color = !color ? "" : sev == Severity::Error ? "\x1b[1;31m"
                                   : sev == Severity::Warning ? "\x1b[1;35m" : "\x1b[1;36m";
  if (loc.valid()) {
    out << bold << loc.file()->path() << ':' << loc.line() << ':' << loc.col() << ":" << reset << ' ';
  } else if (loc.file()) {
    out << bold << loc.file()->path() << ":" << reset << ' ';
  } else {
    out << "rts: ";
  }
  out << sev_color << severity_name(sev) << ':' << reset << ' ' << message << '\n';
  if (!with_source || !loc.valid()) return;
  std::string_view text = loc.file()->line_text(loc.line());
  std::size_t upto = std::min<std::size_t>(loc.col() > 0 ? loc.col() - 1 : 0, text.size());
  // A long line (a generated scene's 900 KB list) is shown as a window around the column.
  const char* before = "";
  const char* after = "";
  if (text.size() > kMaxExcerptBytes) {
    auto is_continuation = [&](std::size_t i) { return i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80; };
    std::size_t begin = upto > kExcerptContext ? upto - kExcerptContext : 0;
    while (begin > 0 && is_continuation(begin)) --begin;
    std::size_t end = std::min(text.size(), begin + 2 * kExcerptContext);
    while (end < text.size() && is_continuation(end)) ++end;
    if (begin > 0) before = "...";
    if (end < text.size()) after = "...";
    upto -= begin;
    text = text.substr(begin, end - begin);
  }
  out << "    " << before << text << after << '\n' << "    " << (*before ? "   " : "");
  // Copy tabs so the caret lines up whatever the terminal's tab width; count UTF-8
  // continuation bytes as no width so the caret sits under the right character.
  for (std::size_t i = 0; i < upto; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\t') out << '\t';
    else if ((c & 0xC0) != 0x80) out << ' ';
  }
  out << (color ? "\x1b[1;32m^\x1b[0m" : "^") << '\n';
}

}  // namespace

void DiagnosticSink::report(const Diagnostic& d) {
  if (d.severity == Severity::Error) ++errors_;
  if (d.severity == Severity::Warning) ++warnings_;
  if (collected_) collected_->push_back(d);
  print(out_, color_, d.severity, d.loc, d.message, true);
  for (const Note& n : d.notes) print(out_, color_, Severity::Note, n.loc, n.message, false);
  out_.flush();
}

void DiagnosticSink::error(SourceLoc loc, const std::string& message) {
  report(Diagnostic{Severity::Error, loc, message, {}});
}

void DiagnosticSink::warning(SourceLoc loc, const std::string& message) {
  report(Diagnostic{Severity::Warning, loc, message, {}});
}

std::string format_diagnostic(const Diagnostic& d) {
  std::ostringstream ss;
  DiagnosticSink sink(ss, false);
  sink.report(d);
  return ss.str();
}

}  // namespace rts
