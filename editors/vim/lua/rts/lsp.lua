-- Attaches `rts lsp` to rts buffers with Neovim's built-in LSP client (no plugin needed).
--
--   vim.opt.runtimepath:append("/path/to/rts/editors/vim")   -- syntax, filetype, this module
--   require("rts.lsp").setup({ cmd = { "rts", "lsp" } })       -- the defaults shown
--
-- Neovim 0.8+ has vim.lsp.start (one client per root folder, reused); 0.7 (Debian 12's) gets
-- the same through start_client + buf_attach_client.
local M = {}

local function root_of(bufnr)
  local name = vim.api.nvim_buf_get_name(bufnr)
  return vim.fn.fnamemodify(name, ":p:h")
end

function M.attach(bufnr, opts)
  opts = opts or {}
  bufnr = bufnr or vim.api.nvim_get_current_buf()
  local config = {
    name = "rts",
    cmd = opts.cmd or { "rts", "lsp" },
    root_dir = root_of(bufnr),
  }
  if vim.lsp.start then
    return vim.lsp.start(config, { bufnr = bufnr })
  end
  M._clients = M._clients or {}
  local id = M._clients[config.root_dir]
  if not id or vim.lsp.get_client_by_id(id) == nil then
    id = vim.lsp.start_client(config)
    M._clients[config.root_dir] = id
  end
  vim.lsp.buf_attach_client(bufnr, id)
  return id
end

function M.setup(opts)
  vim.api.nvim_create_autocmd("FileType", {
    pattern = "rts",
    callback = function(args) M.attach(args.buf, opts) end,
  })
end

return M
