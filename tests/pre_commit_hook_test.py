#!/usr/bin/env python3
"""The pre-commit hook's `files:` pattern (.pre-commit-hooks.yaml) takes the file names that
`massprops check` takes in a folder (python3 standard library only; run by ctest).

pre-commit matches `files:` with Python's re.search on each file's path in the repository
(pre-commit.com, section "Regular expressions"). `massprops check DIR` takes *.urdf and *.sdf with
the extension in any case (src/tool/main.cc, CollectModelFiles); the hook adds *.world, which
check reads when given by name. Run with the tool's path as argument to also compare with the
tool itself on a folder of those names."""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TOOL = sys.argv.pop(1) if len(sys.argv) > 1 else None


def hook_pattern():
    """The `files:` value of .pre-commit-hooks.yaml, read as text (no YAML library needed)."""
    with open(os.path.join(ROOT, ".pre-commit-hooks.yaml"), encoding="utf-8") as f:
        for line in f:
            m = re.match(r"^\s*files:\s*(\S+)\s*$", line)
            if m:
                return re.compile(m.group(1))
    raise AssertionError("no files: line in .pre-commit-hooks.yaml")


# Names from real robot repositories: Reachy's reachy.URDF, SolidWorks' exporter's *.SLDASM.URDF.
TAKEN = ["robot.urdf", "urdf/reachy.URDF", "arm_description/urdf/ARM.SLDASM.URDF",
         "models/box/model.sdf", "models/box/model.SDF", "worlds/empty.world", "worlds/Big.WORLD"]
# Not a model until a tool has run (xacro), a backup, or not a model at all.
NOT_TAKEN = ["robot.urdf.xacro", "robot.URDF.xacro", "robot.urdf.bak", "urdf/README.md",
             "package.xml", "launch/sim.launch.py", "robot_urdf", "model.sdformat", "sdf/x.txt"]


class PreCommitHookPatternTest(unittest.TestCase):
    def test_takes_model_files_whatever_the_case_of_the_extension(self):
        pattern = hook_pattern()
        for name in TAKEN:
            self.assertTrue(pattern.search(name), name)

    def test_leaves_xacro_sources_backups_and_other_files(self):
        pattern = hook_pattern()
        for name in NOT_TAKEN:
            self.assertFalse(pattern.search(name), name)

    @unittest.skipUnless(TOOL, "the massprops tool is not given")
    def test_agrees_with_what_check_takes_in_a_folder(self):
        # Every name but *.world and *.xml, which check takes in a folder by their content (root
        # element <robot> or <sdf>), which a pattern cannot see: the hook leaves *.xml (package.xml,
        # launch files) and takes *.world. For the others the folder search takes exactly the
        # names the pattern takes, each file holding the same URDF.
        pattern = hook_pattern()
        names = [n for n in TAKEN + NOT_TAKEN if not n.lower().endswith((".world", ".xml"))]
        urdf = os.path.join(ROOT, "testdata", "check", "clean.urdf")
        work = tempfile.mkdtemp()
        try:
            for name in names:
                path = os.path.join(work, name)
                os.makedirs(os.path.dirname(path), exist_ok=True)
                shutil.copyfile(urdf, path)
            run = subprocess.run([TOOL, "check", "--format", "json", "--no-geometry", work],
                                 capture_output=True, text=True, check=False)
            self.assertEqual(run.returncode, 0, run.stderr)
            checked = {os.path.relpath(f["path"], work) for f in json.loads(run.stdout)["files"]}
            self.assertEqual(checked, {n for n in names if pattern.search(n)})
        finally:
            shutil.rmtree(work)


if __name__ == "__main__":
    unittest.main()
