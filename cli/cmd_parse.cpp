// `rts parse FILE [--locations] [--quiet]`: parses a scene file and prints its syntax tree.
#include <iostream>
#include <memory>
#include <string>

#include "cli/command.hpp"
#include "parser/diagnostics.hpp"
#include "parser/parser.hpp"
#include "parser/source.hpp"

namespace rts::cli {
namespace {

struct ParseOptions {
  std::string file;
  bool locations = false;
  bool quiet = false;
};

int run_parse(const ParseOptions& opts, bool color) {
  SourceManager sources;
  try {
    const SourceFile* file = sources.load(opts.file);
    // Deliberately never freed, like clang's -disable-free: the process ends right after,
    // and freeing a big scene's millions of nodes one by one takes as long as parsing them.
    // The static pointer keeps it reachable, so leak checkers stay quiet.
    static ast::Program* kept_until_exit = nullptr;
    kept_until_exit = new ast::Program(parse(*file));
    if (!opts.quiet) print_ast(std::cout, *kept_until_exit, opts.locations);
    std::cout.flush();
    return kExitOk;
  } catch (const SourceError& e) {
    std::cerr << e.message << '\n';
    return kExitLanguageError;
  } catch (const LanguageError& e) {
    DiagnosticSink sink(std::cerr, color);
    sink.report(e.diag);
    return kExitLanguageError;
  }
}

}  // namespace

void add_parse_command(CLI::App& app, CommandContext& ctx) {
  auto opts = std::make_shared<ParseOptions>();
  CLI::App* cmd = app.add_subcommand("parse", "Parse a scene file and print its syntax tree");
  cmd->add_option("file", opts->file, "Scene file (.rts)")->required();
  cmd->add_flag("--locations", opts->locations, "Show @line:col after every node");
  cmd->add_flag("-q,--quiet,--check-only", opts->quiet,
                "Only check the syntax: print nothing, report errors (for timing the parser)");
  cmd->callback([opts, &ctx] { ctx.exit_code = run_parse(*opts, ctx.color); });
}

}  // namespace rts::cli
