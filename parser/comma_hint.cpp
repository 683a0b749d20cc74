#include "parser/comma_hint.hpp"

#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "grammar/lexical.hpp"

namespace rts {
namespace {

// POV-Ray's positional arguments, in its order, as rts property names (docs/shapes.md).
struct Positional {
  std::string_view kind;
  std::vector<std::string_view> names;
};
const std::vector<Positional>& positional_forms() {
  static const std::vector<Positional> forms = {
      {"sphere", {"center", "radius"}},
      {"box", {"min", "max"}},
      {"cylinder", {"from", "to", "radius"}},
      {"cone", {"from", "radius_from", "to", "radius_to"}},
      {"plane", {"normal", "offset"}},
      {"torus", {"major", "minor"}},
      {"triangle", {"v0", "v1", "v2"}},
      {"disc", {"center", "normal", "radius"}},
  };
  return forms;
}

// A rewritten line longer than this is not shown (it would not help).
constexpr std::size_t kMaxRewrite = 160;

std::size_t offset_of(const SourceFile& f, SourceLoc loc) {
  std::string_view line = f.line_text(loc.line());
  return static_cast<std::size_t>(line.data() - f.text().data()) + loc.col() - 1;
}

std::string trim_collapse(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (grammar::is_blank(c)) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

// The block's inside split at its top-level commas; empty when the block is not closed or
// holds comments or strings (no rewrite is offered then).
std::vector<std::string> top_level_parts(std::string_view text, std::size_t open) {
  std::vector<std::string> parts;
  int depth = 0;
  std::size_t start = open + 1;
  for (std::size_t i = open + 1; i < text.size(); ++i) {
    char c = text[i];
    if (c == '"' || (c == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*'))) return {};
    if (c == '{' || c == '(' || c == '[') ++depth;
    else if (c == ')' || c == ']') --depth;
    else if (c == '}') {
      if (depth == 0) {
        parts.push_back(trim_collapse(text.substr(start, i - start)));
        return parts;
      }
      --depth;
    } else if (c == ',' && depth == 0) {
      // '<a, b>' commas: a vector's components. Count '<' and '>' in this part to tell.
      std::string_view so_far = text.substr(start, i - start);
      long lt = 0, gt = 0;
      for (char d : so_far) lt += d == '<', gt += d == '>';
      if (lt > gt) continue;
      parts.push_back(trim_collapse(so_far));
      start = i + 1;
    }
  }
  return {};
}

bool is_named(std::string_view part) {
  std::size_t i = 0;
  if (part.empty() || !grammar::is_ident_first(part[0])) return false;
  while (i < part.size() && grammar::is_ident_char(part[i])) ++i;
  while (i < part.size() && part[i] == ' ') ++i;
  return i + 1 < part.size() && part[i] == '=' && part[i + 1] != '=';
}

}  // namespace

Diagnostic comma_in_block_error(const SourceFile& file, SourceLoc open, std::size_t comma) {
  std::string_view text = file.text();
  std::size_t brace = offset_of(file, open);
  // The block's kind: the word before '{' (`sphere`, or `with` for an override block).
  std::size_t k = brace;
  while (k > 0 && grammar::is_blank(text[k - 1])) --k;
  std::size_t kind_end = k;
  while (k > 0 && grammar::is_ident_char(text[k - 1])) --k;
  std::string kind(text.substr(k, kind_end - k));

  // Which habit: the part before the comma names a property, or it does not.
  std::size_t part_start = comma;
  for (int depth = 0; part_start > brace + 1; --part_start) {
    char c = text[part_start - 1];
    if (c == ')' || c == ']' || c == '}' || c == '>') ++depth;
    else if (c == '(' || c == '[' || c == '{' || c == '<') --depth;
    if (depth < 0) break;
    if (depth == 0 && (c == ',' || c == '\n')) break;
  }
  bool named = is_named(trim_collapse(text.substr(part_start, comma - part_start)));
  std::vector<std::string> parts = top_level_parts(text, brace);

  Diagnostic d;
  d.loc = SourceLoc::whole(&file);
  std::string rewrite;
  if (named) {
    d.message = "properties are separated by spaces or newlines, not commas";
    bool all_named = !parts.empty();
    for (const std::string& p : parts) all_named = all_named && is_named(p);
    if (all_named) {
      rewrite = kind + " {";
      for (std::size_t i = 0; i < parts.size(); ++i) rewrite += (i == 0 ? " " : "  ") + parts[i];
      rewrite += " }";
    }
  } else {
    d.message = "rts properties are named, not positional: write 'name = value' for each, "
                "separated by spaces or newlines";
    for (const Positional& form : positional_forms()) {
      if (form.kind != kind) continue;
      if (parts.size() != form.names.size()) break;
      rewrite = kind + " {";
      for (std::size_t i = 0; i < parts.size(); ++i)
        rewrite += fmt::format("{}{} = {}", i == 0 ? " " : "  ", form.names[i], parts[i]);
      rewrite += " }";
    }
    if (rewrite.empty() && !kind.empty() && kind != "with")
      d.message += fmt::format(" (docs/shapes.md lists the properties of '{}')", kind);
  }
  if (!rewrite.empty() && rewrite.size() <= kMaxRewrite)
    d.notes.push_back(Note{open, fmt::format("write it as: {}", rewrite)});
  else
    d.notes.push_back(Note{open, "in the block opened here"});
  return d;
}

}  // namespace rts
