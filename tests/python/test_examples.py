"""The Python examples (examples/python/) run and say what they should."""

import os
import subprocess
import sys

from conftest import SOURCE


def run(script, *args):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, str(SOURCE / "examples/python" / script), *args],
                          check=True, capture_output=True, text=True, cwd=SOURCE, env=env).stdout


def test_paper(tmp_path):
    out = run("paper.py", str(tmp_path / "paper"))
    assert "6 Uzawa steps, M(u*, l*) = -6.7004730e-05" in out
    assert (tmp_path / "paper" / "summary.json").exists()


def test_parameter_study(tmp_path):
    out = run("parameter_study.py", str(tmp_path / "study.png"), "12")
    assert out.startswith("12 solves")
    assert (tmp_path / "study.png").stat().st_size > 10000


def test_meshio_mesh(tmp_path):
    out = run("meshio_mesh.py", str(tmp_path / "ring"))
    assert "7 nodes in contact" in out
    assert (tmp_path / "ring" / "solution.vtu").exists()
