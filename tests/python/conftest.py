"""Shared fixtures of the Python module's tests (tests/python/, issue #12).

CTest (tests/python/CMakeLists.txt) runs pytest on this folder with PYTHONPATH set to the
build's module folder, PDR_BINARY to the `pdr` command (the tests compare the module with
it) and PDR_DATA_DIR to data/. Geometry helpers here are plain numpy, independent of pdr,
so a test can judge the module's output by its own measure.
"""
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

DATA_DIR = pathlib.Path(os.environ.get(
    "PDR_DATA_DIR", pathlib.Path(__file__).resolve().parents[2] / "data"))

# The unit cube [0,1]^3 as a PLC: 8 corners, 6 square facets.
CUBE_POINTS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                        [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=float)
CUBE_FACETS = [[0, 1, 2, 3], [4, 5, 6, 7], [0, 1, 5, 4],
               [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]


def write_poly(path, points, facets, holes=()):
    """A TetGen .poly file (0-based) of a PLC whose facets are single polygons."""
    lines = [f"{len(points)} 3 0 0"]
    lines += [f"{i} {x!r} {y!r} {z!r}" for i, (x, y, z) in enumerate(points)]
    lines.append(f"{len(facets)} 0")
    for f in facets:
        lines += ["1 0", f"{len(f)} " + " ".join(map(str, f))]
    lines.append(f"{len(holes)}")
    lines += [f"{i} {x!r} {y!r} {z!r}" for i, (x, y, z) in enumerate(holes)]
    lines.append("0")
    pathlib.Path(path).write_text("\n".join(lines) + "\n")


def signed_volumes(points, tets):
    """det[b-a, c-a, d-a] / 6 per tet."""
    p = np.asarray(points)[np.asarray(tets)]
    return np.einsum("ij,ij->i", p[:, 1] - p[:, 0],
                     np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6.0


def radius_edge_ratios(points, tets):
    """Circumradius / shortest edge per tet (floating point: for margins, not verdicts)."""
    p = np.asarray(points)[np.asarray(tets)]
    e = p[:, 1:] - p[:, :1]                       # b-a, c-a, d-a
    rhs = 0.5 * np.einsum("ijk,ijk->ij", e, e)
    centre = np.linalg.solve(e, rhs[..., None])[..., 0]
    radius = np.linalg.norm(centre, axis=1)
    pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)]
    shortest = np.min([np.linalg.norm(p[:, i] - p[:, j], axis=1) for i, j in pairs], axis=0)
    return radius / shortest


@pytest.fixture(scope="session")
def pdr_cli():
    """The `pdr` command of the same build."""
    path = os.environ.get("PDR_BINARY") or shutil.which("pdr")
    if not path:
        pytest.skip("PDR_BINARY is not set and pdr is not on PATH")
    return path


def run_cli(cli, *args, cwd=None):
    return subprocess.run([cli, *map(str, args)], capture_output=True, text=True, cwd=cwd)
