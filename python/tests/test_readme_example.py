"""The Python examples of README.md (section "Python") and docs/python.md run as written, from
the repository root, and print what their comments say where the comment gives a value."""
import contextlib
import io
import os
import re

import pytest

from conftest import SOURCE


def python_blocks(path, section=None):
    text = (SOURCE / path).read_text()
    if section is not None:
        start = text.index(section)
        end = text.find("\n## ", start + len(section))
        text = text[start:end if end >= 0 else len(text)]
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


@pytest.mark.parametrize("path,section", [("README.md", "## Python"), ("docs/python.md", None)])
def test_the_python_example_runs(path, section, monkeypatch):
    blocks = python_blocks(path, section)
    assert blocks, f"no python block in {path}"
    monkeypatch.chdir(SOURCE)
    for block in blocks:
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(compile(block, path, "exec"), {"__name__": "__example__"})
        printed = out.getvalue()
        # The values the comments promise.
        assert "['forearm']" in printed
        assert "link 'forearm' [inertia-not-physical" in printed
    assert not os.path.exists(SOURCE / "two_link_arm.fixed.urdf")
