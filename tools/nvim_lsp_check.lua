-- Headless Neovim (0.7 or later) as a real LSP client of `massprops lsp`: opens a file with the
-- server attached, waits for its diagnostics, writes them as JSON and quits (shutdown and exit
-- sent by Neovim). Used by tests/lsp_neovim_test.py; also a complete example of the setup.
--
--   MASSPROPS_TOOL=build/massprops MASSPROPS_FILE=examples/two_link_arm.urdf \
--   MASSPROPS_OUT=/tmp/diagnostics.json nvim --headless --clean -n -c "luafile tools/nvim_lsp_check.lua"
--
-- Output: {"attached": true, "published": true, "stopped": true, "diagnostics": [{"lnum",
-- "col", "end_col", "severity", "code", "source", "message"}]} (lnum/col 0-based, severity 1 error,
-- 2 warning, 3 information).
local tool = os.getenv("MASSPROPS_TOOL") or "massprops"
local file = assert(os.getenv("MASSPROPS_FILE"), "set MASSPROPS_FILE")
local out = assert(os.getenv("MASSPROPS_OUT"), "set MASSPROPS_OUT")

vim.cmd("edit " .. vim.fn.fnameescape(file))
local bufnr = vim.api.nvim_get_current_buf()
local published = false
local client_id = vim.lsp.start_client({
  name = "massprops",
  cmd = { tool, "lsp" },
  root_dir = vim.fn.fnamemodify(file, ":p:h"),
  handlers = {
    ["textDocument/publishDiagnostics"] = function(err, result, ctx, config)
      published = true
      return vim.lsp.handlers["textDocument/publishDiagnostics"](err, result, ctx, config)
    end,
  },
})
local attached = client_id ~= nil and vim.lsp.buf_attach_client(bufnr, client_id)
vim.wait(30000, function() return published end, 20)

local diagnostics = {}
for _, d in ipairs(vim.diagnostic.get(bufnr)) do
  local lsp = d.user_data and d.user_data.lsp or {}
  table.insert(diagnostics, {
    lnum = d.lnum, col = d.col, end_col = d.end_col, severity = d.severity,
    code = d.code or lsp.code, source = d.source, message = d.message,
  })
end

local stopped = false
if client_id then
  vim.lsp.stop_client(client_id)
  stopped = vim.wait(10000, function() return vim.lsp.client_is_stopped(client_id) end, 20)
end
local handle = assert(io.open(out, "w"))
handle:write(vim.fn.json_encode({
  attached = attached and true or false, published = published, stopped = stopped,
  diagnostics = diagnostics,
}))
handle:close()
vim.cmd("qall!")
