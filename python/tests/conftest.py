"""Shared fixtures of the Python tests (run by ctest: see python/CMakeLists.txt, which sets
PYTHONPATH to the build tree and the MASSPROPS_* variables below)."""
import os
import pathlib

import pytest

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = HERE.parent.parent


def _env_path(name, default):
    return pathlib.Path(os.environ.get(name, default))


TESTDATA = _env_path("MASSPROPS_TESTDATA_DIR", SOURCE / "testdata")
EXAMPLES = _env_path("MASSPROPS_EXAMPLES_DIR", SOURCE / "examples")
CORPUS = _env_path("MASSPROPS_CORPUS_DIR", SOURCE.parent / "shared" / "corpus")
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
