#!/usr/bin/env python3
"""`massprops check --format junit` and `--format gitlab` (docs/cli.md), judged against the
tool's own `--format json` on the real-robot corpus (../shared/corpus) and on small fixtures; run
by ctest with Debian's python3 (python3-junitparser reads the JUnit XML as GitLab's and Jenkins'
readers do).

Usage: ci_formats_test.py TOOL TESTDATA_DIR CORPUS_DIR [unittest arguments]

What is independent of the formats under test: the findings come from `--format json`; the
fingerprints are recomputed here with Python's hashlib (SHA-256, FIPS 180-4) from the rule, file,
model, link and occurrence index, as docs/cli.md defines them; the JUnit files are read by
junitparser, the GitLab severities mapped by the table of docs/cli.md."""
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import junitparser

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import shared_data  # noqa: E402  (tests/shared_data.py: the one policy for ../shared)

TOOL, TESTDATA, CORPUS = (os.path.abspath(a) for a in sys.argv[1:4])
del sys.argv[1:4]
SHARED = os.path.dirname(CORPUS)
CORPUS_NAME = os.path.basename(CORPUS)
GITLAB_SEVERITY = {"error": "major", "warning": "minor", "note": "info"}


def check(args, cwd=None):
    """`massprops check ARGS` (its exit code and standard output)."""
    run = subprocess.run([TOOL, "check", *args], cwd=cwd, capture_output=True, text=True,
                         check=False)
    if run.returncode not in (0, 1, 2) or not run.stdout:
        raise AssertionError(f"check {args} exited {run.returncode}: {run.stderr}")
    return run.returncode, run.stdout


def junit_cases(path):
    """Each testcase of a JUnit file read by junitparser: (suite, name, classname, file, line,
    kind of result or None, its message, its text)."""
    cases = []
    for suite in junitparser.JUnitXml.fromfile(path):
        counted = {"tests": 0, "failures": 0, "errors": 0}
        for case in suite:
            results = case.result if isinstance(case.result, list) else [case.result]
            results = [r for r in results if r is not None]
            kind = type(results[0]).__name__ if results else None
            counted["tests"] += 1
            counted["failures"] += kind == "Failure"
            counted["errors"] += kind == "Error"
            attrib = case._elem.attrib  # file and line are not junitparser properties
            line = int(attrib["line"]) if "line" in attrib else 0
            cases.append((suite.name, case.name, case.classname, attrib.get("file"), line, kind,
                          results[0].message if results else None,
                          results[0].text if results else case.system_out))
        # The counts a reader shows are the suite's attributes: they must be the cases'.
        assert (suite.tests, suite.failures, suite.errors) == \
            (counted["tests"], counted["failures"], counted["errors"]), suite.name
    return cases


def expected_failures(document, fail_on="error"):
    """What the failing testcases must be, from `--format json`: one per finding at or above
    the fail level, (suite, "RULE: LINK", "massprops.MODEL", file, line, headline); without a
    link the model names the case, and without a model the file's path names it and its file
    name the class."""
    order = ["note", "warning", "error"]
    out = []
    for f in document["files"]:
        for finding in f["findings"]:
            if order.index(finding["severity"]) < order.index(fail_on):
                continue
            subject = finding["link"] or finding["model"] or f["path"]
            classname = finding["model"] or os.path.basename(f["path"])
            out.append((f["path"], f"{finding['rule']}: {subject}", "massprops." + classname,
                        finding["file"], finding["line"], finding["headline"]))
    return out


def expected_fingerprints(document):
    """The fingerprints docs/cli.md defines: SHA-256 of rule, file, model, link (a read error:
    "read-error", file, "", element) and the occurrence index of those four in the run, each
    followed by a NUL byte; in the report's order (per file: read errors, then findings)."""
    seen = {}
    out = []

    def add(*parts):
        index = seen.get(parts, 0)
        seen[parts] = index + 1
        data = b"".join(p.encode("utf-8", "surrogateescape") + b"\0"
                        for p in (*parts, str(index)))
        out.append(hashlib.sha256(data).hexdigest())

    for f in document["files"]:
        for error in f["errors"]:
            add("read-error", error["file"], "", error["element"])
        for finding in f["findings"]:
            add(finding["rule"], finding["file"], finding["model"], finding["link"])
    return out


