#!/usr/bin/env python3
"""Counts the corpus's mesh links that resolve, per file, with no search-path flag, for one or two
builds of massprops (before/after a change of the mesh resolution): the table of docs/meshes.md
("Meshes found with no flags"). Each tool runs `massprops check --format json --fail-on error FILE`
once per model file of ../shared/corpus/MANIFEST.tsv (no --package-path, no --model-path), from
the corpus folder, then once over all of them for the time.

Usage: tools/mesh_resolution_table.py [--all] NEW/massprops [OLD/massprops] [CORPUS_DIR]
A link counts as resolved when every mesh it references resolved and was read (the summary's
mesh_links - mesh_links_unresolved). Files without a mesh link are left out; without --all,
files whose count did not change too (they are summed in the last rows)."""
import collections
import csv
import json
import os
import subprocess
import sys
import time

args = [a for a in sys.argv[1:] if a != "--all"]
show_all = "--all" in sys.argv[1:]
here = os.path.dirname(os.path.abspath(__file__))
tools = [os.path.abspath(a) for a in args if os.path.basename(a).startswith("massprops")]
rest = [a for a in args if not os.path.basename(a).startswith("massprops")]
if not tools:
    tools = [os.path.join(here, "..", "build", "massprops")]
corpus = rest[0] if rest else os.path.join(here, "..", "..", "shared", "corpus")

with open(os.path.join(corpus, "MANIFEST.tsv"), newline="") as f:
    files = [r["file"] for r in csv.DictReader(f, delimiter="\t") if r["format"] in ("urdf", "sdf")]


def run(tool):
    """Per file (the JSON summary's counts are per run): {path: (summary, file entry)}, and the
    wall time of one run over all files."""
    per_file = {}
    for path in files:
        out = subprocess.run([tool, "check", "--format", "json", "--fail-on", "error", path],
                             cwd=corpus, capture_output=True, text=True)
        report = json.loads(out.stdout)
        per_file[path] = (report["summary"], report["files"][0] if report["files"] else {})
    start = time.monotonic()
    subprocess.run([tool, "check", "--format", "json", "--fail-on", "error"] + files, cwd=corpus,
                   capture_output=True, text=True)
    return per_file, time.monotonic() - start


def resolved(summary):
    return summary.get("mesh_links", 0) - summary.get("mesh_links_unresolved", 0)


runs = [run(tool) for tool in tools]
new = runs[0][0]
old = runs[1][0] if len(runs) > 1 else None

print(f"`massprops check --format json --fail-on error <{len(files)} files>` run from "
      f"../shared/corpus, no --package-path or --model-path; "
      + "; ".join(f"{os.path.relpath(t)}: {r[1]:.2f} s wall in one process" for t, r in zip(tools, runs)) + ".\n")
header = "| file | mesh links | resolved before | resolved after | found by (after, distinct URIs) |"
print(header)
print("|---|---:|---:|---:|---|")
totals = collections.Counter()
unchanged = collections.Counter()
for path in files:
    summary, entry = new[path]
    if summary.get("mesh_links", 0) == 0:
        continue
    after = resolved(summary)
    before = resolved(old[path][0]) if old is not None else None
    totals["files"] += 1
    totals["links"] += summary["mesh_links"]
    totals["after"] += after
    totals["before"] += before or 0
    how = collections.Counter(m["found_by"] for m in entry.get("mesh_uris", []))
    how_text = ", ".join(f"{k} {v}" for k, v in sorted(how.items()))
    if before == after and not show_all:
        unchanged["files"] += 1
        unchanged["links"] += summary["mesh_links"]
        unchanged["resolved"] += after
        continue
    print(f"| {path} | {summary['mesh_links']} | {'' if before is None else before} | {after} | "
          f"{how_text} |")
if unchanged["files"]:
    print(f"| {unchanged['files']} other files (no change) | {unchanged['links']} | "
          f"{unchanged['resolved']} | {unchanged['resolved']} | |")
print(f"| **all {totals['files']} files with mesh links** | {totals['links']} | "
      f"{totals['before'] if old is not None else ''} | {totals['after']} | |")
