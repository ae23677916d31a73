#!/usr/bin/env python3
"""Runs `massprops check --format json` over every model file of ../shared/corpus/MANIFEST.tsv in
one process and prints a Markdown table of findings per source and rule (the corpus
table of docs/corpus.md). Usage: tools/corpus_summary.py [BUILD_DIR/massprops] [CORPUS_DIR]"""
import collections
import csv
import json
import os
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
tool = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(here, "..", "build", "massprops")
corpus = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "..", "shared", "corpus")

with open(os.path.join(corpus, "MANIFEST.tsv"), newline="") as f:
    rows = [r for r in csv.DictReader(f, delimiter="\t") if r["format"] in ("urdf", "sdf")]
files = [r["file"] for r in rows]
model_paths = ["gazebo_models", "sdformat/test/integration/model", "gz-sim/test/worlds/models",
               "example-robot-data/robots"]
cmd = [tool, "check", "--format", "json", "--fail-on", "error"]
for p in model_paths:
    cmd += ["--model-path", p]
# package://example-robot-data/... resolves to the corpus folder of that name (corpus README).
cmd += ["--package-path", "."]
start = time.monotonic()
out = subprocess.run(cmd + files, cwd=corpus, capture_output=True, text=True)
elapsed = time.monotonic() - start
report = json.loads(out.stdout)

source_of = {r["file"]: r["file"].split("/")[0] for r in rows}
per_source = collections.defaultdict(collections.Counter)
files_per_source = collections.Counter(source_of.values())
rules = collections.Counter()
for entry in report["files"]:
    source = source_of.get(entry["path"], "?")
    if entry.get("errors"):
        per_source[source]["read-error"] += 1
        rules["read-error"] += 1
    for finding in entry["findings"]:
        per_source[source][finding["rule"]] += 1
        rules[finding["rule"]] += 1

columns = [r for r, _ in rules.most_common()]
print(f"`{' '.join(['massprops', 'check', '--format', 'json'] + [a for p in model_paths for a in ('--model-path', p)] + ['--package-path', '.'])} <{len(files)} files>`"
      f" (run from ../shared/corpus): {elapsed:.2f} s wall for {len(files)} files in one process, exit code {out.returncode}.\n")
print("| source | files | " + " | ".join(columns) + " |")
print("|---|---:|" + "---:|" * len(columns))
for source in sorted(files_per_source):
    counts = per_source[source]
    print(f"| {source} | {files_per_source[source]} | " +
          " | ".join(str(counts[c]) if counts[c] else "" for c in columns) + " |")
print("| **all** | " + str(len(files)) + " | " + " | ".join(str(rules[c]) for c in columns) + " |")
print("\n(read-error counts files that could not be read; the other columns count findings.)")
