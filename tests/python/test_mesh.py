"""pdr.mesh: the mesher on arrays and on files, judged by the exact checker (pdr.check),
by numpy's own measures, and against the `pdr mesh` command."""
import json

import numpy as np
import pytest

import pdr
from conftest import (CUBE_FACETS, CUBE_POINTS, DATA_DIR, radius_edge_ratios, run_cli,
                      signed_volumes, write_poly)


def check_ids(report, status):
    return {c["id"] for c in report["checks"] if c["status"] == status}


def test_cube_every_tet_checked():
    m = pdr.mesh(CUBE_POINTS, CUBE_FACETS, ratio=2.0, max_volume=0.01)
    assert (m["status"], m["exit_code"], m["reason"]) == ("ok", 0, "")
    pts, tets, faces = m["points"], m["tets"], m["faces"]
    assert pts.dtype == np.float64 and pts.shape[1] == 3
    assert tets.dtype == np.int64 and tets.shape[1] == 4 and len(tets) >= 100
    assert faces.shape[1] == 3 and len(faces) >= 12
    assert tets.min() >= 0 and tets.max() < len(pts)
    # numpy's measures: positive tets that fill the cube, within the volume bound, ratio < 2.
    vol = signed_volumes(pts, tets)
    assert vol.min() > 0 and vol.max() <= 0.01
    assert vol.sum() == pytest.approx(1.0, abs=1e-12)
    assert radius_edge_ratios(pts, tets).max() < 2.0
    # Every corner is a vertex; every boundary face lies on the cube's surface.
    for corner in CUBE_POINTS:
        assert np.any(np.all(pts == corner, axis=1))
    on_surface = np.any((pts[faces] == 0) | (pts[faces] == 1), axis=1)
    assert on_surface.any(axis=1).all()
    # The exact checker, every tet.
    r = pdr.check(pts, tets, faces, domain=(CUBE_POINTS, CUBE_FACETS), ratio=2.0)
    assert r["ok"] is True and r["schema_version"] == 1
    assert r["mesh"] == {"points": len(pts), "tets": len(tets), "boundary_faces": len(faces)}
    by_id = {c["id"]: c for c in r["checks"]}
    for cid in ("validity.orientation", "quality.ratio", "delaunay.empty_sphere"):
        assert by_id[cid]["status"] == "pass"
        assert by_id[cid]["checked"] == len(tets)
    assert by_id["conformity.facets"]["status"] == "pass"
    assert not check_ids(r, "fail")
    # The summary is pdr mesh's.
    s = m["summary"]
    assert s["command"] == "mesh" and s["domain"] == "<arrays>"
    assert (s["vertices"], s["tets"], s["boundary_faces"]) == (len(pts), len(tets), len(faces))
    assert s["check"] == "pass" and s["admissible"] is True
    assert s["ratio_max"] < 2.0 and s["order_independence"]["missing"] == 0
    assert "written" not in s


def test_matches_the_command(tmp_path, pdr_cli):
    poly = tmp_path / "cube.poly"
    write_poly(poly, CUBE_POINTS, CUBE_FACETS)
    cli = run_cli(pdr_cli, "mesh", poly, "-o", tmp_path / "out" / "cube", "--max-volume",
                  "0.02", "--json")
    assert cli.returncode == 0, cli.stderr
    cli_summary = json.loads(cli.stdout)
    from_file = pdr.mesh(str(poly), max_volume=0.02)
    from_arrays = pdr.mesh(CUBE_POINTS, CUBE_FACETS, max_volume=0.02)
    s = from_file["summary"]
    assert set(cli_summary) - set(s) == {"written"}
    assert set(s) == set(cli_summary) - {"written"}
    for key in ("domain", "vertices", "tets", "boundary_faces", "ratio_max", "d",
                "inserted", "check", "order_independence"):
        assert s[key] == cli_summary[key], key
    # The arrays are the written mesh, and the same PLC given as arrays meshes alike.
    written = pdr.read(tmp_path / "out" / "cube")
    for key in ("points", "tets", "faces"):
        np.testing.assert_array_equal(from_file[key], written[key])
        np.testing.assert_array_equal(from_arrays[key], written[key])


def test_volume_hole_from_a_read_domain():
    d = pdr.read(DATA_DIR / "cube-in-cube.poly")
    m = pdr.mesh(d["points"], d["facets"], d["holes"])
    assert m["status"] == "ok"
    centroids = m["points"][m["tets"]].mean(axis=1)
    in_void = np.all((centroids > 4) & (centroids < 6), axis=1)
    assert not in_void.any()
    assert signed_volumes(m["points"], m["tets"]).sum() == pytest.approx(1000 - 8, abs=1e-9)
    # The facets' markers (1 outside, 2 on the void) come back on the faces.
    assert set(np.unique(m["face_markers"])) == {1, 2}
    assert pdr.check(m["points"], m["tets"], m["faces"], domain=d)["ok"]


