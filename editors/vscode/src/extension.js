// Starts `rts lsp` for rts files through vscode-languageclient (stdio transport).
const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const config = vscode.workspace.getConfiguration("rts");
  const command = config.get("path", "rts");
  const args = ["lsp"];
  for (const dir of config.get("includePaths", [])) args.push("-I", dir);
  const server = { command, args, transport: TransportKind.stdio };
  client = new LanguageClient(
    "rts",
    "rts language server",
    { run: server, debug: server },
    { documentSelector: [{ scheme: "file", language: "rts" }, { scheme: "untitled", language: "rts" }] }
  );
  context.subscriptions.push(
    vscode.commands.registerCommand("rts.restartServer", () => client.restart())
  );
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
