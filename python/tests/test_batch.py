"""The vectorised helpers: the same numbers as the per-object C++ calls, against
numpy.linalg.eigvalsh (LAPACK's symmetric eigensolver, an independent second library), shapes,
bad input, and the GIL released while they run."""
import math
import threading
import time

import numpy as np
import pytest

import massprops
from massprops import RotationalInertia

EPS = np.finfo(float).eps


def random_inertias(n, seed):
    """n valid inertias: random principal moments satisfying the triangle inequality, rotated by
    random rotations (QR of a Gaussian matrix, sign-fixed), with scales from 1e-6 to 1e3."""
    rng = np.random.default_rng(seed)
    a = rng.uniform(0.0, 1.0, size=(n, 3))
    # Σ's diagonal (a) ≥ 0 gives principal moments λ_i = a_j + a_k: always valid.
    moments = np.stack([a[:, 1] + a[:, 2], a[:, 0] + a[:, 2], a[:, 0] + a[:, 1]], axis=1)
    moments *= 10.0 ** rng.uniform(-6, 3, size=(n, 1))
    q, r = np.linalg.qr(rng.normal(size=(n, 3, 3)))
    q *= np.sign(np.diagonal(r, axis1=1, axis2=2))[:, None, :]
    I = q @ (moments[:, :, None] * np.swapaxes(q, 1, 2))
    return 0.5 * (I + np.swapaxes(I, 1, 2))


@pytest.mark.parametrize("solver", ["accurate", "fast"])
def test_principal_moments_match_eigvalsh_to_round_off_of_the_trace(solver):
    I = random_inertias(20000, seed=1)
    ours = massprops.principal_moments(I, solver=solver)
    theirs = np.linalg.eigvalsh(I)
    trace = np.trace(I, axis1=1, axis2=2)
    error = np.max(np.abs(ours - theirs) / trace[:, None])
    # principal_axes.h: kAccurate within a few eps of the trace, kFast within 1200 eps (measured
    # about 60); LAPACK's own error is a few eps of the norm as well.
    assert error < (32 if solver == "accurate" else 1200) * EPS


@pytest.mark.parametrize("solver", ["accurate", "fast"])
def test_principal_moments_equal_the_per_object_calls_exactly(solver):
    I = random_inertias(500, seed=2)
    I[7] = np.diag([3.0, 1.0, 2.0])  # diagonal: exact
    I[8] = 1e300 * np.diag([1.0, 1.0, 2.0])  # huge entries: scaled, no overflow
    batch = massprops.principal_moments(I, solver)
    for k in range(len(I)):
        one = RotationalInertia.from_matrix(I[k], skip_validity_check=True)
        np.testing.assert_array_equal(batch[k], one.calc_principal_moments_of_inertia(solver))
    np.testing.assert_array_equal(batch[7], [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(batch[8], [1e300, 1e300, 2e300])


def test_is_physically_valid_equals_the_per_object_call_and_the_eigenvalue_test():
    I = random_inertias(2000, seed=3)
    # Make every other one invalid by a clear margin: raise the largest principal moment above
    # the sum of the other two by 10% of the trace, keeping the axes.
    w, v = np.linalg.eigh(I)
    w[1::2, 2] = w[1::2, 0] + w[1::2, 1] + 0.1 * w[1::2].sum(axis=1)
    J = v @ (w[:, :, None] * np.swapaxes(v, 1, 2))
    J = 0.5 * (J + np.swapaxes(J, 1, 2))
    valid = massprops.is_physically_valid(J)
    assert valid.dtype == np.bool_ and valid.shape == (2000,)
    # Independent test with LAPACK: λ1 + λ2 >= λ3 − 1e-6·trace and λ1 >= −1e-6·trace.
    lam = np.linalg.eigvalsh(J)
    tr = lam.sum(axis=1)
    expected = (lam[:, 0] + lam[:, 1] >= lam[:, 2] - 1e-6 * tr) & (lam[:, 0] >= -1e-6 * tr)
    np.testing.assert_array_equal(valid, expected)
    assert valid[0::2].all() and not valid[1::2].any()
    for k in range(0, 2000, 97):
        one = RotationalInertia.from_matrix(J[k], skip_validity_check=True)
        assert valid[k] == one.could_be_physically_valid(1e-6)
        assert massprops.is_physically_valid(J[k:k + 1], massprops.DEFAULT_VALIDITY_TOLERANCE)[0] \
            == one.could_be_physically_valid()


def test_shapes_dtypes_and_non_finite_rows():
    I = np.tile(np.diag([1, 2, 2]), (2, 3, 1, 1))  # int array of shape (2, 3, 3, 3)
    out = massprops.principal_moments(I)
    assert out.shape == (2, 3, 3) and out.dtype == np.float64
    np.testing.assert_array_equal(out[1, 2], [1.0, 2.0, 2.0])
    assert massprops.is_physically_valid(I).shape == (2, 3)
    single = massprops.principal_moments(np.diag([2.0, 1.0, 3.0]))  # one matrix: shape (3,)
    np.testing.assert_array_equal(single, [1.0, 2.0, 3.0])
    assert massprops.principal_moments(np.zeros((0, 3, 3))).shape == (0, 3)
    bad = np.array([np.eye(3), np.diag([math.nan, 1.0, 1.0]), np.diag([math.inf, 1.0, 1.0])])
    out = massprops.principal_moments(bad)
    np.testing.assert_array_equal(out[0], [1.0, 1.0, 1.0])
    assert np.isnan(out[1]).all() and np.isnan(out[2]).all()
    np.testing.assert_array_equal(massprops.is_physically_valid(bad), [True, False, False])
    transposed = np.asfortranarray(random_inertias(10, seed=4))  # not C-contiguous: converted
    np.testing.assert_array_equal(massprops.principal_moments(transposed),
                                  massprops.principal_moments(np.ascontiguousarray(transposed)))


def test_bad_arguments_raise_value_or_type_errors():
    with pytest.raises(ValueError, match=r"shape \(N, 3, 3\).*got shape \(4, 3\)"):
        massprops.principal_moments(np.zeros((4, 3)))
    with pytest.raises(ValueError, match=r"got shape \(3,\)"):
        massprops.is_physically_valid(np.zeros(3))
    asym = np.array([np.eye(3), [[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]])
    with pytest.raises(ValueError, match="matrix 1 is not symmetric"):
        massprops.principal_moments(asym)
    with pytest.raises(ValueError, match="matrix 1 is not symmetric"):
        massprops.is_physically_valid(asym)
    with pytest.raises(ValueError, match="tolerance"):
        massprops.is_physically_valid(np.eye(3)[None], -1.0)
    with pytest.raises(ValueError, match="solver"):
        massprops.principal_moments(np.eye(3)[None], solver="slow")
    with pytest.raises(TypeError):
        massprops.principal_moments(np.eye(3)[None], solver=None)
    with pytest.raises((TypeError, ValueError)):
        massprops.principal_moments("not an array")


def test_the_gil_is_released_while_principal_moments_runs():
    # While a thread runs principal_moments on a large array, this thread keeps running Python
    # code: with the GIL held for the whole call it could not run at all until the call ends.
    I = np.tile(np.array([[2.0, 1.0, 0.0], [1.0, 2.0, 0.5], [0.0, 0.5, 3.0]]), (500_000, 1, 1))
    started, done = threading.Event(), threading.Event()

    def work():
        started.set()
        massprops.principal_moments(I)
        done.set()

    thread = threading.Thread(target=work)
    thread.start()
    started.wait()
    time.sleep(0.001)
    spins = 0
    while not done.is_set():
        spins += 1
    thread.join()
    assert spins > 100
