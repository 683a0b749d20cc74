// Hover, completion, go to definition, document symbols, signature help and formatting. Each
// reads the document's last analysis (parse tree, names, values) and its text; completion and
// signature help read the text around the cursor, so they work while the buffer does not parse.
#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "lsp/builtin_docs.hpp"
#include "lsp/server.hpp"
#include "parser/format.hpp"
#include "parser/parser.hpp"
#include "render/builder/block_properties.hpp"
#include "render/builder/scene_builder.hpp"
#include "runtime/stdlib_path.hpp"

namespace rts::lsp {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

// LSP's CompletionItemKind and SymbolKind values used here.
constexpr int kItemFunction = 3, kItemVariable = 6, kItemClass = 7, kItemProperty = 10, kItemKeyword = 14;
constexpr int kSymbolFunction = 12, kSymbolVariable = 13, kSymbolObject = 19;

// Included files searched for names, at most this many, this deep, this big.
constexpr std::size_t kMaxIncludedFiles = 32;
constexpr int kMaxIncludeDepth = 8;
constexpr uintmax_t kMaxIncludedBytes = 4u << 20;
// A let's text shown on hover is cut here.
constexpr std::size_t kMaxShownDeclarationBytes = 300;

bool is_block_kind(std::string_view word) {
  return render::SceneBuilder::category(word) != render::BlockCategory::Unknown;
}

// The block kind whose braces enclose the point, when the innermost brace is a block's.
std::string enclosing_block(const ScanState& st) {
  for (auto it = st.open.rbegin(); it != st.open.rend(); ++it)
    if (it->ch == '{') return is_block_kind(it->head) ? it->head : std::string();
  return {};
}

const std::string& standard_library() {
  static const std::string dir = runtime::find_standard_library();
  return dir;
}

// The file `include "name"` in `from` reads: as the interpreter searches (the including file's
// folder, the -I folders, then the standard library); "" when none exists.
std::string resolve_include(const std::string& from, const std::string& name, const std::vector<std::string>& dirs) {
  std::vector<fs::path> candidates;
  if (!runtime::names_standard_library(name)) {
    fs::path p(name);
    if (p.is_absolute()) {
      candidates.push_back(p);
    } else {
      candidates.push_back(fs::path(from).parent_path() / p);
      for (const std::string& d : dirs) candidates.push_back(fs::path(d) / p);
    }
  }
  if (!standard_library().empty())
    for (const fs::path& c : runtime::standard_library_candidates(standard_library(), name)) candidates.push_back(c);
  for (const fs::path& c : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(c, ec)) return c.lexically_normal().string();
  }
  return {};
}

// An included file, parsed and indexed for its names.
struct IncludedFile {
  std::unique_ptr<SourceManager> sources = std::make_unique<SourceManager>();
  const SourceFile* file = nullptr;
  std::optional<ast::Program> program;
  SymbolIndex symbols;
};

// Every file the analysed buffer includes, transitively (bounded), that parses.
std::vector<IncludedFile> load_includes(const std::string& path, const SymbolIndex& symbols,
                                        const std::vector<std::string>& dirs) {
  std::vector<IncludedFile> out;
  std::set<std::string> seen{fs::weakly_canonical(path).string()};
  std::function<void(const std::string&, const SymbolIndex&, int)> walk = [&](const std::string& from,
                                                                               const SymbolIndex& index, int depth) {
    if (depth > kMaxIncludeDepth) return;
    for (const IncludeRef& inc : index.includes) {
      if (out.size() >= kMaxIncludedFiles) return;
      std::string file = resolve_include(from, inc.path, dirs);
      std::error_code ec;
      if (file.empty() || !seen.insert(fs::weakly_canonical(file, ec).string()).second) continue;
      if (fs::file_size(file, ec) > kMaxIncludedBytes || ec) continue;
      IncludedFile f;
      try {
        f.file = f.sources->load(file);
        f.program = parse(*f.file);
        f.symbols = index_program(*f.program, f.file->text(), LineIndex(f.file->text()));
      } catch (const std::exception&) {
        continue;  // unreadable or broken: its own diagnostics say so when it is open
      }
      out.push_back(std::move(f));
      walk(out.back().file->path(), out.back().symbols, depth + 1);
    }
  };
  walk(path, symbols, 0);
  return out;
}

