"""Parity with the command-line tool on every URDF and SDF file of ../shared/corpus (its
MANIFEST.tsv): massprops.check(path) gives the same findings, in the same order, as
`massprops check --format json` on the same files; a file the tool cannot read raises
massprops.ReadError naming the same file and line. The tool runs once on all the files."""
import json
import math
import subprocess

import pytest

import massprops
from conftest import CORPUS, need_shared


def corpus_files():
    manifest = CORPUS / "MANIFEST.tsv"
    if not manifest.exists():
        return []
    rows = [line.split("\t") for line in manifest.read_text().splitlines()[1:]]
    return [str(CORPUS / row[0]) for row in rows if len(row) > 1 and row[1] in ("urdf", "sdf")]


FILES = corpus_files()


@pytest.fixture(autouse=True, scope="module")
def corpus_present():
    need_shared("corpus/MANIFEST.tsv")


def normalized(finding):
    """A finding dict with NaN values as None (the JSON writes null for non-finite numbers)."""
    values = {k: (None if v is None or (isinstance(v, float) and not math.isfinite(v)) else v)
              for k, v in finding["values"].items()}
    return {**finding, "values": values}


@pytest.fixture(scope="module")
def tool_results(tool):
    run = subprocess.run([tool, "check", "--format", "json", "--quiet", *FILES],
                         capture_output=True, text=True, cwd=CORPUS)
    assert run.returncode in (0, 1, 2), run.stderr
    document = json.loads(run.stdout)
    return {entry["path"]: entry for entry in document["files"]}


def test_corpus_has_the_files_the_manifest_lists():
    assert len(FILES) > 200


def test_check_gives_the_tools_findings_on_every_corpus_file(tool_results, monkeypatch):
    monkeypatch.chdir(CORPUS)  # the same working directory (configuration lookup) as the tool
    compared = findings_total = read_errors = 0
    mismatches = []
    for path in FILES:
        expected = tool_results[path]
        try:
            ours = [normalized(f.to_dict()) for f in massprops.check(path)]
        except massprops.ReadError as error:
            read_errors += 1
            if not expected["errors"] or expected["errors"][0]["line"] != error.line or \
                    expected["errors"][0]["file"] != error.file:
                mismatches.append((path, "ReadError", str(error), expected["errors"]))
            continue
        theirs = [normalized(f) for f in expected["findings"]]
        if expected["errors"]:
            mismatches.append((path, "read errors expected", expected["errors"]))
        elif ours != theirs:
            mismatches.append((path, ours, theirs))
        compared += 1
        findings_total += len(ours)
    assert not mismatches, mismatches[:3]
    # The corpus has hundreds of findings (MANIFEST's invalid_inertial_links alone is > 50).
    assert compared > 200 and findings_total > 100
