"""Shared fixtures of the Python tests (run by ctest: see python/CMakeLists.txt, which sets
PYTHONPATH to the build tree and the MASSPROPS_* variables below)."""
import os
import pathlib
import sys

import pytest

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = HERE.parent.parent
sys.path.insert(0, str(SOURCE / "tests"))
import shared_data  # noqa: E402  (tests/shared_data.py)


def _env_path(name, default):
    return pathlib.Path(os.environ.get(name, default))


TESTDATA = _env_path("MASSPROPS_TESTDATA_DIR", SOURCE / "testdata")
EXAMPLES = _env_path("MASSPROPS_EXAMPLES_DIR", SOURCE / "examples")
SHARED = _env_path("MASSPROPS_SHARED_DIR", SOURCE.parent / "shared")
CORPUS = SHARED / "corpus"
XACRO = SHARED / "xacro"
TOOL = os.environ.get("MASSPROPS_TOOL", "")


@pytest.fixture
def testdata():
    return TESTDATA


@pytest.fixture
def examples():
    return EXAMPLES


@pytest.fixture(scope="session")
def tool():
    if not TOOL or not os.path.exists(TOOL):
        pytest.skip("MASSPROPS_TOOL (the massprops executable) is not set")
    return TOOL


def need_shared(part):
    """Skips the calling test or fixture unless ../shared/`part` exists, or fails it where ../shared
    is there (tests/shared_data.py)."""
    why = shared_data.missing(SHARED, part)
    if why:
        (pytest.fail if shared_data.required(SHARED) else pytest.skip)(why)


# A test file whose every test was skipped by need_shared exits with shared_data.SKIP_EXIT, which
# ctest reports as skipped (python/CMakeLists.txt, SKIP_RETURN_CODE), not as passed.
_skipped_for_shared = set()


def pytest_runtest_logreport(report):
    if report.skipped and shared_data.MISSING in str(report.longrepr):
        _skipped_for_shared.add(report.nodeid)


def pytest_sessionfinish(session, exitstatus):
    if exitstatus == 0 and session.testscollected and \
            len(_skipped_for_shared) == session.testscollected:
        session.exitstatus = shared_data.SKIP_EXIT