// A top-level declaration of `name` in the included files.
std::pair<const IncludedFile*, const Declaration*> find_included(const std::vector<IncludedFile>& files,
                                                                 std::string_view name) {
  for (const IncludedFile& f : files)
    for (const Declaration& d : f.symbols.declarations)
      if (d.top_level && d.name == name) return {&f, &d};
  return {nullptr, nullptr};
}

std::string property_markdown(std::string_view kind, const render::PropertyInfo& p) {
  return fmt::format("**{}** ({} property): {}\n\nDefault: {}\n\n{}", p.name, kind, p.type, p.default_value,
                     p.meaning);
}

std::string block_markdown(std::string_view kind) {
  const render::BlockInfo* info = render::find_block_info(kind);
  if (!info) return fmt::format("**{}** block", kind);
  std::string s = fmt::format("**{}** — {}\n\n", kind, info->meaning);
  for (const render::PropertyInfo& p : info->properties) s += fmt::format("- `{}`: {}\n", p.name, p.type);
  return s;
}

// The `//` comment lines right above `begin`: a macro's or a let's description.
std::string comment_above(std::string_view text, std::size_t begin) {
  std::vector<std::string_view> lines;
  std::size_t line_start = text.rfind('\n', begin == 0 ? 0 : begin - 1);
  while (line_start != std::string_view::npos && line_start > 0) {
    std::size_t prev = text.rfind('\n', line_start - 1);
    std::size_t s = prev == std::string_view::npos ? 0 : prev + 1;
    std::string_view line = text.substr(s, line_start - s);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (line.substr(0, 2) != "//") break;
    line.remove_prefix(2);
    if (!line.empty() && line.front() == ' ') line.remove_prefix(1);
    lines.push_back(line);
    if (prev == std::string_view::npos) break;
    line_start = prev;
  }
  std::string out;
  for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
    out.append(*it);
    out += '\n';
  }
  return out;
}

std::string declaration_markdown(const Declaration& d, std::string_view text, const std::vector<GlobalValue>* globals) {
  std::string s;
  switch (d.kind) {
    case Declaration::Let: {
      std::string_view decl = text.substr(d.stmt_begin, d.stmt_end - d.stmt_begin);
      std::string shown(decl.substr(0, kMaxShownDeclarationBytes));
      if (decl.size() > shown.size()) shown += " …";
      s = fmt::format("```rts\n{}\n```\n", shown);
      if (globals && d.top_level)
        for (const GlobalValue& g : *globals)
          if (g.name == d.name) s += fmt::format("\nValue: `{}`\n", g.value);
      break;
    }
    case Declaration::Macro:
      s = fmt::format("```rts\nmacro {}\n```\n", macro_signature(d, text, nullptr));
      break;
    case Declaration::Param:
      s = fmt::format("`{}`: parameter of macro `{}`\n", d.name, d.macro ? *d.macro->name : std::string());
      break;
    case Declaration::LoopVar:
      s = fmt::format("`{}`: loop variable\n", d.name);
      break;
  }
  if (d.kind == Declaration::Let || d.kind == Declaration::Macro) {
    std::string doc = comment_above(text, d.stmt_begin);
    if (!doc.empty()) s += "\n" + doc;
  }
  return s;
}

json markdown(std::string value) { return {{"kind", "markdown"}, {"value", std::move(value)}}; }

}  // namespace

nlohmann::json Server::hover(Document& doc, std::size_t offset) {
  const Analysis& a = *doc.analysis;
  std::string_view text = a.file->text();
  std::size_t ws = 0;
  std::string_view word = word_at(text, offset, &ws);
  if (word.empty()) return nullptr;
  const std::size_t we = ws + word.size();
  ScanState st = scan_to(text, ws);
  if (st.in_comment || st.in_string) return nullptr;
  const json range = range_of(doc, ws, we);
  auto answer = [&](std::string md) { return json{{"contents", markdown(std::move(md))}, {"range", range}}; };

  // A property name: `radius = ...` inside a block that takes it.
  std::size_t after = we;
  while (after < text.size() && (text[after] == ' ' || text[after] == '\t')) ++after;
  const bool assigned = after < text.size() && text[after] == '=' && (after + 1 >= text.size() || text[after + 1] != '=');
  const bool in_call = !st.open.empty() && st.open.back().ch == '(';
  if (assigned && !in_call) {
    std::string kind = enclosing_block(st);
    if (const render::BlockInfo* info = kind.empty() ? nullptr : render::find_block_info(kind))
      for (const render::PropertyInfo& p : info->properties)
        if (p.name == word) return answer(property_markdown(kind, p));
  }
  if (is_block_kind(word) && next_non_blank(text, we) == '{') return answer(block_markdown(word));
  if (const Declaration* d = a.symbols.resolve(word, ws))
    return answer(declaration_markdown(*d, text, a.evaluated ? &a.globals : nullptr));
  if (next_non_blank(text, we) == '(')
    if (const BuiltinDoc* b = find_builtin_doc(word))
      return answer(fmt::format("```rts\n{}\n```\nBuilt-in: {}", b->signature, b->meaning));
  std::vector<IncludedFile> included = load_includes(doc.path, a.symbols, options_.analysis.include_paths);
  if (auto [f, d] = find_included(included, word); d)
    return answer(declaration_markdown(*d, f->file->text(), nullptr) + fmt::format("\nFrom `{}`", f->file->path()));
  if (const BuiltinDoc* b = find_builtin_doc(word))
    return answer(fmt::format("```rts\n{}\n```\nBuilt-in: {}", b->signature, b->meaning));
  if (is_block_kind(word)) return answer(block_markdown(word));
  return nullptr;
}

