"""pdr.read and pdr.write: round trips through every format the io layer writes, and a
rejected mesh leaving no file behind."""
import os

import numpy as np
import pytest

import pdr
from conftest import CUBE_FACETS, CUBE_POINTS, DATA_DIR


@pytest.fixture(scope="module")
def cube():
    return pdr.mesh(CUBE_POINTS, CUBE_FACETS, max_volume=0.05)


def face_set(faces):
    """Faces as rotation-normalised tuples (orientation kept)."""
    out = set()
    for f in np.asarray(faces).tolist():
        k = f.index(min(f))
        out.add(tuple(f[k:] + f[:k]))
    return out


def test_default_formats_round_trip(tmp_path, cube):
    written = pdr.write(tmp_path / "sub" / "cube", cube["points"], cube["tets"], cube["faces"],
                        face_markers=cube["face_markers"])
    assert sorted(written) == sorted(str(tmp_path / "sub" / f"cube.{e}")
                                     for e in ("node", "ele", "face", "vtu"))
    assert sorted(os.listdir(tmp_path / "sub")) == ["cube.ele", "cube.face", "cube.node",
                                                    "cube.vtu"]   # no temporaries left
    for path in (tmp_path / "sub" / "cube", tmp_path / "sub" / "cube.vtu"):
        back = pdr.read(path)
        assert back["kind"] == "mesh" and back["source"] == str(path)
        np.testing.assert_array_equal(back["points"], cube["points"])
        np.testing.assert_array_equal(back["tets"], cube["tets"])
        assert face_set(back["faces"]) == face_set(cube["faces"])
    np.testing.assert_array_equal(pdr.read(tmp_path / "sub" / "cube")["face_markers"],
                                  cube["face_markers"])


@pytest.mark.parametrize("ext", ["node", "vtu", "msh", "mesh"])
def test_each_format_by_extension(tmp_path, cube, ext):
    written = pdr.write(str(tmp_path / f"c.{ext}"), cube["points"], cube["tets"], cube["faces"])
    assert str(tmp_path / f"c.{ext}") in written
    back = pdr.read(tmp_path / f"c.{ext}")
    assert back["kind"] == "mesh"
    np.testing.assert_array_equal(back["points"], cube["points"])
    np.testing.assert_array_equal(back["tets"], cube["tets"])
    assert face_set(back["faces"]) == face_set(cube["faces"])
    assert pdr.check(back["points"], back["tets"], back["faces"],
                     domain=(CUBE_POINTS, CUBE_FACETS))["ok"]


def test_formats_as_a_string(tmp_path, cube):
    written = pdr.write(tmp_path / "c", cube["points"], cube["tets"], formats="msh,mesh")
    assert sorted(written) == [str(tmp_path / "c.mesh"), str(tmp_path / "c.msh")]


def test_rejected_mesh_writes_nothing(tmp_path, cube):
    tets = cube["tets"].copy()
    tets[0, 0] = len(cube["points"])   # out of range: the writer refuses the mesh
    with pytest.raises(ValueError):
        pdr.write(tmp_path / "bad", cube["points"], tets)
    assert os.listdir(tmp_path) == []


def test_read_domain():
    d = pdr.read(DATA_DIR / "cube-in-cube.poly")
    assert d["kind"] == "domain"
    assert d["points"].shape == (16, 3)
    assert len(d["facets"]) == 12
    assert d["facets"][0] == {"polygons": [[0, 1, 2, 3]], "holes": d["facets"][0]["holes"],
                              "marker": 1}
    assert d["facets"][0]["holes"].shape == (0, 3)
    assert [f["marker"] for f in d["facets"]] == [1] * 6 + [2] * 6
    np.testing.assert_array_equal(d["holes"], [[5, 5, 5]])
    with pytest.raises(ValueError, match="kind"):
        pdr.read(DATA_DIR / "cube-in-cube.poly", kind="surface")


def test_read_node_alone_is_a_point_set(tmp_path, cube):
    pdr.write(tmp_path / "c", cube["points"], cube["tets"], formats=["node"])
    assert pdr.read(tmp_path / "c.node")["kind"] == "mesh"       # c.ele beside it
    os.remove(tmp_path / "c.ele")
    d = pdr.read(tmp_path / "c.node")
    assert d["kind"] == "domain" and d["facets"] == []
    np.testing.assert_array_equal(d["points"], cube["points"])
