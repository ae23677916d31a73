#!/usr/bin/env python3
"""Checks the size limit of the source files (docs/development.md, "Size limits").

Every .h and .cc file in src/, include/ and python/src/ has at most LIMIT lines (900), unless a
line of docs/development.md names it with its reason, as "- `path/of/file.cc`: the reason"
(at least three words). A reason that names a file that no longer exists, or one within the
limit, is reported too, so that the list does not outlive its files. (The length of functions,
120 lines, is clang-tidy's readability-function-size in .clang-tidy; tools/lint.sh runs both.)

Usage: check_size.py [--limit N] [ROOT]   (ROOT: the checkout, default: this script's parent)
Exit 0 when every file keeps the limit, 1 with one line per violation (file: lines) otherwise.
"""
import pathlib
import re
import sys

FOLDERS = ("src", "include", "python/src")
REASON = re.compile(r"^\s*[-*]\s+`(?P<path>[^`]+)`\s*:\s*(?P<reason>.+?)\s*$")


def reasons(root):
    """{path: reason} from docs/development.md's "- `path`: reason" lines."""
    doc = root / "docs" / "development.md"
    found = {}
    if doc.exists():
        for line in doc.read_text(encoding="utf-8").splitlines():
            m = REASON.match(line)
            if m and len(m.group("reason").split()) >= 3:
                found[m.group("path")] = m.group("reason")
    return found


def main(argv):
    limit = 900
    if len(argv) >= 2 and argv[0] == "--limit":
        limit = int(argv[1])
        argv = argv[2:]
    root = pathlib.Path(argv[0] if argv else pathlib.Path(__file__).resolve().parent.parent)
    explained = reasons(root)
    problems = []
    checked = 0
    for folder in FOLDERS:
        base = root / folder
        if not base.is_dir():
            continue
        for path in sorted(base.rglob("*")):
            if path.suffix not in (".h", ".cc") or not path.is_file():
                continue
            checked += 1
            rel = path.relative_to(root).as_posix()
            with path.open(encoding="utf-8", errors="replace") as f:
                lines = sum(1 for _ in f)
            if lines > limit and rel not in explained:
                problems.append(f"{rel}: {lines} lines, more than {limit}: split it along its "
                                "seams, or name it with the reason in docs/development.md "
                                f"(\"- `{rel}`: why\")")
            elif lines <= limit and rel in explained and any(
                    rel.startswith(f + "/") for f in FOLDERS):
                problems.append(f"docs/development.md names {rel}, which has {lines} lines, "
                                f"within the limit of {limit}: remove its line")
    for rel in sorted(explained):
        if any(rel.startswith(f + "/") for f in FOLDERS) and not (root / rel).is_file():
            problems.append(f"docs/development.md names {rel}, which does not exist")
    for p in problems:
        print(p)
    if problems:
        print(f"check_size: {len(problems)} violation(s)")
        return 1
    print(f"check_size: {checked} files in {', '.join(FOLDERS)} within {limit} lines "
          f"({len(explained)} named with a reason)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
