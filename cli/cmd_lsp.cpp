// `rts lsp`: the language server on stdin/stdout (lsp/), for any editor's LSP client.
#include "cli/command.hpp"
#include "lsp/stdio.hpp"

namespace rts::cli {

void add_lsp_command(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand("lsp", "Run the language server (LSP 3.17 over stdin/stdout) for editors");
  auto include_paths = std::make_shared<std::vector<std::string>>();
  cmd->add_option("-I", *include_paths, "Add a directory searched by include")->take_all();
  cmd->callback([&ctx, include_paths] {
    lsp::ServerOptions options;
    options.analysis.include_paths = *include_paths;
    ctx.exit_code = lsp::run_stdio(std::move(options));
  });
}

}  // namespace rts::cli
