// Each `rts` subcommand lives in its own file and registers itself on the CLI11 app.
// A command's callback returns the process exit code through `CommandContext::exit_code`.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace rts::dist {
class MpiSession;
}

namespace rts::cli {

struct CommandContext {
  int exit_code = 0;
  bool color = false;  // stderr is a terminal: colored diagnostics
  std::vector<std::string> args;  // the command line without the program name (frame manifests)
  const dist::MpiSession* mpi = nullptr;  // this process's MPI rank (inactive without mpirun)
};

void add_parse_command(CLI::App& app, CommandContext& ctx);   // cli/cmd_parse.cpp
void add_check_command(CLI::App& app, CommandContext& ctx);   // cli/cmd_eval.cpp
void add_eval_command(CLI::App& app, CommandContext& ctx);    // cli/cmd_eval.cpp
void add_render_command(CLI::App& app, CommandContext& ctx);  // cli/cmd_render.cpp
void add_converge_command(CLI::App& app, CommandContext& ctx);  // cli/cmd_converge.cpp
void add_import_command(CLI::App& app, CommandContext& ctx);  // cli/cmd_import.cpp
void add_fmt_command(CLI::App& app, CommandContext& ctx);     // cli/cmd_fmt.cpp
void add_lsp_command(CLI::App& app, CommandContext& ctx);     // cli/cmd_lsp.cpp

}  // namespace rts::cli