class CorpusTest(unittest.TestCase):
    """The whole corpus, checked once per format (from ../shared, so paths read corpus/...)."""

    @classmethod
    def setUpClass(cls):
        why = shared_data.missing(SHARED, CORPUS_NAME)
        if why and shared_data.required(SHARED):
            raise AssertionError(why)
        if why:
            raise unittest.SkipTest(why)
        cls.work = tempfile.mkdtemp(prefix="massprops-ci-formats-")
        _, text = check(["--format", "json", CORPUS_NAME], cwd=SHARED)
        cls.json = json.loads(text)
        _, cls.junit_text = check(["--format", "junit", CORPUS_NAME], cwd=SHARED)
        cls.junit_path = os.path.join(cls.work, "corpus.xml")
        with open(cls.junit_path, "w", encoding="utf-8") as f:
            f.write(cls.junit_text)
        _, text = check(["--format", "gitlab", CORPUS_NAME], cwd=SHARED)
        cls.gitlab = json.loads(text)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_junit_failing_testcases_are_the_json_findings_at_the_fail_level(self):
        failing = [(s, n, cl, f, ln, m) for (s, n, cl, f, ln, k, m, _)
                   in junit_cases(self.junit_path) if k == "Failure"]
        expected = expected_failures(self.json)
        self.assertGreater(len(expected), 20)  # the corpus has real errors to compare
        self.assertEqual(sorted(failing), sorted(expected))

    def test_junit_has_one_suite_per_file_and_one_errored_case_per_read_error(self):
        cases = junit_cases(self.junit_path)
        suites = [s.name for s in junitparser.JUnitXml.fromfile(self.junit_path)]
        self.assertEqual(suites, [f["path"] for f in self.json["files"]])
        errored = sum(1 for c in cases if c[5] == "Error")
        self.assertEqual(errored, sum(len(f["errors"]) for f in self.json["files"]))
        # Every finding is a testcase (failing at the fail level, passing below it), and a file
        # with neither finding nor read error has one passing case.
        clean = sum(1 for f in self.json["files"] if not f["findings"] and not f["errors"])
        findings = sum(len(f["findings"]) for f in self.json["files"])
        self.assertEqual(len(cases), findings + errored + clean)

    def test_junit_findings_below_the_fail_level_pass_with_their_text_as_output(self):
        cases = junit_cases(self.junit_path)
        below = [c for c in cases if c[5] is None and c[1] != "massprops check"]
        warnings = sum(1 for f in self.json["files"] for x in f["findings"]
                       if x["severity"] != "error")
        self.assertEqual(len(below), warnings)
        self.assertTrue(all(c[7] and (": warning: " in c[7] or ": note: " in c[7])
                            for c in below))

    def test_gitlab_items_have_the_five_fields(self):
        findings = [x for f in self.json["files"] for x in f["errors"] + f["findings"]]
        self.assertEqual(len(self.gitlab), len(findings))
        for item in self.gitlab:
            self.assertIsInstance(item["description"], str)
            self.assertTrue(item["description"])
            self.assertLessEqual(len(item["description"]), 110)  # a headline (issue 43)
            self.assertNotIn("\u2026", item["description"])
            self.assertIsInstance(item["check_name"], str)
            self.assertIn(item["severity"], ("info", "minor", "major", "critical", "blocker"))
            self.assertRegex(item["fingerprint"], "^[0-9a-f]{64}$")
            self.assertTrue(item["location"]["path"].startswith(CORPUS_NAME + "/"))
            self.assertIsInstance(item["location"]["lines"]["begin"], int)
            self.assertGreaterEqual(item["location"]["lines"]["begin"], 1)

    def test_gitlab_items_say_the_json_findings(self):
        expected = []
        for f in self.json["files"]:
            # A read error's description is its JSON headline (whole, within 110 characters).
            expected += [("read-error", "critical", e["file"], e["headline"]) for e in f["errors"]]
            expected += [(x["rule"], GITLAB_SEVERITY[x["severity"]], x["file"], x["headline"],
                          max(x["line"], 1)) for x in f["findings"]]
        got = []
        for item, want in zip(self.gitlab, expected):
            if want[0] == "read-error":
                got.append((item["check_name"], item["severity"], item["location"]["path"],
                            item["description"]))
            else:
                got.append((item["check_name"], item["severity"], item["location"]["path"],
                            item["description"], item["location"]["lines"]["begin"]))
        self.assertEqual(got, expected)

    def test_gitlab_fingerprints_are_unique_and_hash_rule_file_model_link(self):
        fingerprints = [item["fingerprint"] for item in self.gitlab]
        self.assertEqual(len(set(fingerprints)), len(fingerprints))
        self.assertEqual(fingerprints, expected_fingerprints(self.json))

    def test_gitlab_fingerprints_stay_when_a_blank_line_moves_every_line(self):
        copy = os.path.join(self.work, "shifted")
        shutil.copytree(CORPUS, os.path.join(copy, CORPUS_NAME))
        models = {f["path"] for f in self.json["files"]}
        for path in models:
            full = os.path.join(copy, path)
            with open(full, "rb") as f:
                data = f.read()
            cut = data.find(b"\n") + 1 if b"\n" in data else len(data)
            with open(full, "wb") as f:
                f.write(data[:cut] + b"\n" + data[cut:])
        _, text = check(["--format", "gitlab", CORPUS_NAME], cwd=copy)
        shifted = json.loads(text)
        self.assertEqual([i["fingerprint"] for i in shifted],
                         [i["fingerprint"] for i in self.gitlab])
        # The lines did move: each below line 1 is one further down.
        moved = [(i["location"]["lines"]["begin"], j["location"]["lines"]["begin"])
                 for i, j in zip(self.gitlab, shifted) if i["location"]["lines"]["begin"] > 1]
        self.assertGreater(len(moved), 20)
        self.assertTrue(all(after == before + 1 for before, after in moved), moved[:5])


