#!/usr/bin/env python3
"""Precision and recall of `massprops check`'s warnings against hand-judged labels, per link and
per rule, on the corpus table (the train set: testdata/labels/warnings.tsv over ../shared/corpus)
on ../shared/labelled/set1 and set2 (the validation set: labelled by others, never tuned on), and
on ../shared/labelled/set3..set5 (robots with their meshes, labelled link by link: label_links.py).

Usage: tools/label_score.py [--tool BUILD/massprops] [--set corpus,labelled,sets3-5|all] [--list]
                            [--extra-args "ARGS"] [--work DIR] [--check FIGURES_TSV]

How a set is scored (../shared/labelled/README.md): a finding of severity warning (or error, for
the rules the labels judge: massless-moving-body, urdf-not-loadable) is judged by the rows of its
link: real when the link has a `real` row (a better rule that names the link's defect counts
too), noise otherwise (a warning with no row counts as noise). Precision = real flagged links /
flagged links; recall = real links flagged by any finding / real links. Rows whose why says
"uncertain:" count as real in recall only when flagged (they are not required).
Per rule: a rule's precision counts the links that rule flags; its recall counts the real rows of
that rule that any finding on the link reports.
"""
import argparse
import collections
import csv
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
SHARED = os.path.join(ROOT, "..", "shared")
# Physics errors are judged exactly against the oracle (not by labels): left out of the figures.
EXACT = {"inertia-not-physical", "mass-not-positive", "inertia-not-finite", "inertial-unreadable",
         "read-warning", "inertia-near-boundary"}
PHYSICS_ERRORS = set()  # (file, link) of every per-link inertia-not-physical error seen
sys.path.insert(0, os.path.join(ROOT, "tests"))
import shared_data  # noqa: E402  (tests/shared_data.py: a missing ../shared skips, exit 77)
sys.path.insert(0, HERE)
import label_links  # noqa: E402  (sets 3-5, with meshes, labelled per link)

CORPUS_MODEL_PATHS = ["gazebo_models", "sdformat/test/integration/model",
                      "gz-sim/test/worlds/models", "example-robot-data/robots"]


def read_rows(path, skip_header=True):
    rows = []
    with open(path, newline="") as f:
        for i, line in enumerate(f):
            if i == 0 and skip_header:
                continue
            cells = line.rstrip("\n").split("\t")
            if len(cells) < 4 or cells[0].startswith("#"):
                continue
            rows.append({"file": cells[0], "rule": cells[1], "link": cells[2],
                         "real": cells[3] == "real",
                         "uncertain": "uncertain:" in (cells[4][:40] if len(cells) > 4 else "")})
    return rows


def run_check(tool, cwd, files, extra):
    cmd = [tool, "check", "--format", "json", "--fail-on", "error"] + extra + files
    out = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    try:
        report = json.loads(out.stdout)
    except json.JSONDecodeError:
        sys.exit(f"label_score: no JSON from {' '.join(cmd[:6])}...: {out.stderr[:500]}")
    findings = []
    for entry in report["files"]:
        for f in entry["findings"]:
            if f["rule"] == "inertia-not-physical" and "group_links" not in f.get("values", {}):
                PHYSICS_ERRORS.add((entry["path"], f.get("link", "")))
            if f["severity"] == "note" or f["rule"] in EXACT:
                continue
            findings.append((entry["path"], f["rule"], f.get("link", ""), f.get("message", ""),
                             f["severity"]))
    return findings


