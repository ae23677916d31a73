#!/usr/bin/env python3
"""tests/shared_data.py and tests/shared_data.h, the one policy of the tests that read ../shared:
skipped without it, with the reason the issue words, failed where it is present (or
MASSPROPS_REQUIRE_SHARED=1); the C++ header in the same words; and the count of tools/test.sh's
last line, on the JUnit file of a real ctest run of four tests whose outcomes are set here."""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import shared_data  # noqa: E402

# The reason as issue 46 spells it, for ../shared/corpus.
ISSUE_REASON = ("../shared/corpus not found: the corpus tests are skipped; docs/development.md "
                "says where the corpus comes from")


def header_string(name):
    """The value of `inline constexpr const char* NAME = "..." "...";` in shared_data.h."""
    text = (HERE / "shared_data.h").read_text()
    match = re.search(name + r' =((?:\s*"[^"]*")+);', text)
    return "".join(re.findall(r'"([^"]*)"', match.group(1)))


class SharedDataTest(unittest.TestCase):
    def setUp(self):
        self.top = pathlib.Path(tempfile.mkdtemp(prefix="massprops-shared-test-"))
        self.shared = self.top / "shared"
        self.saved = os.environ.pop("MASSPROPS_REQUIRE_SHARED", None)

    def tearDown(self):
        shutil.rmtree(self.top)
        if self.saved is not None:
            os.environ["MASSPROPS_REQUIRE_SHARED"] = self.saved

    def run_helper(self, *parts):
        return subprocess.run([sys.executable, str(HERE / "shared_data.py"), str(self.shared),
                               *parts], capture_output=True, text=True)

    def test_the_header_has_the_same_words(self):
        self.assertEqual(header_string("kSharedMissing"), shared_data.MISSING)
        self.assertEqual(header_string("kSharedRequired"), shared_data.REQUIRED)

    def test_without_shared_the_reason_is_the_issues_and_names_the_first_missing_folder(self):
        self.assertFalse(shared_data.required(self.shared))
        self.assertEqual(shared_data.missing(self.shared, "corpus/MANIFEST.tsv"), ISSUE_REASON)
        self.assertEqual(shared_data.missing(self.shared, "corpus"), ISSUE_REASON)
        run = self.run_helper("corpus/MANIFEST.tsv")
        self.assertEqual((run.returncode, run.stdout), (77, ISSUE_REASON + "\n"))

    def test_with_shared_present_a_missing_part_is_a_failure_naming_it(self):
        (self.shared / "corpus").mkdir(parents=True)
        self.assertTrue(shared_data.required(self.shared))
        self.assertEqual(shared_data.missing(self.shared, "corpus"), "")
        why = shared_data.missing(self.shared, "corpus/MANIFEST.tsv")
        self.assertEqual(why, f"../shared/corpus/MANIFEST.tsv not found in {self.shared}: where "
                         "../shared is present (or MASSPROPS_REQUIRE_SHARED=1) a corpus test "
                         "fails rather than skips; docs/development.md says what ../shared holds")
        run = self.run_helper("corpus", "labelled")
        self.assertEqual(run.returncode, 1)
        self.assertTrue(run.stdout.startswith("../shared/labelled not found in "), run.stdout)
        (self.shared / "labelled").mkdir()
        run = self.run_helper("corpus", "labelled")
        self.assertEqual((run.returncode, run.stdout), (0, ""))

    def test_require_shared_makes_a_missing_shared_a_failure(self):
        os.environ["MASSPROPS_REQUIRE_SHARED"] = "1"
        self.assertTrue(shared_data.required(self.shared))
        self.assertNotIn(shared_data.MISSING, shared_data.missing(self.shared, "xacro"))
        self.assertEqual(self.run_helper("xacro").returncode, 1)

    def test_the_count_takes_only_tests_ctest_skipped_for_shared(self):
        cmake, ctest = shutil.which("cmake"), shutil.which("ctest")
        if not cmake or not ctest:
            self.skipTest("cmake or ctest not found")
        # Four tests: skipped by exit code 77 for ../shared (counted); skipped by 77 for another
        # reason; passed with the reason in a note; skipped by GoogleTest's mark for ../shared
        # (counted). 2 counted.
        echo = "echo '{}'; exit {}"
        (self.top / "CMakeLists.txt").write_text(f"""cmake_minimum_required(VERSION 3.16)
project(shared_skips NONE)
enable_testing()
add_test(NAME shared COMMAND sh -c "{echo.format(ISSUE_REASON, 77)}")
add_test(NAME other COMMAND sh -c "{echo.format('no display', 77)}")
add_test(NAME note COMMAND sh -c "{echo.format('note: ' + ISSUE_REASON, 0)}")
add_test(NAME gtest COMMAND sh -c "{echo.format(ISSUE_REASON + ' [  SKIPPED ] T.t', 0)}")
set_tests_properties(shared other PROPERTIES SKIP_RETURN_CODE 77)
set_tests_properties(gtest PROPERTIES SKIP_REGULAR_EXPRESSION "\\\\[  SKIPPED \\\\]")
""")
        build = self.top / "build"
        subprocess.run([cmake, "-S", str(self.top), "-B", str(build)], check=True,
                       capture_output=True)
        junit = build / "junit.xml"
        run = subprocess.run([ctest, "--output-junit", str(junit)], cwd=build,
                             capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stdout)
        self.assertEqual(run.stdout.count("(Skipped)"), 3, run.stdout)  # all but note
        self.assertEqual(shared_data.count_skipped([junit]), 2)
        self.assertEqual(shared_data.count_skipped([junit, junit]), 4)
        count = subprocess.run([sys.executable, str(HERE / "shared_data.py"), "--count",
                                str(junit)], capture_output=True, text=True)
        self.assertEqual(count.stdout, "2\n")


if __name__ == "__main__":
    unittest.main(verbosity=2)