nlohmann::json Server::completion(Document& doc, std::size_t offset) {
  const Analysis& a = *doc.analysis;
  std::string_view text = a.file->text();
  ScanState st = scan_to(text, offset);
  json items = json::array();
  if (st.in_comment || st.in_string) return {{"isIncomplete", false}, {"items", items}};
  std::size_t ps = offset;
  while (ps > 0 && is_word_char(text[ps - 1])) --ps;
  const std::string_view prefix = text.substr(ps, offset - ps);
  if (ps > 0 && text[ps - 1] == '.') {  // a member: vectors and colors
    for (const char* m : {"x", "y", "z", "r", "g", "b"})
      items.push_back({{"label", m}, {"kind", kItemProperty}});
    return {{"isIncomplete", false}, {"items", items}};
  }
  std::set<std::string> labels;
  auto add = [&](std::string_view label, int kind, std::string detail, std::string sort, json extra = {}) {
    if (label.substr(0, prefix.size()) != prefix || !labels.insert(std::string(label)).second) return;
    json item = {{"label", label}, {"kind", kind}, {"sortText", sort + std::string(label)}};
    if (!detail.empty()) item["detail"] = std::move(detail);
    if (extra.is_object()) item.update(extra);
    items.push_back(std::move(item));
  };
  const char before = previous_non_blank_on_line(text, ps);
  const bool value_position = before == '=' || before == '(' || before == ',' || before == '+' || before == '-' ||
                              before == '*' || before == '/' || before == '<' || before == '[';
  const std::string kind = enclosing_block(st);
  if (!kind.empty() && !value_position)
    if (const render::BlockInfo* info = render::find_block_info(kind))
      for (const render::PropertyInfo& p : info->properties)
        add(p.name, kItemProperty, std::string(p.type), "0",
            {{"insertText", std::string(p.name) + " = "},
             {"documentation", markdown(fmt::format("{}\n\nDefault: {}", p.meaning, p.default_value))}});
  for (const Declaration* d : a.symbols.visible_at(offset))
    add(d->name, d->kind == Declaration::Macro ? kItemFunction : kItemVariable,
        d->kind == Declaration::Macro ? "macro " + macro_signature(*d, text, nullptr) : std::string(), "1");
  for (const IncludedFile& f : load_includes(doc.path, a.symbols, options_.analysis.include_paths))
    for (const Declaration& d : f.symbols.declarations)
      if (d.top_level)
        add(d.name, d.kind == Declaration::Macro ? kItemFunction : kItemVariable,
            fmt::format("from {}", fs::path(f.file->path()).filename().string()), "2");
  for (std::string_view k : render::SceneBuilder::block_kinds()) add(k, kItemClass, "block", "3");
  for (const BuiltinDoc& b : builtin_docs()) add(b.name, kItemFunction, std::string(b.signature), "4");
  if (!value_position)
    for (std::string_view k : keywords()) add(k, kItemKeyword, "", "5");
  return {{"isIncomplete", false}, {"items", items}};
}