def score(name, rows, findings, listing):
    real_links = {}
    noise_rows = set()
    for r in rows:
        key = (r["file"], r["link"])
        if r["real"]:
            real_links.setdefault(key, []).append(r)
        else:
            noise_rows.add(key)
    flagged = collections.defaultdict(set)  # (file, link) -> rules of the warnings
    found = set()  # (file, link) with any finding, warning or error
    for path, rule, link, _, severity in findings:
        found.add((path, link))
        if severity == "warning":
            flagged[(path, link)].add(rule)
    tp = sum(1 for k in flagged if k in real_links)
    fp = len(flagged) - tp
    required = {k for k, rs in real_links.items() if not all(r["uncertain"] for r in rs)}
    hit = sum(1 for k in required if k in found)
    prec = tp / len(flagged) if flagged else 1.0
    rec = hit / len(required) if required else 1.0
    print(f"## {name}: flagged links {len(flagged)} (real {tp}, noise {fp}): precision {prec:.3f};"
          f" real links {len(required)} (+{len(real_links) - len(required)} uncertain), flagged"
          f" {hit}: recall {rec:.3f}")
    # Per rule.
    per_rule = collections.defaultdict(lambda: [0, 0, 0, 0])  # real flagged, noise flagged, rows hit, rows
    for (path, link), rules in flagged.items():
        for rule in rules:
            per_rule[rule][0 if (path, link) in real_links else 1] += 1
    for k, rs in real_links.items():
        for r in rs:
            if r["uncertain"]:
                continue
            per_rule[r["rule"]][3] += 1
            if k in found:
                per_rule[r["rule"]][2] += 1
    figures = {"all": (prec if flagged else None, rec if required else None)}
    print("| rule | flagged real | flagged noise | precision | real rows | reported | recall |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for rule in sorted(per_rule):
        a, b, c, d = per_rule[rule]
        p = f"{a / (a + b):.3f}" if a + b else "—"
        q = f"{c / d:.3f}" if d else "—"
        print(f"| `{rule}` | {a} | {b} | {p} | {d} | {c} | {q} |")
        figures[rule] = (a / (a + b) if a + b else None, c / d if d else None)
    if listing:
        print("\nnoise flagged:")
        for (path, link), rules in sorted(flagged.items()):
            if (path, link) not in real_links:
                print(f"  NOISE {path} {link} {sorted(rules)}"
                      + (" (labelled noise)" if (path, link) in noise_rows else " (no row)"))
        print("real missed:")
        for k in sorted(required):
            if k not in found:
                print(f"  MISS {k[0]} {k[1]} {[r['rule'] for r in real_links[k]]}")
    return figures


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "massprops"))
    ap.add_argument("--set", default="all",
                    help="corpus, labelled (set1+2), sets3-5, or several joined by commas; all "
                         "(the default): the three")
    ap.add_argument("--list", action="store_true", help="list noise and missed links")
    ap.add_argument("--extra-args", default="", help="more arguments for check")
    ap.add_argument("--check", metavar="FIGURES_TSV",
                    help="fail (exit 1) when a set's or a rule's precision or recall falls below "
                         "the floor the file gives (columns: set, rule or 'all', precision, "
                         "recall; '-' for none)")
    ap.add_argument("--meshes", metavar="FINDINGS_JSONL",
                    help="score the labelled set from the findings.jsonl of tools/labelled_meshes.py"
                         " (check run in place in the repositories' snapshots, meshes present)")
    ap.add_argument("--mesh-labels", metavar="TSV",
                    help="with --meshes: add these rows (testdata/labels/labelled-meshes-judged.tsv)")
    ap.add_argument("--shared", help="the shared folder (default: ../shared beside the checkout)")
    ap.add_argument("--work", help="where sets 3-5 are unpacked (default: labelled/ beside the "
                                   "tool, in its build folder)")
    return ap.parse_args()


def score_corpus(tool, extra, listing):
    rows = read_rows(os.path.join(ROOT, "testdata", "labels", "warnings.tsv"))
    corpus = os.path.join(SHARED, "corpus")
    with open(os.path.join(corpus, "MANIFEST.tsv"), newline="") as f:
        files = [r["file"] for r in csv.DictReader(f, delimiter="\t")
                 if r["format"] in ("urdf", "sdf")]
    paths = []
    for p in CORPUS_MODEL_PATHS:
        paths += ["--model-path", p]
    findings = run_check(tool, corpus, files, paths + ["--package-path", "."] + extra)
    return score("corpus (train: testdata/labels/warnings.tsv)", rows, findings, listing)


def score_meshes(args):
    allrows, allfindings = [], []
    for s in ("set1", "set2"):
        rows = read_rows(os.path.join(SHARED, "labelled", s, "labels.tsv"))
        for r in rows:
            r["file"] = s + "/" + r["file"]
        allrows += rows
    # Our own judgement of the firings the labels (made without meshes) have no row for,
    # from tools/labelled_mesh_evidence.py: counted only with --mesh-labels.
    if args.mesh_labels:
        allrows += read_rows(args.mesh_labels)
    with open(args.meshes) as f:
        for line in f:
            d = json.loads(line)
            if d["severity"] == "note" or d["rule"] in EXACT:
                continue
            allfindings.append((d["set"] + "/" + d["file"], d["rule"], d.get("link", ""),
                                d.get("message", ""), d["severity"]))
    score("labelled with meshes (validation, " + args.meshes + ")", allrows, allfindings,
          args.list)