def test_nested_shells_as_a_poly_reads_them():
    # Without its hole point the inner cube of cube-in-cube is a second region (TetGen's
    # reading, for arrays as for a .poly); a dict read from a surface file keeps parity.
    d = pdr.read(DATA_DIR / "cube-in-cube.poly")
    assert d["enclosure"] == "hole_points"
    m = pdr.mesh(d["points"], d["facets"])
    assert m["status"] == "ok"
    assert signed_volumes(m["points"], m["tets"]).sum() == pytest.approx(1000, abs=1e-9)
    d["holes"] = np.zeros((0, 3))
    d["enclosure"] = "parity"
    m = pdr.mesh(d)
    assert m["status"] == "ok"
    assert signed_volumes(m["points"], m["tets"]).sum() == pytest.approx(1000 - 8, abs=1e-9)
    r = pdr.read(DATA_DIR / "inclusion.poly")
    assert len(r["regions"]) == 2
    m = pdr.mesh(r)
    assert set(np.unique(m["tet_regions"])) == {1, 2}


def test_facet_walls_and_a_regional_volume_bound():
    # data/walls.poly: three cubes split by two walls, each a region; the first one's
    # region record bounds its tets' volume by 0.002.
    d = pdr.read(DATA_DIR / "walls.poly")
    m = pdr.mesh(d, max_volume=0.01)
    assert m["status"] == "ok"
    vols = signed_volumes(m["points"], m["tets"])
    assert vols.sum() == pytest.approx(3, abs=1e-12)
    labels = m["tet_regions"]
    assert set(np.unique(labels)) == {1, 3, 4}
    assert vols[labels == 1].max() <= 0.002 * (1 + 1e-12)
    assert vols[labels == 4].max() > 0.002
    assert pdr.check(m["points"], m["tets"], m["faces"], domain=d)["ok"]


def test_facets_with_several_polygons_and_a_facet_hole():
    # The unit cube with a square well 0.4 wide and 0.5 deep in its top: the top facet is
    # the outer square and the well's rim, with a facet hole point inside the rim; the
    # bottom facet also holds an isolated vertex (a 1-vertex polygon) and a segment.
    rim = [[0.3, 0.3, 1], [0.7, 0.3, 1], [0.7, 0.7, 1], [0.3, 0.7, 1]]
    floor = [[x, y, 0.5] for x, y, _ in rim]
    extra = [[0.5, 0.5, 0], [0.2, 0.2, 0], [0.2, 0.8, 0]]
    points = np.vstack([CUBE_POINTS, rim, floor, extra])
    facets = [
        {"polygons": [[0, 1, 2, 3], [16], [17, 18]], "marker": 5},   # bottom
        {"polygons": [[4, 5, 6, 7], [8, 9, 10, 11]], "holes": [[0.5, 0.5, 1]]},  # top
        [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7],      # sides
        [[12, 13, 14, 15]],                                         # the well's floor
        [8, 9, 13, 12], [9, 10, 14, 13], [10, 11, 15, 14], [11, 8, 12, 15],
    ]
    m = pdr.mesh(points, facets, max_volume=0.02)
    assert m["status"] == "ok", m["reason"]
    vol = signed_volumes(m["points"], m["tets"])
    assert vol.sum() == pytest.approx(1 - 0.4 * 0.4 * 0.5, abs=1e-12)
    centroids = m["points"][m["tets"]].mean(axis=1)
    in_well = np.all((centroids[:, :2] > 0.3) & (centroids[:, :2] < 0.7), axis=1) & \
        (centroids[:, 2] > 0.5)
    assert not in_well.any()
    for p in extra:
        assert np.any(np.all(m["points"] == p, axis=1))
    assert 5 in set(m["face_markers"])
    r = pdr.check(m["points"], m["tets"], m["faces"], domain=(points, facets), ratio=2.0)
    assert r["ok"], [c for c in r["checks"] if c["status"] == "fail"]


def test_bound_not_met_is_exit_3(tmp_path, pdr_cli):
    # A vertex cap far below what the volume bound needs: pdr mesh exits 3.
    poly = tmp_path / "cube.poly"
    write_poly(poly, CUBE_POINTS, CUBE_FACETS)
    cli = run_cli(pdr_cli, "mesh", poly, "-o", tmp_path / "cube", "--max-volume", "0.0001",
                  "--max-vertices", "200", "--json")
    assert cli.returncode == 3, cli.stderr
    m = pdr.mesh(CUBE_POINTS, CUBE_FACETS, max_volume=0.0001, max_vertices=200)
    assert (m["status"], m["exit_code"]) == ("not_guaranteed", 3)
    assert "NOT GUARANTEED" in m["reason"]
    assert json.loads(cli.stdout)["quality"] in m["reason"]
    assert isinstance(m["leftovers"], list)


def test_bound_below_two_at_the_cap_is_exit_3(tmp_path, pdr_cli):
    # B = 1 is outside Theorem 1 (it refines tets of ratio >= 2): the run stops at the cap,
    # and the check holds no edge to the theorem's h, so only quality.ratio fails.
    cli = run_cli(pdr_cli, "mesh", DATA_DIR / "box.poly", "-o", tmp_path / "box", "--ratio",
                  "1", "--max-vertices", "2000", "--audit", "--json")
    assert cli.returncode == 3, cli.stderr
    assert json.loads(cli.stdout)["check_failed"] == ["quality.ratio"]


def test_surface_cap_returns_no_mesh():
    # The cap reached while meshing the surface: exit 3 of pdr mesh, nothing meshed.
    m = pdr.mesh(DATA_DIR / "cube-in-cube.poly", max_vertices=20)
    assert (m["status"], m["exit_code"]) == ("not_guaranteed", 3)
    assert m["tets"].shape == (0, 4) and m["points"].shape == (0, 3)
    assert m["summary"]["stop_reason"].startswith("surface.cap:")
    assert "stopped before meshing" in m["reason"]
