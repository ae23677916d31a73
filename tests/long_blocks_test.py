#!/usr/bin/env python3
"""tools/long_blocks.py, the scan that chooses where ctest clang_tidy_passes runs clang-tidy.

It must never miss a long function (the size check would then not run on it), whatever braces
hide in comments and literals. Each expected block below is counted by hand: the lines from the
one holding '{' to the one holding '}', both included.
Usage: long_blocks_test.py TOOLS/long_blocks.py TESTDATA/lint
"""
import importlib.util
import pathlib
import sys

spec = importlib.util.spec_from_file_location("long_blocks", sys.argv[1])
scan = importlib.util.module_from_spec(spec)
spec.loader.exec_module(scan)
lint = pathlib.Path(sys.argv[2])
failures = []


def expect(name, text, minimum, want):
    got = scan.long_blocks(text, minimum)
    if got != want:
        failures.append(f"{name}: {got}, expected {want}")


# The clang-tidy fixture: '{' on line 5, '}' on line 127 (wc -l: 127 lines) → 123 lines.
expect("long_function.cc", (lint / "long_function.cc").read_text(), 100, [(5, 123)])

# A function of 110 lines (1 + 108 + 1) whose body hides braces in every kind of literal and
# comment; a digit separator must not open a character literal.
body = ['  const char* a = "}}";', "  char b = '{';", "  // } a comment", "  /* { */",
        '  const char* c = R"x(}})x";', "  int d = 1'000;", "  (void)a; (void)b; (void)c;"]
body += ["  d += 1;"] * (108 - len(body))
function = "int F() {\n" + "\n".join(body) + "\n}\n"
expect("braces in literals", function, 100, [(1, 110)])
expect("below the minimum", function, 111, [])

# A namespace and a class are no functions; their members are. The class spans lines 2-200 and
# holds, from its line 3, a member function of 105 lines (lines 4-108 of the text).
member = "  void G() {\n" + "    int x = 0;\n" * 103 + "  }\n"
klass = "class C {\n public:\n" + member + "  int y = 0;\n" * 91 + "};\n"
text = "namespace n {\n" + klass + "}  // namespace n\n"
expect("namespace, class and member", text, 100, [(4, 105)])

# A namespace of 150 lines with two functions of 50: nothing at 100.
short = "void H() {\n" + "  int z = 0;\n" * 48 + "}\n"
expect("short functions in a long namespace", "namespace {\n" + short * 3 + "}\n", 100, [])

for f in failures:
    print(f)
print(f"long_blocks_test: {len(failures)} failure(s)")
sys.exit(1 if failures else 0)
