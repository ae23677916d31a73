#!/usr/bin/env python3
"""docs/targets.md and the code of the target profiles stay in step (issue 35).

docs/targets.md has a section per simulator (`## MuJoCo ...`, `## Drake`, `## Gazebo`), one per
`--target` value but generic. Each section's `Code:` line names the files of
src/analysis/targets/ that emulate that simulator, and the paragraph before the first section
names the layer they share. The test fails when
  - a file of src/analysis/targets/ is named by no section, or by two;
  - a named file does not exist;
  - a rule of `massprops check --list-rules` that belongs to a target (its id starts with the
    target's name: mujoco-..., drake-..., gazebo-...) is not named in that target's section;
  - a target the tool takes (`--target` in `massprops check --help`) has no section.
The comparison is also run on a copy of the page with a file left out of a `Code:` line and a
rule left out of its section, which it must reject (so that the test can fail).

Usage: targets_docs_test.py MASSPROPS DOCS_DIR TARGETS_SRC_DIR
"""
import pathlib
import re
import subprocess
import sys

SECTION = re.compile(r"^## (MuJoCo|Drake|Gazebo)\b.*$", re.M)
CODE_FILE = re.compile(r"`(src/analysis/targets/[A-Za-z0-9_./]+)`")


def tool_rules(tool):
    out = subprocess.run([tool, "check", "--list-rules"], check=True, capture_output=True,
                         text=True).stdout
    return [line.split()[0] for line in out.splitlines() if line.strip()]


def tool_targets(tool):
    """The values of --target, from `check --help` ("--target TEXT:{generic,mujoco,...}")."""
    out = subprocess.run([tool, "check", "--help"], check=True, capture_output=True,
                         text=True).stdout
    m = re.search(r"--target \S*\{([a-z,]+)\}", out)
    return m.group(1).split(",") if m else []


def code_lines(text):
    """The files named on the `Code:` lines (and the line's continuation) of a piece of page."""
    files = []
    for m in re.finditer(r"^Code\b[^:]*:(.*?)(?:\n\n|\Z)", text, re.M | re.S):
        files += CODE_FILE.findall(m.group(1))
    return files


def problems(page, source_files, rules, targets):
    found = []
    sections = {}
    marks = list(SECTION.finditer(page))
    for i, m in enumerate(marks):
        end = marks[i + 1].start() if i + 1 < len(marks) else len(page)
        body = page[m.end():end]
        # A section ends at the next `## ` heading (its `###` subsections belong to it).
        nxt = re.search(r"^## ", body, re.M)
        sections[m.group(1).lower()] = body[:nxt.start()] if nxt else body
    shared = page[:marks[0].start()] if marks else page
    named = {"shared layer": code_lines(shared)}
    for name, body in sections.items():
        named[name] = code_lines(body)
    for target in targets:
        if target != "generic" and target not in sections:
            found.append(f"--target {target} has no '## ' section in docs/targets.md")
    owners = {}
    for owner, files in named.items():
        for f in files:
            owners.setdefault(f, []).append(owner)
    for f, who in sorted(owners.items()):
        if f not in source_files:
            found.append(f"docs/targets.md ({who[0]}) names {f}, which does not exist")
        if len(who) > 1:
            found.append(f"{f} is named by several sections: {', '.join(who)}")
    for f in sorted(source_files):
        if f not in owners:
            found.append(f"{f} is named by no section's Code: line of docs/targets.md")
    for rule in rules:
        target = rule.split("-")[0]
        if target in sections and f"`{rule}`" not in sections[target]:
            found.append(f"the rule {rule} is not described in the {target} section")
    return found


def main(argv):
    tool, docs, src = argv[1], pathlib.Path(argv[2]), pathlib.Path(argv[3])
    page = (docs / "targets.md").read_text(encoding="utf-8")
    root = src.parent.parent.parent  # src/analysis/targets -> the checkout
    source_files = {p.relative_to(root).as_posix() for p in src.iterdir()
                    if p.suffix in (".h", ".cc")}
    rules = tool_rules(tool)
    targets = tool_targets(tool)
    if not targets:
        sys.exit("targets_docs_test: cannot read the --target values from `check --help`")
    found = problems(page, source_files, rules, targets)
    for p in found:
        print(p)
    # The same comparison on a broken copy must fail: drake.cc left out of its Code: line, and
    # gazebo-lumps-fixed-joint out of its section.
    broken = page.replace("Code: `src/analysis/targets/drake.cc`.", "Code: none.")
    broken = broken.replace("`gazebo-lumps-fixed-joint` note with", "note with")
    expected = {"src/analysis/targets/drake.cc is named by no section's Code: line of "
                "docs/targets.md",
                "the rule gazebo-lumps-fixed-joint is not described in the gazebo section"}
    missed = expected - set(problems(broken, source_files, rules, targets))
    if missed:
        print("the check does not reject a broken page:", *sorted(missed), sep="\n  ")
        return 1
    if found:
        return 1
    print(f"targets_docs_test: {len(source_files)} files of src/analysis/targets/ in "
          f"{len(SECTION.findall(page))} sections and the shared layer; every target rule in "
          "its section")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
