"""read / check / report / fix on MJCF (issue 36), with the values worked out by hand from
the file below (each assertion says how)."""
import math

import numpy as np
import pytest

import massprops

# Body "arm": an <inertial> that breaks the triangle inequality (0.1 + 0.1 < 0.5). Body "ball":
# its mass from its sphere geom at density 500 kg/m³, radius 0.1 m.
MJCF = """<mujoco model="pendulum">
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="arm" pos="0 0 1">
      <joint name="hinge" type="hinge" axis="0 1 0"/>
      <inertial mass="1" pos="0 0 0.1" diaginertia="0.1 0.1 0.5"/>
      <body name="ball" pos="0 0 0.5">
        <joint name="slide" type="slide"/>
        <geom type="sphere" size="0.1" density="500"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""

# Sphere: m = ρ·4/3·π·r³, I = 2/5·m·r² (a solid sphere about its centre).
BALL_MASS = 500 * 4 / 3 * math.pi * 0.1**3
BALL_MOMENT = 0.4 * BALL_MASS * 0.1**2


def test_read_mjcf_bodies_and_geom_derived_mass(tmp_path):
    path = tmp_path / "pendulum.xml"
    path.write_text(MJCF)
    model = massprops.read(path)
    assert model.format == "mjcf" and model.name == "pendulum"
    assert [link.name for link in model.links] == ["world", "arm", "ball"]
    arm = model.link("arm")
    assert arm.mass == 1.0  # as written
    np.testing.assert_array_equal(arm.com, [0.0, 0.0, 0.1])
    np.testing.assert_array_equal(arm.inertia, np.diag([0.1, 0.1, 0.5]))
    ball = model.link("ball")
    assert ball.mass == pytest.approx(BALL_MASS, rel=1e-12)
    np.testing.assert_allclose(ball.inertia, np.eye(3) * BALL_MOMENT, rtol=1e-12, atol=0)
    types = {joint.child: joint.type for joint in model.joints}
    assert types == {"arm": "hinge", "ball": "slide"}  # MuJoCo's own joint types


def test_check_mjcf_finds_the_triangle_inequality_and_not_the_floor(tmp_path):
    path = tmp_path / "pendulum.xml"
    path.write_text(MJCF)
    findings = massprops.check(path)
    by_link = {(f.link, f.rule) for f in findings}
    assert ("arm", "inertia-not-physical") in by_link
    assert ("arm", "mujoco-rejects-inertia-triangle") in by_link
    # The <worldbody>'s floor never moves: no forgotten mass.
    assert not any(link == "world" for link, _ in by_link)
    assert not any(link == "ball" for link, _ in by_link)


def test_report_mjcf_totals(tmp_path):
    path = tmp_path / "pendulum.xml"
    path.write_text(MJCF)
    total = massprops.report(path)["models"][0]["total"]
    # 1 kg at z = 1.1 (body at 1, com 0.1 above) and the ball at z = 1.5: hand sums.
    assert total["mass"] == pytest.approx(1 + BALL_MASS, rel=1e-12)
    assert total["com"][2] == pytest.approx((1.1 + 1.5 * BALL_MASS) / (1 + BALL_MASS), rel=1e-12)


def test_fix_mjcf_patches_the_inertial_attributes(tmp_path):
    path = tmp_path / "pendulum.xml"
    path.write_text(MJCF)
    result = massprops.fix(path)
    assert result.changed and result.reads_back
    assert {change.link for change in result.changes} == {"arm"}
    # The nearest moments with A + B >= C: (0.1, 0.1, 0.5) + 0.1·(1, 1, -1) = (0.2, 0.2, 0.4).
    line = [l for l in result.text.splitlines() if "<inertial" in l][0]
    moments = [float(x) for x in line.split('diaginertia="')[1].split('"')[0].split()]
    np.testing.assert_allclose(moments, [0.2, 0.2, 0.4], rtol=0, atol=1e-6)
    assert 'mass="1" pos="0 0 0.1"' in line  # untouched
    # Only that line changes.
    before, after = MJCF.splitlines(), result.text.splitlines()
    assert [i for i in range(len(before)) if before[i] != after[i]] == [5]
    fixed = tmp_path / "fixed.xml"
    fixed.write_text(result.text)
    assert not [f for f in massprops.check(fixed) if f.severity == "error"]

