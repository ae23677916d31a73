"""fix() writes the text `massprops fix FILE` writes, on the corpus files that have an invalid
inertial (MANIFEST.tsv's invalid_inertial_links > 0).

The mapping of `apply`: fix() repairs every error finding, and a warning's heuristic repair only
when its rule is in `apply`. When the tool has `--apply RULE,...` (heuristic repairs only when
named), fix(path) must equal `massprops fix FILE` and fix(path, apply=R) `massprops fix --apply R
FILE`; a tool without `--apply` applies every repair, which is fix(path, apply=<every rule>)."""
import subprocess

import pytest

import massprops
from conftest import CORPUS, need_shared

HEURISTIC = ["units-suspect", "products-sign-suspect", "inertia-about-origin-suspect"]


def files_with_invalid_inertials():
    manifest = CORPUS / "MANIFEST.tsv"
    if not manifest.exists():
        return []
    files = []
    for line in manifest.read_text().splitlines()[1:]:
        cells = line.split("\t")
        if len(cells) > 8 and cells[1] in ("urdf", "sdf") and cells[8].strip() not in ("", "0"):
            files.append(str(CORPUS / cells[0]))
    return files


FILES = files_with_invalid_inertials()


def tool_fix(tool, path, *options):
    run = subprocess.run([tool, "fix", *options, path], capture_output=True, text=True,
                         cwd=CORPUS)
    return run.returncode, run.stdout


def test_fix_writes_what_the_tool_writes(tool):
    need_shared("corpus/MANIFEST.tsv")
    help_text = subprocess.run([tool, "fix", "--help"], capture_output=True, text=True).stdout
    has_apply = "--apply" in help_text
    every_rule = [rule["id"] for rule in massprops.rules()]
    compared = changed = 0
    mismatches = []
    for path in FILES:
        code, expected = tool_fix(tool, path)
        if code == 2:  # the tool could not read it: fix() raises ReadError
            with pytest.raises(massprops.ReadError):
                massprops.fix(path)
            continue
        ours = massprops.fix(path) if has_apply else massprops.fix(path, apply=every_rule)
        if ours.text != expected:
            mismatches.append(path)
        if has_apply:
            code, expected = tool_fix(tool, path, "--apply", ",".join(HEURISTIC))
            if massprops.fix(path, apply=HEURISTIC).text != expected:
                mismatches.append(path + " (--apply)")
        compared += 1
        changed += ours.changed
    assert not mismatches, mismatches[:5]
    assert compared >= 15 and changed >= 15  # 21 rows, 3 of them unreadable today
