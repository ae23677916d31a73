"""read / check / report / fix on the example and the fixtures, with the expected values worked
out by hand from the files (each test says how), and bad input."""
import os
import pathlib
import re
import shutil
import stat

import numpy as np
import pytest

import massprops

BAD_XML = """<?xml version="1.0"?>
<robot name="broken">
  <link name="a">
    <inertial>
      <mass value="1"/>
  </link>
</robot>
"""


def test_read_the_example_arm(examples):
    model = massprops.read(examples / "two_link_arm.urdf")
    assert model.name == "two_link_arm" and model.format == "urdf"
    assert model.root_link == "base_link"
    names = [link.name for link in model.links]
    assert names[:3] == ["base_link", "upper_arm", "forearm"]
    upper = model.link("upper_arm")
    # As written in the file: mass 1.5, origin xyz 0 0 0.15, ixx = iyy = 11562.5, izz = 625.
    assert upper.mass == 1.5
    np.testing.assert_array_equal(upper.com, [0.0, 0.0, 0.15])
    np.testing.assert_array_equal(upper.inertia, np.diag([11562.5, 11562.5, 625.0]))
    assert upper.inertial.ixx == 11562.5 and upper.inertial.location.line > 0
    assert upper.line > 0 and upper.location.file.endswith("two_link_arm.urdf")
    assert model.link("camera_link").inertial is None and model.link("camera_link").mass is None
    joint = model.joints[0]
    assert (joint.name, joint.type, joint.parent, joint.child) == \
        ("shoulder", "revolute", "base_link", "upper_arm")
    np.testing.assert_array_equal(joint.X_PC.p_AB, [0.0, 0.0, 0.05])
    with pytest.raises(KeyError):
        model.link("no_such_link")
    assert model.find_link("no_such_link") == -1


def test_read_text_and_bytes_and_pathlike(examples):
    path = examples / "two_link_arm.urdf"
    text = path.read_text()
    for source in (text, text.encode(), str(path), path):
        assert massprops.read(source).name == "two_link_arm"
    assert massprops.read(text).file == "<string>"


def test_read_errors_name_the_file_and_line(tmp_path):
    broken = tmp_path / "broken.urdf"
    broken.write_text(BAD_XML)
    with pytest.raises(massprops.ReadError) as caught:
        massprops.read(broken)
    error = caught.value
    assert error.file == str(broken)
    assert error.line > 0
    assert str(broken) in str(error) and error.errors
    with pytest.raises(massprops.ReadError) as caught:
        massprops.read(tmp_path / "missing.urdf")
    assert caught.value.file == str(tmp_path / "missing.urdf")
    with pytest.raises(massprops.ReadError):
        massprops.read("<notarobot/>")
    with pytest.raises(massprops.ReadError):
        massprops.check(broken)
    with pytest.raises(massprops.ReadError):
        massprops.read(tmp_path)  # a folder
    with pytest.raises(ValueError):
        massprops.read("")
    with pytest.raises(TypeError):
        massprops.read(42)
    with pytest.raises(TypeError):
        massprops.read(None)


def test_check_the_example_finds_its_three_documented_defects(examples):
    findings = massprops.check(examples / "two_link_arm.urdf")
    by_link = {(f.link, f.rule): f for f in findings}
    # The file's comment lists them: upper_arm's inertia in kg·mm², forearm's izz breaking the
    # triangle inequality, camera_link without <inertial>.
    assert ("forearm", "inertia-not-physical") in by_link
    assert ("camera_link", "inertial-missing") in by_link
    assert any(link == "upper_arm" for link, _ in by_link)
    bad = by_link[("forearm", "inertia-not-physical")]
    assert bad.severity == "error" and bad.line > 0 and bad.file.endswith("two_link_arm.urdf")
    assert "0.0046" in bad.message
    assert bad.values["principal_max"] == pytest.approx(0.0046, rel=1e-9)
    assert str(bad).startswith(f"{bad.file}:{bad.line}")
    assert "inertia-not-physical" in repr(bad)


