"""pdr.check: the exact checker's report, as `pdr check --json` prints it, on a mesh made
by the `tetgen` command and on planted faults."""
import json
import shutil
import subprocess

import numpy as np
import pytest

import pdr
from conftest import DATA_DIR, run_cli

POLY = DATA_DIR / "cube-in-cube.poly"


@pytest.fixture(scope="module")
def tetgen_mesh(tmp_path_factory):
    """tetgen -pq1.4a0.1 cube-in-cube.poly: the prefix of its .node/.ele/.face files."""
    if shutil.which("tetgen") is None:
        pytest.skip("tetgen is not installed (scripts/install-deps.sh --tests)")
    work = tmp_path_factory.mktemp("tetgen")
    shutil.copy(POLY, work)
    subprocess.run(["tetgen", "-pq1.4a0.1", "cube-in-cube.poly"], cwd=work, check=True,
                   capture_output=True)
    return work / "cube-in-cube.1"


def statuses(report):
    return {c["id"]: c["status"] for c in report["checks"]}


# What TetGen does not promise: its mesh optimisation (on by default) flips tets for better
# dihedral angles, leaving non-Delaunay tets, and may leave subfacets encroached (README,
# "pdr check versus other meshers").
NOT_PROMISED = {"delaunay.empty_sphere", "order.independence", "encroachment.subsegments",
                "encroachment.subfacets"}


def test_tetgen_mesh(tetgen_mesh, pdr_cli):
    r = pdr.check(str(tetgen_mesh), domain=str(POLY), ratio=2.0)
    assert r["mesh"]["tets"] > 1000 and r["domain"] is True
    assert r["options"]["ratio_bound"] == 2.0
    st = statuses(r)
    assert list(st) == [c["id"] for c in r["checks"]]
    for cid in ("validity.orientation", "validity.overlap", "validity.boundary_closed",
                "quality.ratio", "conformity.vertices", "conformity.segments",
                "conformity.facets", "conformity.volume"):
        assert st[cid] == "pass", (cid, st[cid])
    failed = {cid for cid, s in st.items() if s == "fail"}
    assert failed <= NOT_PROMISED
    assert r["ok"] == (not failed)
    # The same object as the command prints, but for the wall times.
    cli = run_cli(pdr_cli, "check", tetgen_mesh, "--domain", POLY, "--ratio", "2", "--json")
    assert cli.returncode == (0 if r["ok"] else 1), cli.stderr
    expected = json.loads(cli.stdout)
    assert set(r) == set(expected)
    for key in expected:
        if key != "seconds":
            assert r[key] == expected[key], key
    assert {"read", "check"} <= set(r["seconds"])


def test_tetgen_mesh_as_arrays(tetgen_mesh):
    m = pdr.read(tetgen_mesh)
    assert m["kind"] == "mesh" and m["tets"].shape[1] == 4
    r = pdr.check(m["points"], m["tets"], m["faces"], domain=pdr.read(POLY), ratio=2.0)
    assert r["input"]["mesh"] == "<arrays>" and r["input"]["domain"] == "<arrays>"
    assert r["mesh"]["tets"] == len(m["tets"])
    from_files = pdr.check(str(tetgen_mesh), domain=str(POLY), ratio=2.0)
    assert r["checks"] == from_files["checks"]


def test_flipped_tet_fails(tetgen_mesh, tmp_path, pdr_cli):
    m = pdr.read(tetgen_mesh)
    tets = m["tets"].copy()
    tets[7, [0, 1]] = tets[7, [1, 0]]   # tet 7 turned inside out
    r = pdr.check(m["points"], tets, m["faces"], ratio=2.0)
    assert r["ok"] is False
    orientation = next(c for c in r["checks"] if c["id"] == "validity.orientation")
    assert orientation["status"] == "fail" and orientation["violations"] == 1
    assert orientation["findings"][0]["id"] == 7
    assert orientation["findings"][0]["message"].startswith("validity.orientation")
    # The command says the same of the same mesh written out (exit 1).
    pdr.write(tmp_path / "flipped", m["points"], tets, m["faces"], formats=["node"])
    cli = run_cli(pdr_cli, "check", tmp_path / "flipped", "--ratio", "2", "--json")
    assert cli.returncode == 1
    assert json.loads(cli.stdout)["checks"] == r["checks"]


def test_unchecked_ratio_and_bad_indices():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    one = pdr.check(points, [[0, 1, 2, 3]], ratio=None)
    assert one["ok"] and statuses(one)["quality.ratio"] == "skipped"
    bad = pdr.check(points, [[0, 1, 2, 4]])   # index 4 of 4 points: a failed check
    assert not bad["ok"] and statuses(bad)["validity.indices"] == "fail"


def test_non_delaunay_pair_fails():
    # A square-ish pyramid base split along the diagonal 0-2: each of the two (positive)
    # tets holds the other's far vertex (3, resp. 1) inside its circumsphere.
    points = np.array([[0, 0, 0], [2, 0, 0], [2.2, 2.2, 0], [0, 2, 0], [1, 1, 1]], dtype=float)
    r = pdr.check(points, [[0, 1, 2, 4], [0, 2, 3, 4]], ratio=None)
    st = statuses(r)
    assert st["validity.orientation"] == "pass" and st["validity.overlap"] == "pass"
    assert st["delaunay.empty_sphere"] == "fail"
