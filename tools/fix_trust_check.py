#!/usr/bin/env python3
"""The fix contract on the corpus, as a user would run it: copies ../shared/corpus to a scratch
folder, runs `massprops fix --in-place FILE` (no other flag, the corpus's model and package paths)
on every URDF/SDF of MANIFEST.tsv and reports how many files changed, whether any changed file has a
finding (rule, link, severity) its original lacked, and whether a second fix changes anything.
(tests/corpus_fix_test.cc asserts the same and that only links with an error change.)

Usage: tools/fix_trust_check.py [BUILD_DIR/massprops] [CORPUS_DIR]"""
import csv
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
tool = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "build", "massprops"))
corpus = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "..", "shared", "corpus"))
paths = ["--package-path", "."]
for p in ["gazebo_models", "sdformat/test/integration/model", "gz-sim/test/worlds/models", "example-robot-data/robots"]:
    paths += ["--model-path", p]


def findings(path):
    out = subprocess.run([tool, "check", "--format", "json", "--fail-on", "never"] + paths + [path],
                         capture_output=True, text=True).stdout
    try:
        report = json.loads(out)
    except json.JSONDecodeError:  # a file the tool cannot read at all: nothing to compare
        return set()
    return {(f["rule"], f["link"], f["severity"]) for e in report["files"] for f in e["findings"]}


def digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


with tempfile.TemporaryDirectory() as scratch:
    copy = os.path.join(scratch, "corpus")
    shutil.copytree(corpus, copy)
    for root, dirs, files in os.walk(copy):
        for name in dirs + files:
            p = os.path.join(root, name)
            os.chmod(p, os.stat(p).st_mode | 0o200)
    os.chdir(copy)
    with open("MANIFEST.tsv", newline="") as f:
        models = [r["file"] for r in csv.DictReader(f, delimiter="\t") if r["format"] in ("urdf", "sdf")]
    changed = new_findings = second_changed = 0
    for path in models:
        if not os.path.exists(path):
            continue
        before, first = findings(path), digest(path)
        subprocess.run([tool, "fix", "--in-place"] + paths + [path], capture_output=True)
        if digest(path) == first:
            continue
        changed += 1
        extra = findings(path) - before
        if extra:
            new_findings += 1
            print("new findings after fix:", path, sorted(extra))
        fixed = digest(path)
        subprocess.run([tool, "fix", "--in-place"] + paths + [path], capture_output=True)
        if digest(path) != fixed:
            second_changed += 1
            print("a second fix changed:", path)
    print(f"{len(models)} files; fix changed {changed}; with a finding the original lacked: "
          f"{new_findings}; changed again by a second fix: {second_changed}")
    sys.exit(1 if new_findings or second_changed else 0)