nlohmann::json Server::definition(Document& doc, std::size_t offset) {
  const Analysis& a = *doc.analysis;
  std::string_view text = a.file->text();
  for (const IncludeRef& inc : a.symbols.includes)
    if (offset >= inc.begin && offset <= inc.end) {
      std::string file = resolve_include(doc.path, inc.path, options_.analysis.include_paths);
      if (file.empty()) return nullptr;
      return {{"uri", path_to_uri(file)},
              {"range", {{"start", {{"line", 0}, {"character", 0}}}, {"end", {{"line", 0}, {"character", 0}}}}}};
    }
  std::size_t ws = 0;
  std::string_view word = word_at(text, offset, &ws);
  if (word.empty()) return nullptr;
  if (const Declaration* d = a.symbols.resolve(word, ws)) return location_in(*a.file, d->begin, d->end);
  std::vector<IncludedFile> included = load_includes(doc.path, a.symbols, options_.analysis.include_paths);
  if (auto [f, d] = find_included(included, word); d) return location_in(*f->file, d->begin, d->end);
  return nullptr;
}

nlohmann::json Server::document_symbols(Document& doc) {
  const Analysis& a = *doc.analysis;
  std::string_view text = a.file->text();
  struct Entry {
    std::size_t begin, end, sel_begin, sel_end;
    std::string name, detail;
    int kind;
  };
  std::vector<Entry> entries;
  for (const Declaration& d : a.symbols.declarations) {
    if (d.kind == Declaration::Let && d.top_level)
      entries.push_back({d.stmt_begin, d.stmt_end, d.begin, d.end, d.name, "let", kSymbolVariable});
    if (d.kind == Declaration::Macro)
      entries.push_back(
          {d.stmt_begin, d.stmt_end, d.begin, d.end, d.name, "macro " + macro_signature(d, text, nullptr), kSymbolFunction});
  }
  for (const PlacedObject& o : a.symbols.objects)
    entries.push_back({o.begin, o.end, o.begin, token_end(text, o.begin), o.kind, "placed", kSymbolObject});
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) { return x.begin < y.begin; });
  json out = json::array();
  for (const Entry& e : entries)
    out.push_back({{"name", e.name},
                   {"detail", e.detail},
                   {"kind", e.kind},
                   {"range", range_of(doc, e.begin, std::max(e.end, e.sel_end))},
                   {"selectionRange", range_of(doc, e.sel_begin, e.sel_end)}});
  return out;
}

nlohmann::json Server::signature_help(Document& doc, std::size_t offset) {
  const Analysis& a = *doc.analysis;
  std::string_view text = a.file->text();
  ScanState st = scan_to(text, offset);
  if (st.in_comment || st.in_string || st.open.empty() || st.open.back().ch != '(') return nullptr;
  const OpenBracket& call = st.open.back();
  if (call.head.empty()) return nullptr;
  std::string label;
  std::vector<std::string> params;
  std::string documentation;
  if (const Declaration* d = a.symbols.resolve(call.head, call.offset); d && d->kind == Declaration::Macro) {
    label = macro_signature(*d, text, &params);
    documentation = comment_above(text, d->stmt_begin);
  } else if (const BuiltinDoc* b = find_builtin_doc(call.head)) {
    label = std::string(b->signature);
    params = signature_params(b->signature);
    documentation = std::string(b->meaning);
  } else {
    std::vector<IncludedFile> included = load_includes(doc.path, a.symbols, options_.analysis.include_paths);
    auto [f, d] = find_included(included, call.head);
    if (!d || d->kind != Declaration::Macro) return nullptr;
    label = macro_signature(*d, f->file->text(), &params);
    documentation = comment_above(f->file->text(), d->stmt_begin);
  }
  json parameters = json::array();
  for (const std::string& p : params) parameters.push_back({{"label", p}});
  unsigned active = call.commas;
  if (!params.empty() && active >= params.size()) active = static_cast<unsigned>(params.size() - 1);
  json sig = {{"label", label}, {"parameters", parameters}};
  if (!documentation.empty()) sig["documentation"] = markdown(documentation);
  return {{"signatures", json::array({sig})}, {"activeSignature", 0}, {"activeParameter", active}};
}

nlohmann::json Server::formatting(Document& doc) {
  // `rts fmt`'s formatter (parser/format.hpp): the same layout as on the command line.
  const SourceFile& file = *doc.analysis->file;
  const std::string& text = file.text();
  std::string formatted;
  try {
    formatted = format_source(file);
  } catch (const LanguageError& e) {
    throw RequestFailed(fmt::format("cannot format a scene that does not parse: {}:{}: {}", e.diag.loc.line(),
                                    e.diag.loc.col(), e.diag.message));
  }
  if (formatted == text) return json::array();
  return json::array({{{"range", range_of(doc, 0, text.size())}, {"newText", formatted}}});
}

}  // namespace rts::lsp