def test_findings_have_a_headline_evidence_and_help(examples):
    # Issue 32: a finding's parts. The example's forearm has principal moments 0.000213333,
    # 0.00427333, 0.0046 (its comment): 0.000213 + 0.00427 < 0.0046, the triangle inequality fails.
    findings = massprops.check(examples / "two_link_arm.urdf")
    bad = next(f for f in findings if (f.link, f.rule) == ("forearm", "inertia-not-physical"))
    assert bad.headline == \
        "link 'forearm': impossible inertia (moments 0.000213 + 0.00427 < 0.0046)"
    assert bad.evidence["moment_3_kg_m2"] == pytest.approx(0.0046, rel=1e-9)
    assert "massprops fix" in bad.help
    assert "0.00427333" in bad.message  # the full reasoning is kept
    assert bad.to_dict()["headline"] == bad.headline
    assert bad.to_dict()["evidence"] == bad.evidence
    assert str(bad).endswith(bad.headline + " [inertia-not-physical]")
    assert all(f.headline and f.help and isinstance(f.evidence, dict) for f in findings)


def test_check_options_map_to_the_tool_options(examples):
    path = examples / "two_link_arm.urdf"
    rules = {f.rule for f in massprops.check(path)}
    assert "inertial-missing" in rules
    assert "inertial-missing" not in {f.rule for f in massprops.check(path, disable=["inertial-missing"])}
    notes = massprops.check(path, severity={"inertial-missing": "note"})
    assert [f.severity for f in notes if f.rule == "inertial-missing"] == ["note"]
    options = massprops.CheckOptions(disable=["inertia-not-physical"])
    assert "inertia-not-physical" not in {f.rule for f in massprops.check(path, options)}
    with pytest.raises(ValueError, match="unknown rule"):
        massprops.check(path, disable=["no-such-rule"])
    with pytest.raises(ValueError, match="level"):
        massprops.check(path, severity={"inertial-missing": "fatal"})
    with pytest.raises(ValueError, match="tolerance"):
        massprops.check(path, tolerance=2.0)
    with pytest.raises(TypeError):
        massprops.check(path, disable="inertial-missing")  # a string, not a list
    with pytest.raises(TypeError):
        massprops.check(path, no_such_option=1)
    with pytest.raises(TypeError):
        massprops.check(path, options={"tolerance": 1e-6})


def test_welded_groups_and_the_composite_by_hand(testdata):
    model = massprops.read(testdata / "check" / "inertia-not-physical.urdf")
    # base (1 kg at the origin) and arm (2 kg, com 0.2 above its frame, which is 0.05 above
    # base's): the composite com is (1·0 + 2·0.25)/3 = 1/6 along z, the mass 3.
    total = model.composite()
    assert total.mass == 3.0 and total.frame == "base"
    np.testing.assert_allclose(total.com, [0.0, 0.0, 0.5 / 3], rtol=1e-15)
    # Izz about the com: 0.00166667 + 0.5 (both on the z axis: no shift term).
    assert total.inertia_about_com[2, 2] == pytest.approx(0.00166667 + 0.5, rel=1e-15)
    # Ixx: 0.00166667 + 1·(1/6)² + 0.1 + 2·(0.25 − 1/6)² (parallel-axis theorem).
    expected_ixx = 0.00166667 + (1 / 6) ** 2 + 0.1 + 2 * (0.25 - 1 / 6) ** 2
    assert total.inertia_about_com[0, 0] == pytest.approx(expected_ixx, rel=1e-14)
    groups = model.welded_groups()
    assert [g.links for g in groups] == [["base"], ["arm"]]
    assert groups[1].parent_joint == "shoulder" and groups[1].is_moving
    assert groups[1].composite.mass == 2.0
    arm = model.link("arm")
    assert not arm.rotational_inertia().could_be_physically_valid()
    assert arm.spatial_inertia().get_mass() == 2.0


def test_report_is_the_json_report_as_python_data(testdata):
    data = massprops.report(testdata / "check" / "inertia-not-physical.urdf")
    assert set(data) >= {"models", "errors"}
    model = data["models"][0]
    total = model["total"]
    assert total["mass"] == 3.0  # 1 + 2 kg (hand sum)
    assert total["com"][2] == pytest.approx(0.5 / 3, rel=1e-15)
    assert [link["name"] for link in model["links"]] == ["base", "arm"]
    with pytest.raises(ValueError, match="no_such_joint"):
        massprops.report(testdata / "check" / "inertia-not-physical.urdf",
                         joints={"no_such_joint": 1.0})
    moved = massprops.report(testdata / "check" / "inertia-not-physical.urdf",
                             joints={"shoulder": np.pi / 2})["models"][0]["total"]
    # Turning the arm by 90° about x swings its com (0.2 from the joint) from z to -y or +y:
    # the composite com's y is ±2·0.2/3.
    assert abs(moved["com"][1]) == pytest.approx(0.4 / 3, rel=1e-12)


