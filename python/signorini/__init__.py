"""signorini: contact problems of linear elasticity from Python.

An elastic body pressed against a rigid obstacle (the Signorini problem), solved by the
modified-Lagrangian Uzawa method with the generalised Newton method (and semismooth Newton,
classical Uzawa), in 2D and 3D, frictionless or with Tresca or Coulomb friction. The same
library as the command-line tool `signorini`, with numpy arrays in and out::

    import signorini
    problem = signorini.Problem("examples/paper.toml", overrides={"mesh.nx": 60, "mesh.ny": 20})
    result = signorini.solve(problem, output="results/paper")
    print(result.iterations, result.energy, result.pressure.max())

Classes: Problem (a problem file or a dict with its keys), Mesh (numpy arrays, a Gmsh file or a
meshio.Mesh), Model (the discrete problem), Solver (set up once, solve many times), Result.
Errors: InputError (a ValueError), NumericalError and ConvergenceError (RuntimeErrors). See
docs/python.md.
"""

from ._signorini import (
    ConvergenceError,
    InputError,
    Mesh,
    Model,
    NumericalError,
    Problem,
    Result,
    Solver,
    __version__,
    solve,
)
from ._meshio import from_meshio

Mesh.from_meshio = staticmethod(from_meshio)

__all__ = [
    "ConvergenceError",
    "InputError",
    "Mesh",
    "Model",
    "NumericalError",
    "Problem",
    "Result",
    "Solver",
    "__version__",
    "from_meshio",
    "solve",
]
