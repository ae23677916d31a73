"""massprops.fix with the mass repairs (total_mass, mass, density={link: ...}, material), as
`massprops fix --total-mass/--mass/--density LINK=/--material` (docs/fix.md), on
testdata/mass/arm.urdf: masses 1 + 2 + 3 = 6 kg, upper's visual mesh the 0.1 x 0.2 x 0.3 m box."""
import pytest

import massprops


def after(result, link):
    return next(c for c in result.changes if c.link == link)


def test_total_mass_scales_every_link_by_one_factor(testdata):
    result = massprops.fix(testdata / "mass" / "arm.urdf", total_mass=12.0)
    # 6 kg to 12 kg: k = 2 for every link, products too (hand-derived).
    assert {c.link for c in result.changes} == {"base", "upper", "tool"}
    base = after(result, "base")
    assert base.rule == "--total-mass"
    assert 'ixx="0.02" ixy="0.002" ixz="-0.004" iyy="0.04" iyz="0.006" izz="0.05"' in result.text


def test_mass_with_total_mass_gives_the_others_one_common_factor(testdata):
    # tool 3 -> 6 kg; base and upper share 10.5 - 6 = 4.5 kg of their 3 kg: k = 1.5.
    result = massprops.fix(testdata / "mass" / "arm.urdf", total_mass=10.5, mass={"tool": 6.0})
    total = massprops.read(result.text).composite()
    assert total.mass == pytest.approx(10.5, rel=1e-12)
    assert '<mass value="1.5"/>' in result.text and '<mass value="6"/>' in result.text


def test_material_and_density_give_the_box_mesh_mass(testdata):
    path = testdata / "mass" / "arm.urdf"
    by_material = massprops.fix(path, material={"upper": "aluminium-6061"})
    by_density = massprops.fix(path, density={"upper": 2700.0})
    assert by_material.text == by_density.text
    upper = massprops.read(by_material.text).links
    # 2700 kg/m³ x 0.006 m³ = 16.2 kg (the STL's 32-bit floats change the 9th digit).
    mass = next(link for link in upper if link.name == "upper").inertial.mass
    assert mass == pytest.approx(16.2, rel=1e-6)
    with pytest.raises(ValueError, match="not one of aluminium-6061"):
        massprops.fix(path, material={"upper": "wood"})
    with pytest.raises(ValueError, match="no closed mesh"):
        massprops.fix(path, density={"base": 1000.0})
    with pytest.raises(ValueError, match="total_mass must be a positive"):
        massprops.fix(path, total_mass=-1.0)
