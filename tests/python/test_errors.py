"""Bad input raises a Python exception with the command line's message (what `pdr`
prints after "pdr: " with exit 2): pdr.InputError, a ValueError, with file and line."""
import numpy as np
import pytest

import pdr
from conftest import CUBE_FACETS, CUBE_POINTS, run_cli, write_poly


def cli_message(result):
    assert result.returncode == 2, (result.stdout, result.stderr)
    assert result.stderr.startswith("pdr: ")
    return result.stderr[len("pdr: "):].rstrip("\n")


def test_bad_poly_same_message_as_the_command(tmp_path, pdr_cli):
    poly = tmp_path / "bad.poly"
    write_poly(poly, CUBE_POINTS, CUBE_FACETS[:-1] + [[3, 0, 4, 9]])  # index 9 of 8
    expected = cli_message(run_cli(pdr_cli, "mesh", poly, "-o", tmp_path / "x"))
    with pytest.raises(pdr.InputError) as e:
        pdr.mesh(str(poly))
    assert str(e.value) == expected
    assert isinstance(e.value, ValueError)
    assert e.value.file == str(poly)
    assert expected.startswith(f"{poly}:{e.value.line}: polygon corner 9 is out of range")
    assert not (tmp_path / "x.node").exists()


def test_unreadable_mesh_same_message_as_the_command(tmp_path, pdr_cli):
    (tmp_path / "m.node").write_text("4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n")  # 3 of 4 points
    (tmp_path / "m.ele").write_text("1 4 0\n1 1 2 3 4\n")
    expected = cli_message(run_cli(pdr_cli, "check", tmp_path / "m"))
    with pytest.raises(pdr.InputError) as e:
        pdr.check(str(tmp_path / "m"))
    assert str(e.value) == expected
    with pytest.raises(pdr.InputError) as e:
        pdr.read(tmp_path / "m")
    assert str(e.value) == expected


def test_array_facet_index_out_of_range():
    facets = CUBE_FACETS[:1] + [[4, 5, 6, 99]] + CUBE_FACETS[2:]
    with pytest.raises(pdr.InputError) as e:
        pdr.mesh(CUBE_POINTS, facets)
    # facets[1] is line 2 of "<arrays>"; the text is domain validation's own.
    assert (e.value.file, e.value.line) == ("<arrays>", 2)
    assert str(e.value).startswith("<arrays>:2: index in range: polygon 1 of this facet uses "
                                   "vertex index 99 (0-based) but there are 8 vertices")


def test_array_duplicate_points():
    points = np.vstack([CUBE_POINTS, CUBE_POINTS[:1]])
    with pytest.raises(pdr.InputError, match=r"^<arrays>: distinct vertices: vertex 8 has the "
                       r"same coordinates as vertex 0"):
        pdr.mesh(points, CUBE_FACETS)


def test_open_boundary_is_input_error():
    with pytest.raises(pdr.InputError, match="closed"):
        pdr.mesh(CUBE_POINTS, CUBE_FACETS[:-1])


@pytest.mark.parametrize("call, message", [
    (lambda: pdr.mesh(CUBE_POINTS[:, :2], CUBE_FACETS),
     r"points: expected an array of shape \(N, 3\)"),
    (lambda: pdr.mesh(CUBE_POINTS, CUBE_FACETS, ratio=0.5), "ratio"),
    (lambda: pdr.mesh(CUBE_POINTS, CUBE_FACETS, max_volume=-1.0), "max_volume"),
    (lambda: pdr.check(CUBE_POINTS, [[0, 1, 2, 4.0]]), "tets: expected integer"),
    (lambda: pdr.check(CUBE_POINTS, [[0, 1, 2]]), r"tets: expected an array of shape \(M, 4\)"),
    (lambda: pdr.check(CUBE_POINTS, [[0, 1, 2, -1]]), r"tets\[0\] has vertex index -1"),
    (lambda: pdr.write("/tmp/never", CUBE_POINTS, [[0, 1, 2, 3]], formats=["obj"]),
     "--formats"),
])
def test_value_errors(call, message):
    with pytest.raises(ValueError, match=message):
        call()


def test_type_errors():
    with pytest.raises(TypeError, match=r"facets\[0\]"):
        pdr.mesh(CUBE_POINTS, [[0, 1.5, 2, 3]] + CUBE_FACETS[1:])
    with pytest.raises(TypeError, match="domain"):
        pdr.check(CUBE_POINTS, [[0, 1, 2, 4]], domain=42)


def test_missing_files(tmp_path, pdr_cli):
    missing = tmp_path / "nothing"
    expected = cli_message(run_cli(pdr_cli, "check", missing))
    with pytest.raises(pdr.InputError) as e:
        pdr.check(missing)
    assert str(e.value) == expected and "unknown mesh format" in expected
    with pytest.raises(pdr.InputError, match=r"nothing\.poly: cannot open file"):
        pdr.mesh(str(missing) + ".poly")