def score_labelled(tool, extra, listing):
    """Sets 1 and 2: (figures, the links whose errors differ from the oracle)."""
    allrows, allfindings = [], []
    oracle_mismatches = []
    for s in ("set1", "set2"):
        base = os.path.join(SHARED, "labelled", s)
        PHYSICS_ERRORS.clear()
        rows = read_rows(os.path.join(base, "labels.tsv"))
        files = sorted(os.listdir(os.path.join(base, "files")))
        extra_s = extra + ["--model-path", os.path.join(base, "modelpath")]
        findings = run_check(tool, os.path.join(base, "files"), files, extra_s)
        for r in rows:
            r["file"] = s + "/" + r["file"]
        allrows += rows
        allfindings += [(s + "/" + f[0],) + tuple(f[1:]) for f in findings]
        # Errors are physics: exactly the links the independent numpy oracle finds invalid.
        invalid = label_links.oracle_invalid(base, files)
        for key in sorted(invalid ^ PHYSICS_ERRORS):
            oracle_mismatches.append(f"{s}/{key[0]} {key[1]}: " + (
                "oracle invalid, no error" if key in invalid else "error, oracle valid"))
        print(f"## {s} errors: {len(PHYSICS_ERRORS)} links with inertia-not-physical, "
              f"{len(invalid)} invalid by oracle.json, {len(invalid ^ PHYSICS_ERRORS)} differ")
    for m in oracle_mismatches:
        print("  ORACLE", m)
    return score("labelled (validation: ../shared/labelled set1+set2)", allrows, allfindings,
                 listing), oracle_mismatches


def check_floors(path, results, oracle_mismatches):
    failures = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or line.startswith("set\t") or not line.strip():
                continue
            name, rule, floor_p, floor_r = line.rstrip("\n").split("\t")[:4]
            if name not in results:
                continue
            got_p, got_r = results[name].get(rule, (None, None))
            for what, floor, got in (("precision", floor_p, got_p), ("recall", floor_r, got_r)):
                if floor == "-":
                    continue
                if got is None or got + 1e-9 < float(floor):
                    failures.append(f"{name} {rule} {what}: {got} below the floor {floor}")
    for failure in failures:
        print("FAIL:", failure)
    failures += ["errors differ from the oracle: " + m for m in oracle_mismatches]
    print(f"label_score: {len(failures)} figure(s) below their floor or error(s) unlike the "
          f"oracle")
    sys.exit(1 if failures else 0)


def main():
    args = parse_args()
    global SHARED
    if args.shared:
        SHARED = os.path.abspath(args.shared)
    tool = os.path.abspath(args.tool)
    extra = args.extra_args.split()
    wants = {"corpus", "labelled", "sets3-5"} if args.set == "all" else set(args.set.split(","))
    if wants - {"corpus", "labelled", "sets3-5"}:
        sys.exit(f"label_score: --set {args.set}: corpus, labelled, sets3-5 or all")
    shared_data.check(SHARED, (["corpus/MANIFEST.tsv"] if "corpus" in wants else []) +
                      (["labelled"] if "labelled" in wants or args.meshes else []) +
                      ([f"labelled/{s}/data.tar.xz" for s in label_links.SETS]
                       if "sets3-5" in wants and not args.meshes else []))
    results = {}
    if "corpus" in wants:
        results["corpus"] = score_corpus(tool, extra, args.list)
    if args.meshes:
        score_meshes(args)
        return
    oracle_mismatches = []
    if "labelled" in wants:
        results["labelled"], oracle_mismatches = score_labelled(tool, extra, args.list)
    if "sets3-5" in wants:
        work = os.path.abspath(args.work or os.path.join(os.path.dirname(tool), "labelled"))
        results["sets3-5"], mismatches = label_links.score_sets(
            tool, SHARED, work, extra, EXACT, args.list)
        oracle_mismatches += mismatches
    if args.check:
        check_floors(args.check, results, oracle_mismatches)


if __name__ == "__main__":
    main()
