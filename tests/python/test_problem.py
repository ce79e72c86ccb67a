"""Problems from a file or a dict: the same reader, checks and messages as the tool's."""

import subprocess
import tomllib

import numpy as np
import pytest

import signorini


def test_a_dict_with_the_file_keys_solves_to_the_same_bits(examples):
    with open(examples / "paper.toml", "rb") as f:
        keys = tomllib.load(f)
    keys["mesh"].update(nx=60, ny=20)
    from_dict = signorini.solve(signorini.Problem(keys))
    from_file = signorini.solve(signorini.Problem(examples / "paper.toml",
                                                  overrides={"mesh.nx": 60, "mesh.ny": 20}))
    np.testing.assert_array_equal(from_dict.u, from_file.u)
    np.testing.assert_array_equal(from_dict.pressure, from_file.pressure)
    assert from_dict.summary["M"] == pytest.approx(-6.700472e-05, abs=1e-11)


def test_overrides_as_strings_or_a_dict_are_the_same(examples):
    a = signorini.Problem(examples / "paper.toml", overrides=["mesh.nx=60", "mesh.ny=20",
                                                              "solver.r=2.5e7"])
    b = signorini.Problem(examples / "paper.toml",
                          overrides={"mesh.nx": 60, "mesh.ny": 20, "solver.r": 2.5e7})
    assert a.settings == b.settings
    assert "r = 25000000.0" in a.settings or "r = 2.5e7" in a.settings or "2.5e+07" in a.settings


def tool_error(tool, problem_path, *overrides):
    args = [tool, "check", str(problem_path)]
    for o in overrides:
        args += ["--set", o]
    run = subprocess.run(args, capture_output=True, text=True)
    assert run.returncode == 2, run.stderr
    return run.stderr.strip().removeprefix("signorini: error: ")


@pytest.mark.parametrize("override,words", [
    ("material.E=-1.0", "material.E"),
    ("material.nu=0.5", "material.nu"),
    ("mesh.nxx=3", "unknown key 'mesh.nxx' (did you mean 'mesh.nx'?)"),
    ("solver.method=\"newton\"", "solver.method"),
])
def test_bad_input_raises_input_error_with_the_tools_message(examples, tool, override, words):
    with pytest.raises(signorini.InputError) as e:
        signorini.Problem(examples / "paper.toml", overrides=[override])
    assert words in str(e.value)
    assert "\n" not in str(e.value)
    assert str(e.value) in tool_error(tool, examples / "paper.toml", override)
    assert isinstance(e.value, ValueError)


def test_bad_dicts_name_the_key():
    base = {"mesh": {"type": "rectangle", "length": 1.0, "height": 1.0, "nx": 4, "ny": 4},
            "material": {"E": 1.0, "nu": 0.3}, "clamp": [{"boundary": "left"}],
            "contact": {"boundary": "bottom"}}
    signorini.Problem(base)  # valid
    with pytest.raises(signorini.InputError, match=r"problem dict: key 'material.E' is None"):
        signorini.Problem({**base, "material": {"E": None, "nu": 0.3}})
    with pytest.raises(signorini.InputError, match=r"key 'material.E' must be a number"):
        signorini.Problem({**base, "material": {"E": "stiff", "nu": 0.3}})
    with pytest.raises(signorini.InputError, match=r"unknown key 'materail'"):
        signorini.Problem({**base, "materail": {}})
    with pytest.raises(signorini.InputError, match=r"key 'mesh.nx' is a object|is a object"):
        signorini.Problem({**base, "mesh": {**base["mesh"], "nx": object()}})
    with pytest.raises(signorini.InputError, match=r"cannot read 'no/such.toml'"):
        signorini.Problem("no/such.toml")
    # numpy scalars and arrays are numbers and lists
    p = signorini.Problem({**base, "material": {"E": np.float64(2.0), "nu": np.float32(0.25)},
                           "mesh": {**base["mesh"], "nx": np.int64(4)},
                           "body_force": {"f": np.array(["0", "-1"])}})
    assert "E = 2.0" in p.settings


def test_model_errors_name_the_problem(examples):
    problem = signorini.Problem(examples / "paper.toml",
                                overrides={"mesh.nx": 6, "mesh.ny": 2,
                                           "clamp.0.boundary": "nowhere"})
    with pytest.raises(signorini.InputError, match=r"paper.toml: .*nowhere"):
        signorini.Model(problem)
