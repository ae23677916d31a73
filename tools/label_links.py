"""Sets 3-5 of ../shared/labelled (robots with their meshes, labelled link by link), scored for
tools/label_score.py (docs/labels.md, "Sets 3-5").

Each set's data.tar.xz (files/ and modelpath/) is unpacked once into WORK/setN/ (by default
BUILD/labelled/, beside the tool); a stamp holding the tarball's size and time skips the unpacking
while it is up to date. The meshes resolve as the sets' READMEs say with the tool's own options:
`package://pkg/x` and `model://name/x` -> modelpath/... (`--package-path modelpath --model-path
modelpath`), `package:///x` beside the file (the sets hold each such mesh byte for byte both in
files/ and in modelpath/), relative paths against files/.

Scoring (../shared/labelled/README.md): labels-links.tsv is `file link real|noise|either why`. A
flagged link is one with a warning (the rules judged exactly by the oracle left out, as in sets 1-2);
it is real with a `real` row, not counted with an `either` row, noise otherwise (a `noise` row or no
row). Precision = real flagged / (real + noise flagged); recall = real links with any warning or
error naming them / real links. Per rule: the links that rule flags (precision), and the real links
it reports among all real links (its share of the recall: the labels name no rule).
"""
import collections
import json
import os
import shutil
import subprocess
import tarfile

SETS = ("set3", "set4", "set5")


def unpack(shared, work, name):
    """WORK/NAME/ holding files/ and modelpath/ of shared/labelled/NAME/data.tar.xz, unpacked
    only when the stamp (size and mtime of the tarball) differs."""
    tarball = os.path.join(shared, "labelled", name, "data.tar.xz")
    st = os.stat(tarball)
    stamp = f"{st.st_size} {st.st_mtime_ns}\n"
    dest = os.path.join(work, name)
    stamp_path = os.path.join(dest, ".unpacked")
    if os.path.isfile(stamp_path):
        with open(stamp_path) as f:
            if f.read() == stamp:
                return dest
    tmp = dest + ".part"
    shutil.rmtree(tmp, ignore_errors=True)
    os.makedirs(tmp)
    with tarfile.open(tarball) as tar:
        if hasattr(tarfile, "data_filter"):
            tar.extractall(tmp, filter="data")
        else:
            tar.extractall(tmp)  # noqa: S202 (Python < 3.12: the shared tarball, read-only)
    with open(os.path.join(tmp, ".unpacked"), "w") as f:
        f.write(stamp)
    shutil.rmtree(dest, ignore_errors=True)
    os.rename(tmp, dest)
    return dest


def read_link_labels(path):
    """{(file, link): (label, why)} of a labels-links.tsv."""
    labels = {}
    with open(path, newline="") as f:
        for line in f:
            cells = line.rstrip("\n").split("\t")
            if line.startswith("#") or len(cells) < 3 or cells[2] not in ("real", "noise", "either"):
                continue
            labels[(cells[0], cells[1])] = (cells[2], cells[3] if len(cells) > 3 else "")
    return labels


def robot_files(base):
    """The manifest's files (NN_name.ext), in its order."""
    with open(os.path.join(base, "manifest.tsv"), newline="") as f:
        return [line.split("\t")[0] for i, line in enumerate(f) if i and line.strip()]


def run_set(tool, unpacked, files, extra, exact):
    """check over one set: (findings [(file, rule, link, severity, message)], physics errors
    {(file, link)}, mesh resolution counts summed)."""
    cmd = [tool, "check", "--format", "json", "--fail-on", "error",
           "--package-path", os.path.join(unpacked, "modelpath"),
           "--model-path", os.path.join(unpacked, "modelpath")] + extra + files
    out = subprocess.run(cmd, cwd=os.path.join(unpacked, "files"), capture_output=True, text=True,
                         check=False)
    try:
        report = json.loads(out.stdout)
    except json.JSONDecodeError:
        raise SystemExit(f"label_score: no JSON from {' '.join(cmd[:8])}...: {out.stderr[:500]}")
    findings, errors = [], set()
    resolution = collections.Counter(report["summary"].get("mesh_resolution", {}))
    for entry in report["files"]:
        for f in entry["findings"]:
            if f["rule"] == "inertia-not-physical" and "group_links" not in f.get("values", {}):
                errors.add((entry["path"], f.get("link", "")))
            if f["severity"] == "note" or (f["rule"] in exact and f["severity"] != "error"):
                continue
            findings.append((entry["path"], f["rule"], f.get("link", ""), f["severity"],
                             f.get("message", "")))
    return findings, errors, resolution


