#!/usr/bin/env python3
"""Per corpus source, how many model files each target profile accepts: `massprops check
--target T --format json` over every URDF/SDF of ../shared/corpus/MANIFEST.tsv (one process per
target). A file is accepted when it reads and has no error-severity finding. MuJoCo reads URDF
only, so its column counts URDFs. Prints the Markdown table of docs/targets.md.
Usage: tools/target_table.py [BUILD_DIR/massprops] [CORPUS_DIR]"""
import collections
import csv
import json
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
tool = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(here, "..", "build", "massprops")
corpus = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "..", "shared", "corpus")

with open(os.path.join(corpus, "MANIFEST.tsv"), newline="") as f:
    rows = [r for r in csv.DictReader(f, delimiter="\t") if r["format"] in ("urdf", "sdf")]
model_paths = ["gazebo_models", "sdformat/test/integration/model", "gz-sim/test/worlds/models",
               "example-robot-data/robots"]
targets = ["generic", "mujoco", "drake", "gazebo"]
accepted = {t: collections.Counter() for t in targets}
total = collections.Counter()
urdf_total = collections.Counter()
for r in rows:
    total[r["file"].split("/")[0]] += 1
    if r["format"] == "urdf":
        urdf_total[r["file"].split("/")[0]] += 1
for t in targets:
    files = [r["file"] for r in rows if t != "mujoco" or r["format"] == "urdf"]
    cmd = [tool, "check", "--format", "json", "--target", t]
    for p in model_paths:
        cmd += ["--model-path", p]
    out = subprocess.run(cmd + files, cwd=corpus, capture_output=True, text=True)
    for f in json.loads(out.stdout)["files"]:
        ok = not f.get("errors") and not any(x["severity"] == "error" for x in f["findings"])
        if ok:
            accepted[t][f["path"].split("/")[0]] += 1
print("| source | files (URDF) | generic | mujoco (of URDF) | drake | gazebo |")
print("| --- | --- | --- | --- | --- | --- |")
for s in sorted(total):
    print(f"| {s} | {total[s]} ({urdf_total[s]}) | {accepted['generic'][s]} | "
          f"{accepted['mujoco'][s]} | {accepted['drake'][s]} | {accepted['gazebo'][s]} |")
print(f"| **all** | {sum(total.values())} ({sum(urdf_total.values())}) | "
      + " | ".join(str(sum(accepted[t].values())) for t in targets) + " |")
