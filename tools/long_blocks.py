#!/usr/bin/env python3
"""Finds the C++ files in which a function could be over the size limit, from their text alone.

A function of more than 120 lines (clang-tidy's readability-function-size, .clang-tidy) has a
body: a brace block of more than 120 lines. This script scans each file's braces (outside
comments, string, raw-string and character literals) and prints the files holding a block of at
least MIN lines (default 100, a margin below the limit) that is not a namespace, class, struct,
union or enum body (their functions are blocks of their own, found inside them). A file it does
not print holds no function longer than MIN lines, so clang-tidy need not be run on it for the
size check: tools/lint.sh --long-only runs clang-tidy on the files printed here (and on the
sources that include a printed header), where it alone decides. The scan may print too much
(a long initializer list, a block in a macro), never too little.

Usage: long_blocks.py [--min N] [--verbose] FILE...   (prints one FILE per line; --verbose adds
each long block's first line and length). Exit 0.
"""
import re
import sys

CONTAINER = re.compile(r"^(?:template\s*<[^{;]*>\s*)?(?:inline\s+)?"
                       r"(?:namespace|class|struct|union|enum)\b|^extern\s+\"C\"$")
COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)


def _statement_head(text):
    """The code before a '{' since the last ; { or }: no comments, no preprocessor lines."""
    text = COMMENT.sub(" ", text)
    lines = [ln for ln in text.splitlines() if not ln.lstrip().startswith("#")]
    return " ".join(" ".join(lines).split())


def _skip_literal(text, i):
    """Index just past the literal, comment or raw string starting at text[i], or i."""
    if text.startswith("//", i):
        end = text.find("\n", i)
        return len(text) if end < 0 else end
    if text.startswith("/*", i):
        end = text.find("*/", i + 2)
        return len(text) if end < 0 else end + 2
    c = text[i]
    if c == '"' and i > 0 and text[i - 1] == "R":
        m = re.compile(r'R"([^(\s]{0,16})\(').match(text, i - 1)
        if m:
            end = text.find(")" + m.group(1) + '"', m.end())
            return len(text) if end < 0 else end + len(m.group(1)) + 2
    if c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):
        # A character literal, or a string; a ' after a digit or letter is a digit separator.
        j = i + 1
        while j < len(text) and text[j] != c and text[j] != "\n":
            j += 2 if text[j] == "\\" else 1
        return j + 1
    return i


def long_blocks(text, minimum):
    """[(first line, lines)] of the non-container brace blocks of at least `minimum` lines."""
    found = []
    stack = []  # (line of the '{', is a container)
    line = 1
    head_start = 0  # where the text before the next '{' starts (after the last ; { or })
    i = 0
    while i < len(text):
        j = _skip_literal(text, i)
        if j != i:
            line += text.count("\n", i, j)
            i = j
            continue
        c = text[i]
        if c == "\n":
            line += 1
        elif c == "{":
            head = _statement_head(text[head_start:i])
            stack.append((line, bool(CONTAINER.match(head)) and "(" not in head))
            head_start = i + 1
        elif c == "}":
            if stack:
                start, container = stack.pop()
                if not container and line - start + 1 >= minimum:
                    found.append((start, line - start + 1))
            head_start = i + 1
        elif c == ";":
            head_start = i + 1
        i += 1
    return found


def main(argv):
    minimum, verbose, files = 100, False, []
    k = 0
    while k < len(argv):
        if argv[k] == "--min":
            minimum = int(argv[k + 1])
            k += 2
            continue
        if argv[k] == "--verbose":
            verbose = True
        else:
            files.append(argv[k])
        k += 1
    for path in files:
        with open(path, encoding="utf-8", errors="replace") as f:
            blocks = long_blocks(f.read(), minimum)
        if blocks:
            print(path)
            if verbose:
                for start, lines in blocks:
                    print(f"  {path}:{start}: a block of {lines} lines", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
