#!/usr/bin/env python3
"""Checks the include directions between the parts of massprops (docs/architecture.md).

Each part is a folder of include/massprops/ and of src/ (src/tool/ for the command-line tool). The
first line starting with "May include:" of the part's README.md (include/massprops/PART/README.md,
src/tool/README.md) lists the other parts its files may include. Every `#include
"massprops/PART/..."` and every private `#include "PART/..."` of a file in a part's folders must
name the part itself or one it may include, and the files must not include each other in a
circle. Also: no public header or source outside a part folder (but the umbrella header
include/massprops/massprops.h).

Usage: check_layers.py [ROOT]   (ROOT: the checkout, default: this script's parent folder)
Exit 0 when the layering holds, 1 with one line per violation (file:line) otherwise.
"""
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def allowed_parts(root):
    """{part: set of parts it may include} from the parts' README.md files."""
    readmes = {p.parent.name: p for p in (root / "include" / "massprops").glob("*/README.md")}
    tool = root / "src" / "tool" / "README.md"
    if tool.exists():
        readmes["tool"] = tool
    rules = {}
    for part, readme in readmes.items():
        for line in readme.read_text(encoding="utf-8").splitlines():
            if line.startswith("May include:"):
                names = re.findall(r"[a-z_]+", line[len("May include:"):])
                rules[part] = {n for n in names if n in readmes or n == part}
                break
        else:
            sys.exit(f"{readme}: no 'May include:' line")
    return rules


def files_of(root, part):
    for base in (root / "include" / "massprops" / part, root / "src" / part):
        if base.is_dir():
            yield from sorted(p for p in base.rglob("*") if p.suffix in (".h", ".cc"))


def included_part(name, parts):
    """The part an include names ("massprops/core/x.h" or private "core/x.h"), else None."""
    pieces = name.split("/")
    if len(pieces) >= 3 and pieces[0] == "massprops" and pieces[1] in parts:
        return pieces[1], "include/" + name
    if len(pieces) >= 2 and pieces[0] in parts:
        return pieces[0], "src/" + name
    return None, None


def find_cycle(graph):
    """One include circle of the graph {file: [(file, line)]}, as a list of files, or None."""
    state, stack = {}, []

    def visit(node):
        state[node] = 1
        stack.append(node)
        for target, _ in graph.get(node, ()):
            if state.get(target) == 1:
                return stack[stack.index(target):] + [target]
            if target not in state:
                found = visit(target)
                if found:
                    return found
        stack.pop()
        state[node] = 2
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent)
    rules = allowed_parts(root)
    problems, graph = [], {}
    public = root / "include" / "massprops"
    for stray in sorted(list(public.glob("*.h")) + list((root / "src").glob("*.cc")) +
                        list((root / "src").glob("*.h"))):
        if stray.name != "massprops.h":
            problems.append(f"{stray.relative_to(root)}: outside a part folder")
    for part in sorted(rules):
        for path in files_of(root, part):
            rel = path.relative_to(root).as_posix()
            text = path.read_text(encoding="utf-8", errors="replace").splitlines()
            for number, line in enumerate(text, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target, target_file = included_part(m.group(1), rules)
                if target is None:
                    continue
                graph.setdefault(rel, []).append((target_file, number))
                if target != part and target not in rules[part]:
                    may = ", ".join(sorted(rules[part] - {part})) or "no other part"
                    problems.append(f"{rel}:{number}: includes {m.group(1)}, but {part} may "
                                    f"include only: {may}")
    cycle = find_cycle(graph)
    if cycle:
        problems.append("include circle: " + " -> ".join(cycle))
    for p in problems:
        print(p)
    if problems:
        print(f"check_layers: {len(problems)} violation(s) of docs/architecture.md")
        return 1
    print(f"check_layers: {sum(len(v) for v in graph.values())} includes between parts follow "
          f"docs/architecture.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
