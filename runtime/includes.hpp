// The files a scene is made of: parsing (timed), the main file, `include` resolution (next to
// the including file, the -I folders, then the standard library), include-once and the cycle
// check, the read policy of --allow-read, and the small files the -D defines are parsed from.
// Internal to runtime/; the interpreter runs what this unit parses. Every failure is a
// located LanguageError.
#pragma once

#include <deque>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "parser/ast.hpp"
#include "parser/source.hpp"
#include "render/scene/resource_limits.hpp"
#include "runtime/evaluator.hpp"

namespace rts::runtime {

class Includes {
 public:
  Includes(SourceManager& sources, const EvalOptions& options) : sources_(sources), options_(options) {}

  // The read policy of --allow-read for a scene whose main file is `main` (everything is
  // allowed unless options.restrict_reads); the builder gets the same one for meshes and images.
  const render::ReadPolicy& restrict_reads(const SourceFile& main);
  // Parses the main file and opens the include chain with it.
  const ast::Program& open_main(const SourceFile& main);
  // Parses `text` as a file of its own called `name` (a -D define), which `file` is set to.
  const ast::Program& parse_text(const std::string& name, const std::string& text, const SourceFile*& file);

  // The file an `include` statement names, found and checked (it exists, is a scene file and
  // may be read), or a located error.
  struct Found {
    std::filesystem::path path;
    std::string canonical;
  };
  Found find(const ast::IncludeStmt& s);
  // The file is being included now (an include cycle) / was included to the end (include once).
  bool is_open(const std::string& canonical) const;
  bool is_done(const std::string& canonical) const { return included_.count(canonical) > 0; }
  // The program of a found file, parsed on first use (programs live as long as this unit:
  // macros point into them).
  const ast::Program& parse(const ast::IncludeStmt& s, const Found& f);
  // Running a found file: enter() before, leave() after it ran to its end.
  void enter(const std::string& canonical) { chain_.push_back(canonical); }
  void leave() {
    included_.insert(std::move(chain_.back()));
    chain_.pop_back();
  }

  // The loaded file whose path() is `name` (the SourceRefs of builder errors), or null.
  const SourceFile* file_named(const char* name) const {
    auto it = files_by_name_.find(name);
    return it == files_by_name_.end() ? nullptr : it->second;
  }
  double parse_seconds() const { return parse_seconds_; }  // of every file parsed

 private:
  const ast::Program& add_program(const SourceFile& file);
  // The standard library's folder (options.stdlib_dir, else found once); "" if none.
  const std::string& stdlib_dir();

  SourceManager& sources_;
  const EvalOptions& options_;
  render::ReadPolicy read_policy_;
  double parse_seconds_ = 0.0;
  std::string stdlib_dir_;  // see stdlib_dir()
  bool stdlib_found_ = false;
  std::deque<ast::Program> programs_;                  // kept alive: macros point into them
  std::map<std::string, const ast::Program*> parsed_;  // canonical path → program
  std::vector<std::string> chain_;                     // canonical paths being run
  std::set<std::string> included_;                     // canonical paths run to the end
  std::unordered_map<const char*, const SourceFile*> files_by_name_;
};

}  // namespace rts::runtime
