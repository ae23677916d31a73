#!/usr/bin/env python3
"""A real LSP client: headless Neovim (Debian's neovim) opens the README's example with `massprops
lsp` attached (tools/nvim_lsp_check.lua) and lists the same diagnostics as `massprops check
--format json` reports for the file: the same rules at the same lines, with the same severities
(error 1, warning 2, note 3: LSP's DiagnosticSeverity) and check's headlines as the messages'
first lines; and the server stops when Neovim asks (shutdown, exit).

Usage: lsp_neovim_test.py MASSPROPS NVIM EXAMPLES_DIR TOOLS_DIR
"""
import json
import os
import pathlib
import subprocess
import sys
import tempfile

LSP_SEVERITY = {"error": 1, "warning": 2, "note": 3}


def main():
    tool, nvim, examples, tools = sys.argv[1:5]
    example = pathlib.Path(examples).resolve() / "two_link_arm.urdf"
    report = json.loads(subprocess.run([tool, "check", "--format", "json", str(example)],
                                       capture_output=True, text=True, check=False).stdout)
    expected = sorted((f["rule"], f["line"] - 1, LSP_SEVERITY[f["severity"]], f["headline"])
                      for file in report["files"] for f in file["findings"])
    assert expected, "check reports nothing on the example"
    with tempfile.TemporaryDirectory() as home:
        out = pathlib.Path(home) / "diagnostics.json"
        env = dict(os.environ, MASSPROPS_TOOL=tool, MASSPROPS_FILE=str(example),
                   MASSPROPS_OUT=str(out), HOME=home, XDG_STATE_HOME=home, XDG_DATA_HOME=home)
        script = pathlib.Path(tools).resolve() / "nvim_lsp_check.lua"
        run = subprocess.run([nvim, "--headless", "--clean", "-n", "-i", "NONE", "-c",
                              "luafile " + str(script)], env=env, capture_output=True, text=True,
                             timeout=120, stdin=subprocess.DEVNULL, check=False)
        assert out.exists(), "Neovim wrote nothing:\n" + run.stdout + run.stderr
        got = json.loads(out.read_text())
    assert got["attached"] and got["published"], got
    assert got["stopped"], "the server did not stop on shutdown/exit"
    rows = sorted((d["code"], d["lnum"], d["severity"], d["message"].split("\n")[0])
                  for d in got["diagnostics"])
    assert rows == expected, (rows, expected)
    print("ok   Neovim lists the diagnostics check reports (%d)" % len(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())
