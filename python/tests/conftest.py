"""Shared fixtures of the Python tests (run by ctest: python/CMakeLists.txt sets the paths)."""

import importlib
import os
import pathlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SHAPES = pathlib.Path(os.environ.get("FRONTPACK_SHAPES_DIR", ROOT / "shapes"))
TEST_DATA = pathlib.Path(os.environ.get("FRONTPACK_TEST_DATA_DIR", ROOT / "tests" / "data"))


def need(module):
    """Imports an optional module of the tests (shapely, matplotlib): a skip without it, a failure
    where FRONTPACK_REQUIRE_READERS=1 says every test must run (tools/dev.sh test)."""
    try:
        return importlib.import_module(module)
    except ImportError as e:
        if os.environ.get("FRONTPACK_REQUIRE_READERS") == "1":
            pytest.fail("%s is required here (FRONTPACK_REQUIRE_READERS=1): %s" % (module, e))
        pytest.skip("%s is not installed" % module)


@pytest.fixture
def shapes():
    return SHAPES


@pytest.fixture
def test_data():
    return TEST_DATA


@pytest.fixture
def square_with_hole():
    """The unit square with a square hole, as shapely geometry (python3-shapely)."""
    geometry = need("shapely.geometry")
    return geometry.Polygon(
        [(0, 0), (1, 0), (1, 1), (0, 1)], [[(0.4, 0.4), (0.4, 0.6), (0.6, 0.6), (0.6, 0.4)]]
    )


def same_bits(a, b):
    """Whether two float64 arrays hold the same bits (NaN-safe, -0.0 distinct from 0.0)."""
    a = np.ascontiguousarray(a, dtype=np.float64)
    b = np.ascontiguousarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()
