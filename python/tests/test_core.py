"""The core classes against values worked out by hand (the formula or derivation is named in each
test), and their Python behaviour (numpy in/out, ==, repr, errors)."""
import math
import pickle

import numpy as np
import pytest

import massprops
from massprops import RotationalInertia, SpatialInertia, UnitInertia

EPS = np.finfo(float).eps


def test_rotational_inertia_moments_and_products_are_numpy_arrays():
    I = RotationalInertia(2.0, 3.0, 4.0, 0.1, 0.2, 0.3)
    assert isinstance(I.get_moments(), np.ndarray)
    np.testing.assert_array_equal(I.get_moments(), [2.0, 3.0, 4.0])
    np.testing.assert_array_equal(I.get_products(), [0.1, 0.2, 0.3])
    # The full matrix puts each product at both of its places (negated convention, as URDF).
    np.testing.assert_array_equal(
        I.copy_to_full_matrix3(), [[2.0, 0.1, 0.2], [0.1, 3.0, 0.3], [0.2, 0.3, 4.0]])
    np.testing.assert_array_equal(np.asarray(I), I.copy_to_full_matrix3())
    assert I[0, 1] == 0.1 and I[2, 1] == 0.3
    assert I.trace() == 9.0
    assert I.calc_maximum_possible_moment_of_inertia() == 4.5