def oracle_invalid(base, files):
    """(file, link) of the links oracle.json finds invalid, as sets 1-2 are judged: an inertial
    that is neither valid nor of mass zero."""
    with open(os.path.join(base, "oracle.json")) as f:
        oracle = json.load(f)
    by_index = {int(name.split("_")[0]): name for name in files}
    invalid = set()
    for index, links in oracle.items():
        for link in links:
            ok = link.get("tensor_ok_1e6", link.get("valid") or link.get("mass_zero"))
            if link.get("has_inertial") and not ok:
                invalid.add((by_index.get(int(index), index), link["link"]))
    return invalid


def tally(labels, findings, exact):
    """The figures of one scoring: overall counts and per rule."""
    flagged = collections.defaultdict(set)  # (file, link) -> rules of its warnings
    found = collections.defaultdict(set)  # (file, link) -> rules of any warning or error
    for path, rule, link, severity, _ in findings:
        found[(path, link)].add(rule)
        if severity == "warning" and rule not in exact:
            flagged[(path, link)].add(rule)
    kind = {k: labels.get(k, ("noise", ""))[0] for k in flagged}
    real = sorted(k for k, (label, _) in labels.items() if label == "real")
    per_rule = collections.defaultdict(lambda: [0, 0, 0])  # real flagged, noise flagged, real found
    for k, rules in flagged.items():
        for rule in rules:
            if kind[k] != "either":
                per_rule[rule][0 if kind[k] == "real" else 1] += 1
    for k in real:
        for rule in found.get(k, ()):
            per_rule[rule][2] += 1
    return flagged, found, kind, real, per_rule


def ratio(a, b):
    return a / b if b else None


def fmt(x):
    return "—" if x is None else f"{x:.3f}"


def score(name, labels, findings, exact, listing):
    """Prints the figures; returns {rule or 'all': (precision, recall)}."""
    flagged, found, kind, real, per_rule = tally(labels, findings, exact)
    tp = sum(1 for k in kind.values() if k == "real")
    fp = sum(1 for k in kind.values() if k == "noise")
    either = sum(1 for k in kind.values() if k == "either")
    hit = [k for k in real if k in found]
    prec, rec = ratio(tp, tp + fp), ratio(len(hit), len(real))
    print(f"## {name}: flagged links {tp + fp} (real {tp}, noise {fp}; {either} either, not "
          f"counted): precision {fmt(prec)}; real links {len(real)}, reported {len(hit)}: recall "
          f"{fmt(rec)}")
    by_file = collections.Counter(k[0] for k in real)
    if by_file:
        top, n = by_file.most_common(1)[0]
        rest = [k for k in hit if k[0] != top]
        print(f"   without {top} ({n} real links): recall {fmt(ratio(len(rest), len(real) - n))}"
              f" ({len(rest)} of {len(real) - n})")
    figures = {"all": (prec, rec)}
    print("| rule | flagged real | flagged noise | precision | real links reported | share of"
          " real |")
    print("|---|---:|---:|---:|---:|---:|")
    for rule in sorted(per_rule):
        a, b, c = per_rule[rule]
        figures[rule] = (ratio(a, a + b), ratio(c, len(real)))
        print(f"| `{rule}` | {a} | {b} | {fmt(figures[rule][0])} | {c} | {fmt(figures[rule][1])} |")
    if listing:
        print("\nnoise flagged:")
        for k in sorted(flagged):
            if kind[k] == "noise":
                why = labels.get(k, ("", "(no row)"))[1] or "(no row)"
                print(f"  NOISE {k[0]} {k[1]} {sorted(flagged[k])}: {why}")
        print("real missed:")
        for k in real:
            if k not in found:
                print(f"  MISS {k[0]} {k[1]}: {labels[k][1]}")
    return figures


def score_sets(tool, shared, work, extra, exact, listing):
    """Unpacks, checks and scores sets 3-5; returns (figures, oracle mismatches)."""
    labels, findings, mismatches = {}, [], []
    for name in SETS:
        base = os.path.join(shared, "labelled", name)
        unpacked = unpack(shared, work, name)
        files = robot_files(base)
        found, errors, resolution = run_set(tool, unpacked, files, extra, exact)
        invalid = oracle_invalid(base, files)
        for key in sorted(invalid ^ errors):
            mismatches.append(f"{name}/{key[0]} {key[1]}: " + (
                "oracle invalid, no error" if key in invalid else "error, oracle valid"))
        print(f"## {name} errors: {len(errors)} links with inertia-not-physical, {len(invalid)} "
              f"invalid by oracle.json, {len(invalid ^ errors)} differ; meshes: "
              + ", ".join(f"{k} {v}" for k, v in sorted(resolution.items()) if v))
        for (file, link), value in read_link_labels(os.path.join(base, "labels-links.tsv")).items():
            labels[(name + "/" + file, link)] = value
        findings += [(name + "/" + f[0],) + tuple(f[1:]) for f in found]
    for m in mismatches:
        print("  ORACLE", m)
    figures = score("sets 3-5 (validation with meshes: ../shared/labelled set3..set5)", labels,
                    findings, exact, listing)
    return figures, mismatches
