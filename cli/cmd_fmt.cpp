// `rts fmt FILE... [--check]`, `rts fmt -`: rewrites scene files in the canonical layout
// (parser/format.hpp). A file that does not parse is left untouched and its error reported.
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "parser/diagnostics.hpp"
#include "parser/format.hpp"
#include "parser/source.hpp"

namespace rts::cli {
namespace {

struct FmtOptions {
  std::vector<std::string> files;
  bool check = false;
};

// Written beside the file and renamed over it, so that an interrupted run never leaves a
// half-written scene.
bool write_atomically(const std::string& path, const std::string& text) {
  std::string tmp = path + ".rts-fmt.tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      return false;
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

enum class Outcome { Unchanged, Changed, Failed };

Outcome format_one(SourceManager& sources, const std::string& path, const FmtOptions& opts, bool color) {
  bool from_stdin = path == "-";
  try {
    const SourceFile* file;
    if (from_stdin) {
      std::string text{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
      if (std::size_t bad = find_invalid_utf8(text); bad != std::string::npos)
        throw SourceError("<stdin>: invalid UTF-8 or a NUL byte at byte " + std::to_string(bad));
      file = sources.add("<stdin>", std::move(text));
    } else {
      file = sources.load(path);
    }
    std::string out = format_source(*file);
    bool changed = out != file->text();
    if (from_stdin) {
      if (!opts.check) std::cout << out << std::flush;
    } else if (changed && !opts.check && !write_atomically(path, out)) {
      std::cerr << "rts fmt: cannot write " << path << "\n";
      return Outcome::Failed;
    }
    if (changed && opts.check) std::cout << (from_stdin ? "<stdin>" : path) << "\n";
    return changed ? Outcome::Changed : Outcome::Unchanged;
  } catch (const SourceError& e) {
    std::cerr << e.message << '\n';
  } catch (const LanguageError& e) {
    DiagnosticSink sink(std::cerr, color);
    sink.report(e.diag);
  } catch (const std::logic_error& e) {
    std::cerr << e.what() << '\n';
  }
  return Outcome::Failed;
}

int run_fmt(const FmtOptions& opts, bool color) {
  SourceManager sources;
  bool failed = false, changed = false;
  for (const std::string& path : opts.files) {
    Outcome o = format_one(sources, path, opts, color);
    failed |= o == Outcome::Failed;
    changed |= o == Outcome::Changed;
  }
  if (failed || (opts.check && changed)) return kExitLanguageError;
  return kExitOk;
}

}  // namespace

void add_fmt_command(CLI::App& app, CommandContext& ctx) {
  auto opts = std::make_shared<FmtOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fmt", "Rewrite scene files in the canonical layout (docs/language.md, \"Formatting\")");
  cmd->add_option("files", opts->files, "Scene files; '-' reads standard input and writes standard output")
      ->required();
  cmd->add_flag("--check", opts->check,
                "Change nothing: list the files that would change and exit 1 if there are any");
  cmd->callback([opts, &ctx] { ctx.exit_code = run_fmt(*opts, ctx.color); });
}

}  // namespace rts::cli
