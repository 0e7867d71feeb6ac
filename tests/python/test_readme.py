"""The README's Python examples run as written (section "## Python"): the cube, then the
check of a `tetgen -pq1.4a0.1` mesh in a folder holding cube-in-cube.poly."""
import os
import pathlib
import re
import shutil
import subprocess

import pytest

from conftest import DATA_DIR

README = pathlib.Path(__file__).resolve().parents[2] / "README.md"


def python_blocks():
    text = README.read_text()
    section = text.split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"```python\n(.*?)```", section, re.S)


def test_two_examples():
    assert len(python_blocks()) == 2


def test_cube_example():
    exec(python_blocks()[0], {})


def test_tetgen_example(tmp_path, monkeypatch, capsys):
    if shutil.which("tetgen") is None:
        pytest.skip("tetgen is not installed (scripts/install-deps.sh --tests)")
    shutil.copy(DATA_DIR / "cube-in-cube.poly", tmp_path)
    subprocess.run(["tetgen", "-pq1.4a0.1", "cube-in-cube.poly"], cwd=tmp_path, check=True,
                   capture_output=True)
    monkeypatch.chdir(tmp_path)
    exec(python_blocks()[1], {})
    ok, _, failed = capsys.readouterr().out.partition(" ")
    assert ok in ("True", "False") and failed.startswith("[")
    assert os.path.exists("cube-in-cube.1.ele")
