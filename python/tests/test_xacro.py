"""check(..., source_root=...) on an expanded xacro package of ../shared/xacro/ (docs/xacro.md):
the same source places as `massprops check --expanded ... --source-root ... --format json`."""
import json
import os
import subprocess

import pytest

import massprops
from conftest import XACRO, need_shared

PMB2 = XACRO / "pmb2"


@pytest.fixture
def pmb2():
    need_shared("xacro/pmb2/expanded.urdf")
    return PMB2


def test_check_with_source_root_points_findings_at_the_xacro_line(pmb2):
    findings = massprops.check(str(pmb2 / "expanded.urdf"), source_root=str(pmb2), config=None)
    physical = [f for f in findings if f.rule == "inertia-not-physical"]
    # pmb2's two antennas come from one macro: urdf/objects/antenna.urdf.xacro, the inertia
    # literals at lines 26-28 (ixx at line 26), expanded at lines 445 and 474.
    assert [f.link for f in physical] == ["base_antenna_left_link", "base_antenna_right_link"]
    for finding, generated in zip(physical, [445, 474]):
        source = finding.source
        assert os.path.samefile(source["file"], pmb2 / "src/urdf/objects/antenna.urdf.xacro")
        assert (source["line"], source["how"], source["text"]) == (26, "literal", "0.00000002371")
        assert source["generated"]["line"] == generated == finding.line
        assert finding.to_dict()["source"] == source


def test_without_source_root_there_is_no_source(pmb2):
    findings = massprops.check(str(pmb2 / "expanded.urdf"), config=None)
    assert findings and all(f.source is None for f in findings)


def test_python_and_tool_give_the_same_places(pmb2, tool):
    out = subprocess.run([tool, "check", "--format", "json", "--expanded", str(pmb2 / "expanded.urdf"),
                          "--source-root", str(pmb2)], capture_output=True, text=True).stdout
    from_tool = [(f["link"], f["source"]["file"], f["source"]["line"], f["source"]["how"])
                 for f in json.loads(out)["files"][0]["findings"] if "source" in f]
    from_python = [(f.link, f.source["file"], f.source["line"], f.source["how"])
                   for f in massprops.check(str(pmb2 / "expanded.urdf"), source_root=str(pmb2))
                   if f.source]
    assert from_python == from_tool and len(from_tool) == 2