def test_diagonal_inertia_principal_moments_are_its_sorted_diagonal_exactly():
    # Hand-derived: a diagonal matrix's eigenvalues are its diagonal entries; the accurate solver
    # is exact on diagonal input (principal_axes.h).
    I = RotationalInertia(3.0, 1.0, 2.0)
    np.testing.assert_array_equal(I.calc_principal_moments_of_inertia(), [1.0, 2.0, 3.0])
    moments, axes = I.calc_principal_moments_and_axes_of_inertia()
    np.testing.assert_array_equal(moments, [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(np.abs(axes), [[0, 0, 1], [1, 0, 0], [0, 1, 0]])


def test_principal_moments_of_a_matrix_with_one_product():
    # Hand-derived: [[3, 1, 0], [1, 3, 0], [0, 0, 5]] has eigenvalues 3 ± 1 and 5 (the 2x2 block
    # [[a, b], [b, a]] has a ± b).
    I = RotationalInertia(3.0, 3.0, 5.0, 1.0, 0.0, 0.0)
    for solver in ("accurate", "fast", massprops.PrincipalSolver.FAST):
        np.testing.assert_allclose(I.calc_principal_moments_of_inertia(solver), [2.0, 4.0, 5.0],
                                   rtol=0, atol=8 * EPS * I.trace())


def test_solid_box_unit_inertia_matches_the_textbook_formula():
    # Solid box with sides a, b, c: ((b²+c²)/12, (a²+c²)/12, (a²+b²)/12) per unit mass
    # (e.g. Meriam & Kraige, Engineering Mechanics: Dynamics, Table D/4).
    G = UnitInertia.solid_box(1.0, 2.0, 3.0)
    np.testing.assert_allclose(G.get_moments(), [13 / 12, 10 / 12, 5 / 12], rtol=1e-15)
    assert type(G) is UnitInertia
    # 2 kg of it: a RotationalInertia with twice the numbers.
    I = 2.0 * G
    assert type(I) is RotationalInertia
    np.testing.assert_allclose(I.get_moments(), [26 / 12, 20 / 12, 10 / 12], rtol=1e-15)


def test_shape_factories_against_hand_formulas():
    z = [0.0, 0.0, 1.0]
    # Solid sphere 2/5 r², hollow sphere 2/3 r², cube L²/6 (standard tables).
    assert UnitInertia.solid_sphere(0.5).get_moments()[0] == pytest.approx(0.1, rel=1e-15)
    assert UnitInertia.hollow_sphere(0.3).get_moments()[0] == pytest.approx(0.06, rel=1e-15)
    assert UnitInertia.solid_cube(0.6).get_moments()[0] == pytest.approx(0.06, rel=1e-15)
    # Cylinder r = 0.1, L = 0.4 along z: r²/2 = 0.005 about z, (3r² + L²)/12 = 0.01583.. across.
    np.testing.assert_allclose(UnitInertia.solid_cylinder(0.1, 0.4, z).get_moments(),
                               [0.19 / 12, 0.19 / 12, 0.005], rtol=1e-14)
    # Thin rod L = 1 along z: 1/12 across, 0 along; it lies on the validity boundary.
    rod = UnitInertia.thin_rod(1.0, z)
    np.testing.assert_allclose(rod.get_moments(), [1 / 12, 1 / 12, 0.0], rtol=1e-15, atol=0)
    assert rod.could_be_physically_valid()
    # Thin disk r = 1, normal z: r²/4 in plane, r²/2 about the normal (triangle equality).
    np.testing.assert_allclose(UnitInertia.thin_disk(1.0, z).get_moments(), [0.25, 0.25, 0.5])


def test_parallel_axis_theorem_by_hand():
    # A 2 kg particle at (1, 2, 0): I = m(|p|²·1 − p pᵀ) = 2·[[4, -2, 0], [-2, 1, 0], [0, 0, 5]].
    I = RotationalInertia(2.0, [1.0, 2.0, 0.0])
    np.testing.assert_array_equal(I.copy_to_full_matrix3(),
                                  [[8.0, -4.0, 0.0], [-4.0, 2.0, 0.0], [0.0, 0.0, 10.0]])
    # A 1 kg unit cube (L²/6 = 1/6) shifted 1 m along x: + m·d² about y and z (Steiner).
    cube = RotationalInertia.triaxially_symmetric(1 / 6)
    shifted = cube.shift_from_center_of_mass(1.0, [1.0, 0.0, 0.0])
    np.testing.assert_allclose(shifted.get_moments(), [1 / 6, 7 / 6, 7 / 6], rtol=1e-15)
    back = shifted.shift_to_center_of_mass(1.0, [1.0, 0.0, 0.0])
    assert back.is_nearly_equal_to(cube, 4 * EPS)
    # To then away in one step equals the two steps.
    one_step = shifted.shift_to_then_away_from_center_of_mass(1.0, [-1.0, 0, 0], [0, 2.0, 0])
    two_steps = back.shift_from_center_of_mass(1.0, [0, 2.0, 0])
    assert one_step.is_nearly_equal_to(two_steps, 8 * EPS)


def test_re_express_by_a_quarter_turn_swaps_moments():
    # Hand-derived: R = rotation of 90° about z maps x to y: diag(2, 3, 4) → diag(3, 2, 4), and
    # the product Ixz = 0.5 moves to Iyz = 0.5 (R·I·Rᵀ entry (1, 2) = R10·I02·R22).
    R = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    I = RotationalInertia(2.0, 3.0, 4.0, 0.0, 0.5, 0.0)
    J = I.re_express(R)
    np.testing.assert_allclose(J.copy_to_full_matrix3(),
                               [[3.0, 0.0, 0.0], [0.0, 2.0, 0.5], [0.0, 0.5, 4.0]], atol=1e-15)


def test_validity_is_the_triangle_inequality_with_a_relative_tolerance():
    # 0.1 + 0.2 < 0.5: no body has it (the fixture testdata/check/inertia-not-physical.urdf).
    bad = RotationalInertia.make_from_moments_and_products_of_inertia(
        0.1, 0.2, 0.5, 0, 0, 0, skip_validity_check=True)
    assert not bad.could_be_physically_valid()
    assert "triangle inequality" in bad.criticize_not_physically_valid()
    # On the boundary (thin disk, 1 + 1 = 2) it is valid; beyond by 1e-6·trace it is not.
    assert RotationalInertia(1.0, 1.0, 2.0).could_be_physically_valid()
    over = RotationalInertia.make_from_moments_and_products_of_inertia(
        1.0, 1.0, 2.0 + 4e-6, 0, 0, 0, skip_validity_check=True)
    assert not over.could_be_physically_valid()
    assert over.could_be_physically_valid(1e-5)
    # Indefinite although the diagonal satisfies the triangle inequality: [[1, 1, 0], [1, 1, 0],
    # [0, 0, 1]] has eigenvalues 0, 1, 2 → 0 + 1 < 2.
    indefinite = RotationalInertia.make_from_moments_and_products_of_inertia(
        1, 1, 1, 1, 0, 0, skip_validity_check=True)
    assert not indefinite.could_be_physically_valid()
    assert RotationalInertia().is_nan()


def test_invalid_results_raise_value_error_in_every_build():
    with pytest.raises(ValueError, match="triangle inequality"):
        RotationalInertia(0.1, 0.2, 0.5)
    with pytest.raises(ValueError):
        RotationalInertia(1.0, 1.0, 1.0) - RotationalInertia(2.0, 2.0, 2.0)
    with pytest.raises(ValueError, match="must be >= 0"):
        RotationalInertia(1.0, 1.0, 1.0) * -1.0
    with pytest.raises(ValueError, match="must be > 0"):
        RotationalInertia(1.0, 1.0, 1.0) / 0.0
    with pytest.raises(ValueError, match="negative or not finite"):
        UnitInertia.solid_sphere(-1.0)
    with pytest.raises(ValueError, match="not symmetric"):
        RotationalInertia.from_matrix([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    with pytest.raises(ValueError, match="non-finite"):
        RotationalInertia.make_from_moments_and_products_of_inertia(
            math.nan, 1, 1, 0, 0, 0, True).calc_principal_moments_of_inertia()
    with pytest.raises(ValueError, match="solver"):
        RotationalInertia(1.0, 1.0, 1.0).calc_principal_moments_of_inertia("exact")
    with pytest.raises(IndexError):
        RotationalInertia(1.0, 1.0, 1.0)[3, 0]
    with pytest.raises(TypeError):
        RotationalInertia.from_matrix(np.eye(4))
    with pytest.raises(TypeError):
        RotationalInertia(1.0, [1.0, 2.0])  # a 2-vector is no position
    with pytest.raises(TypeError):
        RotationalInertia(1.0, 1.0, 1.0).calc_principal_moments_of_inertia(3)


def test_equality_repr_and_pickle():
    I = RotationalInertia(1.0, 2.0, 2.5, 0.1, 0.0, -0.2)
    assert I == RotationalInertia(1.0, 2.0, 2.5, 0.1, 0.0, -0.2)
    assert I != RotationalInertia(1.0, 2.0, 2.5)
    assert repr(I) == "RotationalInertia(Ixx=1, Iyy=2, Izz=2.5, Ixy=0.1, Ixz=0, Iyz=-0.2)"
    assert eval(repr(I), {"RotationalInertia": RotationalInertia}) == I
    assert pickle.loads(pickle.dumps(I)) == I
    G = UnitInertia.solid_cube(1.0)
    assert repr(G).startswith("UnitInertia(Ixx=0.16666666666666666")
    assert pickle.loads(pickle.dumps(G)) == G
    M = SpatialInertia.point_mass(2.0, [1.0, 0.0, 0.0])
    assert repr(M).startswith("SpatialInertia(mass=2, p_PScm_E=[1, 0, 0]")
    assert pickle.loads(pickle.dumps(M)) == M
    nan = RotationalInertia()
    assert nan != nan  # NaN compares unequal, as in C++


def test_spatial_inertia_composite_of_two_boxes_by_hand():
    # Two 1 kg unit cubes (central 1/6 each) with centers at x = ±1 about the origin: mass 2,
    # com 0, Ixx = 2/6, Iyy = Izz = 2·(1/6 + 1) (parallel-axis theorem).
    cube = UnitInertia.solid_cube(1.0)
    left = SpatialInertia.make_from_central_inertia(1.0, [-1.0, 0, 0], 1.0 * cube)
    right = SpatialInertia.make_from_central_inertia(1.0, [1.0, 0, 0], 1.0 * cube)
    both = left + right
    assert both.get_mass() == 2.0
    np.testing.assert_allclose(both.get_com(), [0, 0, 0], atol=1e-15)
    np.testing.assert_allclose(both.calc_rotational_inertia().get_moments(),
                               [2 / 6, 2 * (1 / 6 + 1), 2 * (1 / 6 + 1)], rtol=1e-15)
    assert both.is_physically_valid()
    # Shift about x = 1: the com is at -1 from there.
    np.testing.assert_allclose(both.shift([1.0, 0, 0]).get_com(), [-1.0, 0, 0])
    # Pseudo-inertia bottom-right is the mass; 6x6 bottom-right is m·1.
    assert both.calc_pseudo_inertia()[3, 3] == 2.0
    np.testing.assert_array_equal(both.copy_to_full_matrix6()[3:, 3:], 2.0 * np.eye(3))
    with pytest.raises(ValueError, match="negative or not finite"):
        SpatialInertia.make_from_central_inertia(-1.0, [0, 0, 0], 1.0 * cube)
    bad = SpatialInertia(1.0, [0, 0, 0], UnitInertia(0.1, 0.2, 0.5, skip_validity_check=True),
                         skip_validity_check=True)
    assert not bad.is_physically_valid()
    assert "not physically valid" in bad.criticize_not_physically_valid()


def test_docstrings_everywhere():
    public = [massprops.RotationalInertia, massprops.UnitInertia, massprops.SpatialInertia,
              massprops.principal_moments, massprops.is_physically_valid, massprops.read,
              massprops.check, massprops.report, massprops.fix, massprops.Model,
              massprops.Link, massprops.Finding, massprops.FixResult, massprops.ReadError]
    for item in public:
        assert item.__doc__ and len(item.__doc__) > 30, item
    for cls in (RotationalInertia, UnitInertia, SpatialInertia, massprops.Model):
        for name, member in vars(cls).items():
            if name.startswith("_") or not callable(member):
                continue
            assert member.__doc__ and len(member.__doc__.strip()) > 20, f"{cls.__name__}.{name}"


def test_repair_inertia_by_hand():
    # docs/fix.md: diag(0.1, 0.2, 0.5) violates 0.1 + 0.2 >= 0.5 by 0.2; the nearest valid
    # inertia moves each moment by 0.2/3 along (1, 1, −1) (plus a 1e-9 floor); balance sets the
    # three moments to their mean 0.8/3.
    fixed = massprops.repair_inertia(np.diag([0.1, 0.2, 0.5]))
    np.testing.assert_allclose(np.diag(fixed), [0.1 + 0.2 / 3, 0.2 + 0.2 / 3, 0.5 - 0.2 / 3],
                               rtol=1e-8)
    assert massprops.is_physically_valid(fixed[None], 0.0)[0]
    balanced = massprops.repair_inertia(np.diag([0.1, 0.2, 0.5]), "balance")
    np.testing.assert_allclose(balanced, np.eye(3) * 0.8 / 3, rtol=1e-15, atol=1e-17)
    valid = np.diag([1.0, 2.0, 2.5])
    np.testing.assert_array_equal(massprops.repair_inertia(valid), valid)
    with pytest.raises(ValueError, match="method"):
        massprops.repair_inertia(valid, "nearest")
    with pytest.raises(ValueError, match="symmetric"):
        massprops.repair_inertia(np.triu(np.ones((3, 3))))