def test_fix_dry_run_writes_nothing_and_repairs_only_errors_by_default(tmp_path, examples):
    path = tmp_path / "arm.urdf"
    shutil.copy(examples / "two_link_arm.urdf", path)
    before = path.read_bytes()
    mtime = path.stat().st_mtime_ns
    result = massprops.fix(path)
    assert path.read_bytes() == before and path.stat().st_mtime_ns == mtime
    assert result.written is None and result.changed and result.reads_back
    changed_links = {change.link for change in result.changes}
    # Errors only: forearm (inertia-not-physical); upper_arm's unit slip (units-suspect) and
    # camera_link's missing inertial (inertial-missing) are warnings, guesses: not applied.
    assert "forearm" in changed_links
    assert "upper_arm" not in changed_links and "camera_link" not in changed_links
    # The nearest valid inertia to the forearm's (ixx 0.0046 > iyy + izz = 0.00448667, excess
    # 0.000113333): the Euclidean projection onto the half-space ixx <= iyy + izz moves along its
    # normal (1, -1, -1), a third of the excess from ixx and a third to each of the others
    # (hand-derived): 0.00456222, 0.00431111, 0.000251111.
    forearm = result.text[result.text.index('<link name="forearm">'):]
    written = re.search(r'ixx="([^"]+)".*iyy="([^"]+)".*izz="([^"]+)"', forearm)
    excess = 0.0046 - (0.00427333 + 0.000213333)
    assert [float(v) for v in written.groups()] == pytest.approx(
        [0.0046 - excess / 3, 0.00427333 + excess / 3, 0.000213333 + excess / 3], rel=1e-5)
    forearm = next(c for c in result.changes if c.link == "forearm")
    assert forearm.rule == "inertia-not-physical" and forearm.method == "project"
    assert forearm.changes and all(ch.element == "inertia" for ch in forearm.changes)
    assert "forearm" not in {f.link for f in massprops.check(result.text)
                             if f.rule == "inertia-not-physical"}
    assert "-" in result.diff() and "+" in result.diff()
    # Naming the heuristic rule applies it too.
    findings = massprops.check(path)
    upper_rules = {f.rule for f in findings if f.link == "upper_arm"}
    with_units = massprops.fix(path, apply=sorted(upper_rules))
    assert "upper_arm" in {c.link for c in with_units.changes}


def test_fix_writes_only_when_asked_atomically_keeping_the_mode(tmp_path, examples):
    path = tmp_path / "arm.urdf"
    shutil.copy(examples / "two_link_arm.urdf", path)
    os.chmod(path, 0o640)
    original = path.read_text()
    out = tmp_path / "fixed.urdf"
    result = massprops.fix(path, dry_run=False, output=out)
    assert result.written == os.fspath(out) and out.read_text() == result.text
    assert path.read_text() == original
    result = massprops.fix(path, dry_run=False, backup=".orig")
    assert result.written == os.path.realpath(path)
    assert path.read_text() == result.text != original
    assert (tmp_path / "arm.urdf.orig").read_text() == original
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["arm.urdf", "arm.urdf.orig",
                                                          "fixed.urdf"]  # no temporary left
    # Fixed again: nothing to change, the file is not rewritten.
    mtime = path.stat().st_mtime_ns
    again = massprops.fix(path, dry_run=False)
    assert not again.changed and again.written is None and path.stat().st_mtime_ns == mtime


def test_fix_bad_arguments(tmp_path, examples):
    path = examples / "two_link_arm.urdf"
    with pytest.raises(ValueError, match="unknown rule"):
        massprops.fix(path, apply=["no-such-rule"])
    with pytest.raises(ValueError, match="project"):
        massprops.fix(path, repair="average")
    with pytest.raises(ValueError, match="density"):
        massprops.fix(path, density=-1.0)
    with pytest.raises(ValueError, match="no link 'nope'"):
        massprops.fix(path, from_geometry=["nope"])
    with pytest.raises(TypeError):
        massprops.fix(path, from_geometry=3)
    with pytest.raises(ValueError, match="output"):
        massprops.fix(path, output=tmp_path / "x.urdf")  # dry run: nothing may be written
    with pytest.raises(ValueError, match="no file"):
        massprops.fix(path.read_text(), dry_run=False)
    broken = tmp_path / "broken.urdf"
    broken.write_text(BAD_XML)
    with pytest.raises(massprops.ReadError):
        massprops.fix(broken)


