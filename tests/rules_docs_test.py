#!/usr/bin/env python3
"""docs/rules.md and `massprops check --list-rules` name the same rules (issue 25).

Every rule the tool lists must be documented: the rules of `massprops check` and the geometry
rules each by a section `### `id` (severity...)` of docs/rules.md, in the order of --list-rules and
with its severity ("(warning, off unless `--geometry`)" for a rule off by default), and in the
table under "## The rules"; the rules the readers report by the page docs/rules.md points to for
them (docs/urdf.md, docs/sdf.md); the `--target` rules by a row of docs/targets.md's table. A rule
added without its documentation therefore fails. The comparison is also run on a copy of
docs/rules.md with one section removed and one severity changed, which it must reject (so the
test can fail).

Usage: rules_docs_test.py MASSPROPS DOCS_DIR
"""
import pathlib
import re
import subprocess
import sys

SECTION = re.compile(r"^### `([a-z0-9-]+)` \(([^)]*)\)", re.M)
TABLE_ROW = re.compile(r"^\| `([a-z0-9-]+)` \| ([^|]+?) \|", re.M)
# --list-rules: id, severity ("warning" or "warning (off)"), summary.
LISTED = re.compile(r"^(\S+)\s+(note|warning|error)( \(off\))?\s+(.*)$")


def listed_rules(tool):
    out = subprocess.run([tool, "check", "--list-rules"], check=True, capture_output=True,
                         text=True).stdout
    rules = []
    for line in out.splitlines():
        m = LISTED.match(line)
        if not m:
            sys.exit(f"--list-rules: cannot read the line {line!r}")
        rules.append((m.group(1), m.group(2), m.group(3) is None, m.group(4)))
    return rules


def reader_pages(rules_md):
    """{rule: page} from the paragraph of docs/rules.md naming the readers' rules."""
    m = re.search(r"Besides these, the readers report(.*?)\n\n", rules_md, re.S)
    if not m:
        return {}
    pages = {}
    names = []
    for token in re.finditer(r"`([a-z0-9-]+)`|\[[a-z]+\.md\]\(([a-z]+\.md)\)", m.group(1)):
        if token.group(1):
            names.append(token.group(1))
        else:
            for name in names:
                pages[name] = token.group(2)
            names = []
    return pages


def compare(listed, rules_md, docs):
    """The differences between the listed rules and the docs, one line each."""
    problems = []
    target = [r for r in listed if r[3].startswith("--target ")]
    readers = reader_pages(rules_md)
    own = [r for r in listed if r not in target and r[0] not in readers]
    sections = SECTION.findall(rules_md)
    expected = [(rid, sev, on) for rid, sev, on, _ in own]
    found = [(rid, text.split(",")[0].strip(), "off" not in text) for rid, text in sections]
    if [e[0] for e in expected] != [f[0] for f in found]:
        problems.append("docs/rules.md sections " + " ".join(f[0] for f in found) +
                        "\n  differ from --list-rules " + " ".join(e[0] for e in expected))
    for e, f in zip(expected, found):
        if e[0] == f[0] and e != f:
            problems.append(f"`{e[0]}`: --list-rules says {e[1]}{'' if e[2] else ' (off)'}, "
                            f"docs/rules.md's section says {f[1]}{'' if f[2] else ' (off)'}")
    table = rules_md.split("## The rules", 1)[-1]
    rows = [(rid, sev.split(",")[0].strip()) for rid, sev in TABLE_ROW.findall(table)]
    if rows != [(e[0], e[1]) for e in expected]:
        problems.append("the table under '## The rules' of docs/rules.md differs from "
                        "--list-rules: " + str(rows))
    for rid, sev, _, _ in listed:
        if rid in readers:
            page = (docs / readers[rid]).read_text(encoding="utf-8")
            if f"`{rid}`" not in page:
                problems.append(f"`{rid}`: docs/rules.md points to {readers[rid]}, which does "
                                "not name it")
    targets_md = (docs / "targets.md").read_text(encoding="utf-8")
    target_rows = dict(TABLE_ROW.findall(targets_md))
    for rid, sev, _, _ in target:
        if target_rows.get(rid, "").strip() != sev:
            problems.append(f"`{rid}` ({sev}): no row `| `{rid}` | {sev} |` in docs/targets.md")
    return problems


def main():
    tool, docs = sys.argv[1], pathlib.Path(sys.argv[2])
    listed = listed_rules(tool)
    rules_md = (docs / "rules.md").read_text(encoding="utf-8")
    problems = compare(listed, rules_md, docs)
    for p in problems:
        print("FAIL:", p)
    # The comparison must reject docs that lack a section or give a wrong severity.
    first = SECTION.search(rules_md)
    second = SECTION.search(rules_md, first.end())
    without_first = rules_md[:first.start()] + rules_md[second.start():]
    if not compare(listed, without_first, docs):
        print("FAIL: a docs/rules.md without the section of", first.group(1), "was accepted")
        problems.append("self-test")
    wrong_severity = rules_md.replace(first.group(0), f"### `{first.group(1)}` (note)", 1)
    if not compare(listed, wrong_severity, docs):
        print("FAIL: a docs/rules.md with", first.group(1), "as a note was accepted")
        problems.append("self-test")
    if problems:
        return 1
    print(f"OK: {len(listed)} rules listed, each documented")
    return 0


if __name__ == "__main__":
    sys.exit(main())
