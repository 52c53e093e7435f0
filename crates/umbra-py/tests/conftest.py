"""Shared fixtures of the umbra Python tests: analytic shapes and the
command-line binary when one is built."""

import os
import pathlib
import shutil

import numpy as np
import pytest

import umbra

REPO = pathlib.Path(__file__).resolve().parents[3]


def cube(lo=(0.0, 0.0, 0.0), size=1.0):
    """An axis-aligned cube as quads, facing outwards (volume size**3)."""
    x, y, z = lo
    s = size
    v = np.array(
        [
            [x, y, z], [x + s, y, z], [x + s, y + s, z], [x, y + s, z],
            [x, y, z + s], [x + s, y, z + s], [x + s, y + s, z + s], [x, y + s, z + s],
        ],
        dtype=np.float64,
    )
    f = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    return umbra.Mesh(v, f)


def tetra():
    """The unit right tetrahedron as an (m, 3) triangle array (volume 1/6)."""
    v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
    f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int64)
    return umbra.Mesh(v, f)


@pytest.fixture
def unit_cube():
    return cube()


def cli_binary():
    """The `umbra` binary: $UMBRA_CLI, or a build in the workspace's target
    directory, or on PATH; None when there is none."""
    env = os.environ.get("UMBRA_CLI")
    if env and os.path.isfile(env):
        return env
    for profile in ("release", "debug"):
        p = REPO / "target" / profile / "umbra"
        if p.is_file():
            return str(p)
    return shutil.which("umbra")


@pytest.fixture
def cli():
    exe = cli_binary()
    if exe is None:
        pytest.skip("the umbra command-line binary is not built")
    return exe