def test_hostile_numbers_do_not_crash(tmp_path):
    # NaN and infinity: urdfdom (the URDF reader) cannot read them, so the link's inertial is
    # unreadable: an error finding on the link quoting the first such text, not a read error.
    text = """<robot name="r"><link name="a"><inertial><mass value="nan"/>
<inertia ixx="1" iyy="1" izz="inf" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>"""
    unreadable = [f for f in massprops.check(text) if f.rule == "inertial-unreadable"]
    assert len(unreadable) == 1 and unreadable[0].link == "a" and unreadable[0].line == 1
    assert 'value="nan"' in unreadable[0].message and unreadable[0].severity == "error"
    # A subnormal (4.9e-324: nonzero, below the smallest normal double 2.2e-308) is one that
    # urdfdom reads with lost precision and SDF readers refuse: inertial-unreadable, like nan.
    text = """<robot name="r"><link name="a"><inertial><mass value="1"/>
<inertia ixx="1" iyy="1" izz="4.9e-324" ixy="0" ixz="0" iyz="0"/></inertial></link></robot>"""
    assert [f.rule for f in massprops.check(text)] == ["inertial-unreadable"]
    # Finite extremes are findings, and every function copes with them.
    text = """<robot name="r"><link name="a"><inertial><mass value="-1e308"/>
<inertia ixx="1e308" iyy="-1e308" izz="2.3e-308" ixy="1e308" ixz="0" iyz="0"/></inertial>
</link></robot>"""
    findings = massprops.check(text)
    assert {"mass-not-positive", "inertia-not-physical"} <= {f.rule for f in findings}
    model = massprops.read(text)
    assert not model.links[0].rotational_inertia().could_be_physically_valid()
    assert not model.links[0].spatial_inertia().is_physically_valid()
    massprops.fix(text)
    massprops.report(text)
    model.composite()
    model.welded_groups()


def test_rules_list_matches_the_tool(tool):
    import json
    import subprocess
    out = subprocess.run([tool, "check", "--list-rules", "--format", "json"],
                         capture_output=True, text=True, check=True).stdout
    assert massprops.rules() == json.loads(out)


def test_check_finds_package_meshes_in_the_descriptions_repository(tmp_path, testdata):
    # A repository (.git) whose package "arm_meshes" (its package.xml, folder "parts") holds the
    # only geometry of link "box": the 0.1 x 0.2 x 0.3 m box of testdata/mesh/box_ascii.stl.
    # Its inertia diag(1, 1, 1) kg m^2 for 1 kg gives tr(I)/2 = 1.5 kg m^2 about the box center,
    # far above m r^2 = 1 x (2 x 0.187)^2 = 0.14 kg m^2 (r = twice the half-diagonal
    # sqrt(0.05^2 + 0.1^2 + 0.15^2) = 0.187 m): inertia-exceeds-geometry, once the box is known.
    repo = tmp_path / "repo"
    (repo / ".git").mkdir(parents=True)
    (repo / "parts" / "meshes").mkdir(parents=True)
    (repo / "parts" / "package.xml").write_text(
        "<package format='3'><name>arm_meshes</name></package>")
    shutil.copy(os.path.join(testdata, "mesh", "box_ascii.stl"), repo / "parts" / "meshes")
    (repo / "desc").mkdir()
    urdf = repo / "desc" / "arm.urdf"
    urdf.write_text(
        "<robot name='arm'><link name='box'><inertial><origin xyz='0.05 0.1 0.15'/>"
        "<mass value='1'/><inertia ixx='1' iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/>"
        "</inertial><visual><geometry>"
        "<mesh filename='package://arm_meshes/meshes/box_ascii.stl'/>"
        "</geometry></visual></link></robot>")
    rules = {f.rule for f in massprops.check(urdf, config=None)}
    assert "inertia-exceeds-geometry" in rules
    # Without the package.xml no package is named arm_meshes: the mesh's size is unknown.
    (repo / "parts" / "package.xml").unlink()
    rules = {f.rule for f in massprops.check(urdf, config=None)}
    assert "inertia-exceeds-geometry" not in rules