class FixtureTest(unittest.TestCase):
    """Welded groups and hostile names, on testdata fixtures."""

    def test_a_welded_groups_finding_names_its_members_in_json_sarif_and_junit(self):
        # testdata/report/welded_pair.urdf: 'extra' is welded to 'arm'; each link's inertia and
        # the composite's are impossible: three inertia-not-physical, one about the group.
        path = os.path.join(TESTDATA, "report", "welded_pair.urdf")
        document = json.loads(check(["--format", "json", path])[1])
        findings = [x for x in document["files"][0]["findings"]
                    if x["rule"] == "inertia-not-physical"]
        self.assertEqual(len(findings), 3)
        self.assertEqual([x.get("group") for x in findings].count(["arm", "extra"]), 1)
        self.assertEqual([x.get("group") for x in findings].count(None), 2)
        group = next(x for x in findings if "group" in x)
        self.assertEqual(group["link"], "arm")
        self.assertEqual(group["values"]["group_links"], 2)

        sarif = json.loads(check(["--format", "sarif", path])[1])
        groups = [r["properties"].get("group") for r in sarif["runs"][0]["results"]
                  if r["ruleId"] == "inertia-not-physical"]
        self.assertEqual(sorted(groups, key=str), sorted([["arm", "extra"], None, None], key=str))

        with tempfile.TemporaryDirectory() as work:
            junit = os.path.join(work, "welded.xml")
            with open(junit, "w", encoding="utf-8") as f:
                f.write(check(["--format", "junit", path])[1])
            texts = [c[7] for c in junit_cases(junit) if c[5] == "Failure"]
        self.assertEqual(len(texts), 3)
        self.assertEqual(sum("welded group of 2 links: arm, extra" in t for t in texts), 1)

    def test_junit_of_names_with_markup_and_control_characters_parses(self):
        # A link named  a<b&"c'd  followed by U+0001 (written &#1; in the file, which tinyxml2
        # decodes): XML 1.0 cannot hold U+0001, so JUnit has U+FFFD there.
        text = ('<?xml version="1.0"?>\n<robot name="r&amp;d">\n'
                '  <link name="a&lt;b&amp;&quot;c\'d&#1;">\n    <inertial>\n'
                '      <mass value="1"/>\n'
                '      <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.003"/>\n'
                '    </inertial>\n  </link>\n</robot>\n')
        with tempfile.TemporaryDirectory() as work:
            model = os.path.join(work, "names.urdf")
            with open(model, "w", encoding="utf-8") as f:
                f.write(text)
            document = json.loads(check(["--format", "json", model])[1])
            junit = os.path.join(work, "names.xml")
            with open(junit, "w", encoding="utf-8") as f:
                f.write(check(["--format", "junit", model])[1])
            cases = junit_cases(junit)
        finding = document["files"][0]["findings"][0]
        self.assertEqual(finding["link"], "a<b&\"c'd\x01")
        failing = [c for c in cases if c[5] == "Failure"]
        self.assertEqual(len(failing), 1)
        self.assertEqual(failing[0][1], finding["rule"] + ": a<b&\"c'd\ufffd")
        self.assertEqual(failing[0][2], "massprops.r&d")
        self.assertEqual(failing[0][6], finding["headline"].replace("\x01", "\ufffd"))

    def test_a_clean_file_is_one_passing_testcase_and_no_gitlab_item(self):
        path = os.path.join(TESTDATA, "report", "welded.urdf")
        document = json.loads(check(["--format", "json", path])[1])
        self.assertEqual(document["files"][0]["findings"], [])  # the fixture is clean
        with tempfile.TemporaryDirectory() as work:
            junit = os.path.join(work, "clean.xml")
            with open(junit, "w", encoding="utf-8") as f:
                f.write(check(["--format", "junit", path])[1])
            cases = junit_cases(junit)
        self.assertEqual([(c[0], c[1], c[5]) for c in cases], [(path, "massprops check", None)])
        self.assertEqual(json.loads(check(["--format", "gitlab", path])[1]), [])

    def test_fail_on_warning_makes_warnings_failing_testcases(self):
        # The bundled example has an error, two warnings and a note.
        path = os.path.join(os.path.dirname(TESTDATA), "examples", "two_link_arm.urdf")
        document = json.loads(check(["--format", "json", "--fail-on", "warning", path])[1])
        severities = sorted(x["severity"] for x in document["files"][0]["findings"])
        self.assertEqual(severities, ["error", "note", "warning", "warning"])
        with tempfile.TemporaryDirectory() as work:
            junit = os.path.join(work, "warnings.xml")
            with open(junit, "w", encoding="utf-8") as f:
                f.write(check(["--format", "junit", "--fail-on", "warning", path])[1])
            failing = [(s, n, cl, f, ln, m) for (s, n, cl, f, ln, k, m, _) in junit_cases(junit)
                       if k == "Failure"]
        self.assertEqual(len(failing), 3)
        self.assertEqual(sorted(failing), sorted(expected_failures(document, "warning")))


if __name__ == "__main__":
    unittest.main(verbosity=2)
