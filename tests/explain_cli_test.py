#!/usr/bin/env python3
"""`massprops explain RULE` prints the rule's section of docs/rules.md (issue 32).

For every rule of `massprops check --list-rules` the command exits 0 and prints exactly the
section of docs/rules.md that documents it (`### `id` (...)` or `#### `id` (...)`, up to the next
heading of its level or above), extracted here independently of the tool: the binary carries the
text compiled in, so a docs/rules.md edited after the build, or a rule without a long form, fails.
An unknown rule exits 2 and lists every rule on standard error. The comparison is also run on a
copy of the page with one section's text changed, which must be told apart (so the test can fail).

Usage: explain_cli_test.py MASSPROPS DOCS_DIR
"""
import pathlib
import re
import subprocess
import sys

HEADING = re.compile(r"^(#+) (?:`([a-z0-9-]+)`)?")


def sections(markdown):
    """{rule: text} of every `###`/`####` section naming a rule, as the tool cuts them."""
    out = {}
    current, level, in_code = None, 0, False
    for line in markdown.split("\n"):
        if line.startswith("```"):
            in_code = not in_code
        m = None if in_code else HEADING.match(line)
        if m:
            this = len(m.group(1))
            if current and this <= level:
                current = None
            if this >= 3 and m.group(2):
                current, level = m.group(2), this
                out[current] = []
        if current:
            out[current].append(line)
    return {rule: "\n".join(lines).rstrip(" \n") + "\n" for rule, lines in out.items()}


def listed(tool):
    text = subprocess.run([tool, "check", "--list-rules"], check=True, capture_output=True,
                          text=True).stdout
    return [line.split()[0] for line in text.splitlines() if line.strip()]


def main():
    tool, docs = sys.argv[1], pathlib.Path(sys.argv[2])
    expected = sections((docs / "rules.md").read_text())
    rules = listed(tool)
    problems = []
    for rule in rules:
        run = subprocess.run([tool, "explain", rule], capture_output=True, text=True)
        if run.returncode != 0:
            problems.append(f"explain {rule}: exit {run.returncode}: {run.stderr.strip()}")
        elif rule not in expected:
            problems.append(f"explain {rule}: docs/rules.md has no section for it")
        elif run.stdout != expected[rule]:
            problems.append(f"explain {rule}: differs from docs/rules.md (rebuild, or drift)")
    # The check can fail: a changed section is told apart.
    some = rules[0]
    changed = sections((docs / "rules.md").read_text().replace(
        expected[some].split("\n")[1], "a different first line", 1))
    shown = subprocess.run([tool, "explain", some], capture_output=True, text=True).stdout
    if changed.get(some) == shown:
        problems.append("a changed section of docs/rules.md was not told apart")
    unknown = subprocess.run([tool, "explain", "no-such-rule"], capture_output=True, text=True)
    if unknown.returncode != 2:
        problems.append(f"explain no-such-rule: exit {unknown.returncode}, expected 2")
    for rule in rules:
        if f"  {rule}\n" not in unknown.stderr:
            problems.append(f"explain no-such-rule: the list on standard error lacks {rule}")
            break
    for p in problems:
        print(p)
    print(f"{len(rules)} rules explained, {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
