"""../shared beside the checkout: the real-robot corpus (corpus/), the labelled set (labelled/) and
the xacro packages (xacro/), which a fresh clone does not have (docs/development.md, "The shared
corpus"). The policy of tests/shared_data.h for the Python and script tests, in the same words:

  - ../shared absent: the test is skipped, with MISSING's reason (exit code SKIP_EXIT for a
    script that ctest runs, its SKIP_RETURN_CODE);
  - ../shared present (as in CI), or MASSPROPS_REQUIRE_SHARED=1: a missing part fails the test.

tools/test.sh counts the skips by MISSING's words.

As a command, for shell tests: `shared_data.py SHARED_DIR PART...` exits 0 when every
SHARED_DIR/PART exists; otherwise it prints why and exits SKIP_EXIT, or 1 where ../shared is
required. `shared_data.py --count JUNIT_XML...` prints how many tests of those ctest runs
(`ctest --output-junit`) were skipped for a missing ../shared (tools/test.sh's last line)."""
import os
import pathlib
import sys
import xml.etree.ElementTree as ET

# The words after "../shared/<part> not found" (kSharedMissing and kSharedRequired of
# tests/shared_data.h; tests/shared_data_test.py checks that they are the same).
MISSING = (" not found: the corpus tests are skipped; docs/development.md says where the corpus "
           "comes from")
REQUIRED = (": where ../shared is present (or MASSPROPS_REQUIRE_SHARED=1) a corpus test fails "
            "rather than skips; docs/development.md says what ../shared holds")
SKIP_EXIT = 77


def required(shared):
    """Whether a missing part of `shared` is a failure rather than a skip."""
    return os.environ.get("MASSPROPS_REQUIRE_SHARED") == "1" or pathlib.Path(shared).is_dir()


def missing(shared, part):
    """'' when shared/part exists; otherwise why the test cannot run, naming the first missing
    folder or file of `part` (relative to `shared`: "corpus", "xacro/pmb2", ...)."""
    at = pathlib.Path(shared)
    names = []
    for name in pathlib.PurePosixPath(part).parts:
        at = at / name
        names.append(name)
        if at.exists():
            continue
        if required(shared):
            return f"../shared/{'/'.join(names)} not found in {shared}{REQUIRED}"
        return f"../shared/{'/'.join(names)}{MISSING}"
    return ""


def check(shared, parts):
    """For a script test: returns when every part exists; otherwise prints why and exits with
    SKIP_EXIT (skipped) or 1 (required)."""
    for part in parts:
        why = missing(shared, part)
        if why:
            print(why, flush=True)
            sys.exit(1 if required(shared) else SKIP_EXIT)


def count_skipped(junit_files):
    """The tests of `ctest --output-junit` files that ctest reports skipped (SKIP_RETURN_CODE, or
    GoogleTest's [  SKIPPED ]) and whose output gives MISSING's reason."""
    count = 0
    for path in junit_files:
        for case in ET.parse(path).getroot().iter("testcase"):
            if case.find("skipped") is not None and MISSING in (case.findtext("system-out") or ""):
                count += 1
    return count


if __name__ == "__main__":
    if len(sys.argv) >= 2 and sys.argv[1] == "--count":
        print(count_skipped(sys.argv[2:]))
    elif len(sys.argv) >= 3:
        check(sys.argv[1], sys.argv[2:])
    else:
        sys.exit(f"usage: {sys.argv[0]} SHARED_DIR PART... | --count JUNIT_XML...")
