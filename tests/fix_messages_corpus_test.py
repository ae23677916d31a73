#!/usr/bin/env python3
"""`massprops fix` at a glance over ../shared/corpus (docs/fix.md, "What fix says"): runs
`massprops fix FILE` and `massprops fix --dry-run FILE` (writing nothing; the model and package
paths of tools/fix_trust_check.py) on every URDF/SDF of MANIFEST.tsv and fails unless

  - every message (a line that does not start with a space) has a headline of at most 110
    characters: what is left after its `FILE:LINE: SEVERITY: ` or `massprops: [FILE: ]` lead and
    its trailing ` [rule]` (and ` (no repair)`), as `check`'s headlines are measured;
  - every line under a message (starting with a space) has at most 100 characters;
  - no line is cut with "…";
  - every refused repair (a headline with ": not repaired: ") is followed, before the next
    message, by a help line (`  = help: ...` and its indented continuation lines) that names a
    `massprops` command.

Usage: fix_messages_corpus_test.py MASSPROPS CORPUS_DIR. Exit 77 without ../shared
(tests/shared_data.py)."""
import concurrent.futures
import csv
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shared_data  # noqa: E402  (tests/shared_data.py: the one policy for ../shared)

TOOL, CORPUS = (os.path.abspath(a) for a in sys.argv[1:3])
shared_data.check(os.path.dirname(CORPUS), [os.path.basename(CORPUS) + "/MANIFEST.tsv"])
PATHS = ["--package-path", "."]
for p in ["gazebo_models", "sdformat/test/integration/model", "gz-sim/test/worlds/models",
          "example-robot-data/robots"]:
    PATHS += ["--model-path", p]

LOCATED = re.compile(r"^\S+?:\d+(?::\d+)?: (?:(?:error|warning|note): )?(.*)$")
READ_ERROR = re.compile(r"^\S+?:\d+(?::\d+)?: <[A-Za-z_]+>")
RULE_TAIL = re.compile(r" \[[a-z0-9-]+( → [a-z0-9+-]+)?\]( \(no repair\))?(: .*)?$")


def headline(line, path):
    """The headline of a message line, measured as check measures its headlines."""
    if line.startswith("massprops: "):
        text = line[len("massprops: "):]
        for lead in ("error: ", "warning: ", "note: ", path + ": ", "<stdin>: "):
            if text.startswith(lead):
                text = text[len(lead):]
        return text
    if line.startswith(path + ": "):  # a status line about the whole file: "PATH: no change needed"
        return line[len(path) + 2:]
    m = LOCATED.match(line)
    text = m.group(1) if m else line
    if text.startswith("not applied (a guess): "):
        text = text[len("not applied (a guess): "):]
    return RULE_TAIL.sub("", text)


def problems(path, text):
    found = []
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if "…" in line:
            found.append(f"{path}: cut with …: {line}")
        if not line:
            continue
        if line.startswith(" "):
            if len(line) > 100:
                found.append(f"{path}: line of {len(line)} characters: {line}")
            continue
        if READ_ERROR.match(line):
            # The reader's own errors (file:line: <element> ...), which fix prints as the reader
            # words them; `check` renders them as headline and why (text_lines_test). Left for
            # fix: docs/fix.md, "What fix says".
            continue
        h = headline(line, path)
        if len(h) > 110:
            found.append(f"{path}: headline of {len(h)} characters: {line}")
        if ": not repaired: " in line:
            block = []
            for under in lines[i + 1:]:
                if not under.startswith(" "):
                    break
                block.append(under)
            helps = "\n".join(u for u in block if u.startswith("  = help: ") or
                              u.startswith("    "))
            if "massprops " not in helps:
                found.append(f"{path}: a refused repair without a help naming a command: {line}")
    return found


def run(path):
    """The problems of fix's messages on one file, and whether it refused a repair."""
    out = []
    refused = 0
    for extra in ([], ["--dry-run"]):
        r = subprocess.run([TOOL, "fix"] + extra + PATHS + [path], cwd=CORPUS,
                           capture_output=True, text=True, errors="replace")
        text = r.stderr + ("\n" + r.stdout if extra else "")
        refused += text.count(": not repaired: ")
        out += problems(path, text)
    return out, refused


def main():
    with open(os.path.join(CORPUS, "MANIFEST.tsv"), newline="") as f:
        models = [r["file"] for r in csv.DictReader(f, delimiter="\t")
                  if r["format"] in ("urdf", "sdf") and os.path.exists(os.path.join(CORPUS, r["file"]))]
    failures = []
    refused = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for found, n in pool.map(run, models):
            failures += found
            refused += n
    for f in failures:
        print(f)
    print(f"{len(models)} files; {refused} refused-repair messages (plain and --dry-run); "
          f"{len(failures)} problem(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
