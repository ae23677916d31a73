"""massprops where robot teams test (docs/ci.md): the ament_python test file of the docs
(examples/ament_python/test/test_massprops.py) run by pytest on a clean and a bad package;
Finding.group for a welded group's finding; massprops.diff equal to `massprops diff --format json`.
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys

import massprops

HERE = pathlib.Path(__file__).resolve().parent
FIXTURE_URDF = HERE.parent.parent / "tests" / "colcon" / "fixture_description" / "urdf"


def run_package_test(examples, tmp_path, urdf_files):
    """A package folder holding urdf/ (the given files) and the documented test/test_massprops.py,
    run by pytest in a new Python: (exit code, output)."""
    (tmp_path / "urdf").mkdir()
    (tmp_path / "test").mkdir()
    for path in urdf_files:
        shutil.copy(path, tmp_path / "urdf" / path.name)
    shutil.copy(examples / "ament_python" / "test" / "test_massprops.py", tmp_path / "test")
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
         str(tmp_path / "test" / "test_massprops.py")],
        capture_output=True, text=True, env=dict(os.environ), cwd=tmp_path, check=False)
    return run.returncode, run.stdout + run.stderr


def test_ament_python_test_file_passes_on_a_clean_package(examples, tmp_path):
    code, output = run_package_test(examples, tmp_path, [FIXTURE_URDF / "gripper.urdf"])
    assert code == 0, output
    assert "1 passed" in output


def test_ament_python_test_file_fails_with_the_headlines_of_a_bad_package(examples, tmp_path):
    bad = FIXTURE_URDF / "arm.urdf"
    code, output = run_package_test(examples, tmp_path, [bad, FIXTURE_URDF / "gripper.urdf"])
    assert code == 1, output
    assert "1 failed" in output
    # The errors massprops.check finds in arm.urdf (forearm: ixx + iyy < izz) are in the failure.
    errors = [f for f in massprops.check(bad) if f.severity == "error"]
    assert [f.link for f in errors] == ["forearm"]
    for finding in errors:
        assert finding.headline in output


def test_finding_group_names_a_welded_groups_members(testdata):
    # welded_pair.urdf: 'extra' is welded to 'arm'; both links and their composite have the
    # impossible moments (0, 0, 1) and (0, 0, 2): one finding per link, one for the group.
    findings = [f for f in massprops.check(testdata / "report" / "welded_pair.urdf")
                if f.rule == "inertia-not-physical"]
    assert sorted(f.group for f in findings) == [[], [], ["arm", "extra"]]
    about_group = next(f for f in findings if f.group)
    assert about_group.link == "arm"
    assert about_group.values["group_links"] == 2
    assert about_group.to_dict()["group"] == ["arm", "extra"]
    assert all("group" not in f.to_dict() for f in findings if not f.group)


def diff_command(tool, a, b, *options):
    run = subprocess.run([tool, "diff", "--format", "json", *options, str(a), str(b)],
                         capture_output=True, text=True, check=False)
    assert run.returncode in (0, 1), run.stderr
    return json.loads(run.stdout)


def test_diff_equals_the_command_on_a_changed_mass(tool, testdata, tmp_path):
    a = testdata / "report" / "welded.urdf"
    b = tmp_path / "welded.urdf"
    text = a.read_text()
    assert text.count('<mass value="6"/>') == 1
    b.write_text(text.replace('<mass value="6"/>', '<mass value="6.6"/>'))
    result = massprops.diff(a, b)
    assert result == diff_command(tool, a, b)
    # model_diff.h: the relative mass difference |a - b| / max(|a|, |b|) = 0.6 / 6.6.
    base = next(e for e in result["entries"] if e["kind"] == "link" and e["name"] == "base")
    assert abs(base["mass_difference"] - 0.6 / 6.6) < 1e-12
    assert base["differs"] and result["differs"]


def test_diff_equals_the_command_on_two_robots_with_a_tolerance(tool, testdata):
    a = testdata / "report" / "welded.urdf"
    b = testdata / "report" / "welded_pair.urdf"
    assert massprops.diff(a, b, tolerance=0.5) == diff_command(tool, a, b, "--tolerance", "0.5")
    same = massprops.diff(a, a)
    assert not same["differs"] and same == diff_command(tool, a, a)
