#!/usr/bin/env python3
"""How long `massprops check`'s findings are, in default text, over the corpus (issue 32).

Runs `massprops check --color never` on every URDF/SDF file of ../shared/corpus (MANIFEST.tsv,
with the model paths tools/label_score.py uses), from the corpus folder, and reads its text: a
finding's line is `file:line: severity: HEADLINE [rule]` (the xacro note may follow); the lines
under it that start with "  = " are its evidence and help. Prints the number of findings, the
headline length (characters between "severity: " and " [rule]") max, median and 90th percentile,
the most lines under one headline, how many headlines contain "…" (cut), the read errors' headline
lengths, and the bytes of the whole output; with --json also whether every finding of `--format
json` has a non-empty headline and help and an evidence object, and the lengths and cuts of every
headline of JSON and SARIF, read errors included (issue 43). Works on any build (before issue 32
the "headline" measured is the whole message).

  tools/finding_lengths.py --tool build/massprops [--json] [--file F]

--file F measures one file instead (e.g. testdata/check/units-suspect-repeated.urdf) and also
counts its "= evidence" and "= help" lines.
"""
import argparse
import csv
import json
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
CORPUS = os.path.join(HERE, "..", "..", "shared", "corpus")
MODEL_PATHS = ["gazebo_models", "sdformat/test/integration/model", "gz-sim/test/worlds/models",
               "example-robot-data/robots"]
ELLIPSIS = "\u2026"  # what a cut headline contains
READ_ERRORS = []  # the read errors' headlines (measure fills it)
CUT = []  # per finding's headline: whether it contains "…"
LINE = re.compile(r"^(?P<where>\S.*?): (?P<severity>error|warning|note): (?P<headline>.*?) "
                  r"\[(?P<rule>[a-z0-9-]+)\](?: \(.*\))?$")


def run(tool, cwd, files, extra):
    args = [tool, "check", "--color", "never"] + extra + files
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True).stdout


def measure(text):
    lengths, under, evidence, helps = [], [], 0, 0
    reading_error = False
    for line in text.splitlines():
        m = LINE.match(line)
        if m and m.group("rule") == "read-error":
            READ_ERRORS.append(m.group("headline"))
            reading_error = True  # its "  = why:" line is not a finding's
        elif m:
            reading_error = False
            lengths.append(len(m.group("headline")))
            CUT.append(ELLIPSIS in m.group("headline"))
            under.append(0)
        elif line.startswith("  = ") and under and not reading_error:
            under[-1] += 1
            evidence += line.startswith("  = evidence:")
            helps += line.startswith("  = help:")
    return lengths, under, evidence, helps


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--tool", required=True)
    ap.add_argument("--json", action="store_true", help="also check the JSON parts")
    ap.add_argument("--file", help="one file instead of the corpus")
    args = ap.parse_args()
    tool = os.path.abspath(args.tool)
    if args.file:
        cwd, files, extra = os.getcwd(), [args.file], []
    else:
        cwd = os.path.abspath(CORPUS)
        with open(os.path.join(cwd, "MANIFEST.tsv"), newline="") as f:
            files = [r["file"] for r in csv.DictReader(f, delimiter="\t")
                     if r["format"] in ("urdf", "sdf")]
        extra = ["--package-path", "."]
        for p in MODEL_PATHS:
            extra += ["--model-path", p]
    text = run(tool, cwd, files, extra)
    lengths, under, evidence, helps = measure(text)
    if not lengths:
        print("no findings")
        return 1
    ordered = sorted(lengths)
    print(f"files {len(files)}, findings {len(lengths)}, output {len(text.encode())} bytes")
    print(f"headline characters: max {max(lengths)}, median {statistics.median(lengths):g}, "
          f"90th percentile {ordered[int(0.9 * (len(ordered) - 1))]}")
    print(f"lines under a headline: max {max(under)}; headlines over 110 characters: "
          f"{sum(1 for n in lengths if n > 110)}; with '\u2026': {sum(CUT)}")
    if READ_ERRORS:
        print(f"read errors {len(READ_ERRORS)}: headline characters max "
              f"{max(len(h) for h in READ_ERRORS)}, with '\u2026': "
              f"{sum(ELLIPSIS in h for h in READ_ERRORS)}")
    if args.file:
        print(f"'= evidence' lines {evidence}, '= help' lines {helps}")
    if args.json:
        out = subprocess.run([tool, "check", "--format", "json"] + extra + files, cwd=cwd,
                             capture_output=True, text=True).stdout
        bad = 0
        count = 0
        for f in json.loads(out)["files"]:
            for finding in f["findings"]:
                count += 1
                if not finding.get("headline") or not finding.get("help") or \
                        not isinstance(finding.get("evidence"), dict):
                    bad += 1
        print(f"JSON findings {count}, without a headline, help or evidence object: {bad}")
        # Every headline of JSON (findings' and read errors'; before issue 43 a read error had
        # none: its "element: message" is measured) and of SARIF (message.text).
        heads = []
        for f in json.loads(out)["files"]:
            heads += [finding.get("headline", "") for finding in f["findings"]]
            heads += [e.get("headline", (e["element"] + ": " if e["element"] else "") +
                            e["message"]) for e in f["errors"]]
        sarif = subprocess.run([tool, "check", "--format", "sarif"] + extra + files, cwd=cwd,
                               capture_output=True, text=True).stdout
        texts = [r["message"]["text"] for r in json.loads(sarif)["runs"][0]["results"]]
        for name, hs in (("JSON headlines", heads), ("SARIF message.text", texts)):
            print(f"{name} {len(hs)} (read errors included): max {max(map(len, hs))} characters, "
                  f"over 110: {sum(len(h) > 110 for h in hs)}, with '\u2026': "
                  f"{sum(ELLIPSIS in h for h in hs)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
