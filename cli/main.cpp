// The `rts` program: parse, check, eval and render scene files.
#include <unistd.h>

#include <exception>
#include <iostream>
#include <new>
#include <string_view>

#include <CLI/CLI.hpp>

#include "cli/command.hpp"
#include "dist/mpi_session.hpp"
#include "parser/diagnostics.hpp"

int main(int argc, char** argv) {
  using namespace rts;
  // Joins MPI only when mpirun/srun started this process (dist/mpi_session.hpp).
  dist::MpiSession mpi(&argc, &argv);
  CLI::App app{"rts — a scene-description language and ray tracer"};
  app.name("rts");
  app.set_version_flag("--version", std::string("rts ") + RTS_VERSION);
  // At most one command; "none" is reported after parsing, so that an unknown flag or command
  // is named in the message rather than hidden behind "a subcommand is required".
  app.require_subcommand(0, 1);
  app.fallthrough(false);

  cli::CommandContext ctx;
  ctx.color = isatty(STDERR_FILENO) && getenv("NO_COLOR") == nullptr;
  ctx.args.assign(argv + 1, argv + argc);
  ctx.mpi = &mpi;
  cli::add_parse_command(app, ctx);
  cli::add_check_command(app, ctx);
  cli::add_eval_command(app, ctx);
  cli::add_render_command(app, ctx);
  cli::add_converge_command(app, ctx);
  cli::add_import_command(app, ctx);
  cli::add_fmt_command(app, ctx);
  cli::add_lsp_command(app, ctx);

  // A first word that is neither an option nor a command is most likely a misspelt command.
  auto is_command = [&](const std::string& word) {
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
      if (sub->get_name() == word) return true;
    return false;
  };
  if (argc > 1 && argv[1][0] != '-' && !is_command(argv[1])) {
    std::cerr << "rts: unknown command '" << argv[1]
              << "' (expected one of: parse, check, eval, render, converge, import, fmt, lsp)\n";
    std::cerr << "Run 'rts --help' for usage.\n";
    return kExitUsage;
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Unknown flags, missing arguments, bad values: a usage error, never exit 1.
    std::cerr << "rts: " << e.what() << "\n";
    std::cerr << "Run 'rts --help' or 'rts <command> --help' for usage.\n";
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    // Not a bug: the system (or `ulimit -v`) refused memory where no command said more.
    std::cerr << "rts: out of memory: the system refused memory (lower what the scene builds, or check ulimit -v)\n";
    return kExitRenderError;
  } catch (const std::exception& e) {
    // oneTBB reports a worker it could not start as a runtime_error naming pthread_create.
    if (std::string_view(e.what()).starts_with("pthread_create")) {
      std::cerr << "rts: out of resources: could not start a worker thread (" << e.what()
                << "; check ulimit -v and ulimit -u, or try --threads 1)\n";
      return kExitRenderError;
    }
    std::cerr << "rts: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
  if (app.get_subcommands().empty()) {
    std::cerr << "rts: no command given (expected one of: parse, check, eval, render, converge, import, fmt, lsp)\n";
    std::cerr << "Run 'rts --help' for usage.\n";
    return kExitUsage;
  }
  return ctx.exit_code;
}
