#include "runtime/includes.hpp"

#include <chrono>

#include <fmt/format.h>

#include "parser/diagnostics.hpp"
#include "parser/parser.hpp"
#include "runtime/stdlib_path.hpp"

namespace rts::runtime {

namespace fs = std::filesystem;

namespace {
// Included files must be named like scenes: rts never shows excerpts of other files (a
// mistyped `include "/etc/shadow"` would otherwise print its first line in a syntax error).
bool is_scene_file_name(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  return ext == ".rts" || ext == ".inc";
}

[[noreturn]] void fail(SourceLoc loc, std::string message) { throw LanguageError(loc, std::move(message)); }
}  // namespace

const render::ReadPolicy& Includes::restrict_reads(const SourceFile& main) {
  if (options_.restrict_reads) {
    std::vector<std::string> roots;
    std::string main_dir = fs::path(main.path()).parent_path().string();
    roots.push_back(main_dir.empty() ? "." : main_dir);
    roots.insert(roots.end(), options_.include_paths.begin(), options_.include_paths.end());
    if (!stdlib_dir().empty()) roots.push_back(stdlib_dir());
    roots.push_back(".");
    roots.insert(roots.end(), options_.allow_read.begin(), options_.allow_read.end());
    read_policy_ = render::ReadPolicy(roots);
  }
  return read_policy_;
}

const ast::Program& Includes::add_program(const SourceFile& file) {
  files_by_name_[file.path().c_str()] = &file;
  auto start = std::chrono::steady_clock::now();
  ast::Program p = rts::parse(file);
  parse_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  programs_.push_back(std::move(p));
  return programs_.back();
}

const ast::Program& Includes::open_main(const SourceFile& main) {
  const ast::Program& program = add_program(main);
  std::error_code ec;
  chain_.push_back(fs::weakly_canonical(main.path(), ec).string());
  parsed_[chain_.back()] = &program;
  return program;
}

const ast::Program& Includes::parse_text(const std::string& name, const std::string& text, const SourceFile*& file) {
  file = sources_.add(name, text);
  return add_program(*file);
}

bool Includes::is_open(const std::string& canonical) const {
  for (const std::string& open : chain_)
    if (open == canonical) return true;
  return false;
}

Includes::Found Includes::find(const ast::IncludeStmt& stmt) {
  const std::string path(stmt.path);
  fs::path including_dir = fs::path(stmt.loc.file()->path()).parent_path();
  std::vector<fs::path> candidates;
  if (fs::path(path).is_absolute()) {
    candidates.emplace_back(path);
  } else if (!names_standard_library(path)) {
    candidates.push_back(including_dir / path);
    for (const std::string& dir : options_.include_paths) candidates.push_back(fs::path(dir) / path);
  }
  // Then the standard library (docs/library.md): after the scene's own files, so they win.
  for (fs::path& c : standard_library_candidates(stdlib_dir(), path)) candidates.push_back(std::move(c));
  std::error_code ec;
  const fs::path* found = nullptr;
  for (const fs::path& c : candidates) {
    if (fs::is_regular_file(c, ec)) {
      found = &c;
      break;
    }
    // A directory, FIFO or device of that name is named as such (reading a FIFO would block).
    if (std::string kind = render::non_regular_kind(c.string()); !kind.empty())
      fail(stmt.loc, fmt::format("cannot include '{}': '{}' is {}, not a scene file", path, c.string(), kind));
  }
  if (!found) {
    if (names_standard_library(path))
      fail(stmt.loc, fmt::format("cannot find include file '{}' in the standard library{}", path,
                              stdlib_dir().empty() ? " (no standard library folder was found: set RTS_STDLIB)"
                                                   : " " + stdlib_dir()));
    std::string where = "next to this file";
    if (!options_.include_paths.empty()) {
      where += " or in the -I folders";
      for (std::size_t i = 0; i < options_.include_paths.size(); ++i)
        where += (i ? ", " : " ") + options_.include_paths[i];
    }
    if (stdlib_dir().empty())
      where += " (nor a standard library: none was found; set RTS_STDLIB to its folder)";
    else if (fs::path(path).extension() == ".inc" && !fs::path(path).has_parent_path())
      where += fmt::format(" (rts's standard library has no '{}' either; docs/library.md lists its files)",
                           fs::path(path).stem().string());
    fail(stmt.loc, fmt::format("cannot find include file '{}' {}", path, where));
  }
  std::string canonical = fs::weakly_canonical(*found, ec).string();
  if (!read_policy_.allows(found->string())) fail(stmt.loc, read_policy_.refusal(path, found->string()));
  if (!is_scene_file_name(canonical))
    fail(stmt.loc, fmt::format("cannot include '{}': included files must be scene files named *.rts or *.inc{}", path,
                            canonical != found->lexically_normal().string()
                                ? fmt::format(" (it leads to '{}')", canonical)
                                : ""));
  return Found{*found, std::move(canonical)};
}

const ast::Program& Includes::parse(const ast::IncludeStmt& s, const Found& f) {
  if (auto it = parsed_.find(f.canonical); it != parsed_.end()) return *it->second;
  const SourceFile* file;
  try {
    file = sources_.load(f.path.lexically_normal().string());
  } catch (const SourceError& e) {
    fail(s.loc, fmt::format("cannot read include file '{}': {}", s.path, e.message));
  }
  const ast::Program& program = add_program(*file);
  parsed_[f.canonical] = &program;
  return program;
}

const std::string& Includes::stdlib_dir() {
  if (!stdlib_found_) {
    stdlib_dir_ = options_.stdlib_dir.empty() ? find_standard_library() : options_.stdlib_dir;
    stdlib_found_ = true;
  }
  return stdlib_dir_;
}

}  // namespace rts::runtime
