"""signorini.solve from Python equals `signorini solve` to the last bit: the same result files
(solution.vtu, contact.csv, contact.vtu byte for byte; summary.json equal but for the timings),
and the numpy arrays equal to the numbers of those files."""

import json
import subprocess

import numpy as np
import pytest

import signorini

# On the sparse direct path, factor_updates = "auto" chooses between updating the factor and
# factorising again by the times it measures (linalg/cholmod_solver.hpp), which vary with the
# machine's load: two runs of the tool itself may then differ in the last bits. "never" makes
# the comparison deterministic.
DETERMINISTIC = "solver.linear.factor_updates=\"never\""
CASES = [
    ("paper.toml", ["mesh.nx=60", "mesh.ny=20"]),
    ("paper.toml", ["mesh.nx=60", "mesh.ny=20", "solver.method=semismooth_newton"]),
    ("hertz_sphere.toml", [DETERMINISTIC]),
    ("cattaneo_mindlin.toml", [DETERMINISTIC]),
]


def without_timings(summary):
    summary = dict(summary)
    for key in ("timings", "peak_memory_bytes"):
        summary.pop(key, None)
    summary["load_steps"] = [{k: v for k, v in s.items() if k != "seconds"}
                             for s in summary.get("load_steps", [])]
    return summary


@pytest.mark.parametrize("problem,overrides", CASES)
def test_python_solve_equals_the_tool(tmp_path, examples, tool, problem, overrides):
    by_tool, by_python = tmp_path / "tool", tmp_path / "python"
    args = [tool, "solve", str(examples / problem), "-q", "-o", str(by_tool)]
    for o in overrides:
        args += ["--set", o]
    subprocess.run(args, check=True)
    result = signorini.solve(signorini.Problem(examples / problem, overrides=overrides),
                             output=by_python)
    for name in ("solution.vtu", "contact.csv", "contact.vtu"):
        assert (by_tool / name).read_bytes() == (by_python / name).read_bytes(), name
    if (by_tool / "steps").exists():
        for f in sorted((by_tool / "steps").iterdir()):
            assert f.read_bytes() == (by_python / "steps" / f.name).read_bytes(), f.name
    tool_summary = json.loads((by_tool / "summary.json").read_text())
    python_summary = json.loads((by_python / "summary.json").read_text())
    assert without_timings(tool_summary) == without_timings(python_summary)
    assert without_timings(result.summary) == without_timings(tool_summary)

    # The arrays against the tool's contact.csv (17 digits: exact).
    table = np.genfromtxt(by_tool / "contact.csv", delimiter=",", names=True, dtype=None,
                          encoding="utf-8")
    np.testing.assert_array_equal(result.pressure, table["pressure"])
    np.testing.assert_array_equal(result.contact["pressure"], table["pressure"])
    assert result.energy == tool_summary["energy"]
    assert result.iterations == tool_summary["uzawa_iterations"]
    assert result.converged and tool_summary["converged"]
