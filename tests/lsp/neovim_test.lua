-- Run by neovim_test.sh inside `nvim --headless`: opens the scene through the repository's own
-- Neovim setup (editors/vim: filetype detection and rts.lsp's attach), waits for `rts lsp`'s
-- diagnostics, asks for a hover, and writes what Neovim received to $RTS_OUT.
local out = assert(io.open(os.getenv("RTS_OUT"), "w"))
local function finish(code)
  out:close()
  vim.cmd(code == 0 and "qa!" or "cq!")
end

vim.opt.runtimepath:append(os.getenv("RTS_EDITORS") .. "/vim")
vim.cmd("filetype on")
vim.cmd("runtime ftdetect/rts.vim")
require("rts.lsp").setup({ cmd = { os.getenv("RTS_BINARY"), "lsp" } })
vim.cmd("edit " .. vim.fn.fnameescape(os.getenv("RTS_SCENE")))
out:write("filetype " .. vim.bo.filetype .. "\n")

local got = vim.wait(10000, function() return #vim.diagnostic.get(0) > 0 end, 20)
if not got then
  out:write("no diagnostics within 10 s\n")
  return finish(1)
end
for _, d in ipairs(vim.diagnostic.get(0)) do
  -- 0-based lines and byte columns, as Neovim stores them.
  out:write(string.format("diagnostic %d:%d-%d:%d severity %d %s\n", d.lnum, d.col, d.end_lnum, d.end_col,
                          d.severity, d.message))
end

local params = { textDocument = { uri = vim.uri_from_bufnr(0) }, position = { line = 1, character = 10 } }
local replies = vim.lsp.buf_request_sync(0, "textDocument/hover", params, 5000) or {}
for _, r in pairs(replies) do
  if r.result and r.result.contents then
    out:write("hover " .. (r.result.contents.value or ""):gsub("\n", " ") .. "\n")
  end
end
for _, client in pairs(vim.lsp.get_active_clients()) do client.stop() end
vim.wait(2000, function() return #vim.lsp.get_active_clients() == 0 end, 20)
finish(0)
