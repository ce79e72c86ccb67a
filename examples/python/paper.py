"""The paper's benchmark from Python: the strip of examples/paper.toml as a dict, solved, and its
results written as the tool writes them.

    python3 examples/python/paper.py [OUTPUT_FOLDER]
"""
import sys

import signorini

problem = signorini.Problem({
    "units": "m-MPa",
    "mesh": {"type": "rectangle", "length": 3.0, "height": 1.0, "nx": 60, "ny": 20},
    "material": {"E": 21.19e4, "nu": 0.277, "plane_model": "plane_strain"},
    "clamp": [{"boundary": "left"}],
    "traction": [{"boundary": "right", "p": ["0", "1"]},
                 {"boundary": "top", "p": ["0", "-2/3*(3 - x)"]}],
    "contact": {"boundary": "bottom", "gap": "0"},
    "solver": {"r": 1e8, "uzawa_tolerance": 1e-8, "gnm_tolerance": 1e-10},
})
result = signorini.solve(problem, output=sys.argv[1] if len(sys.argv) > 1 else None)
print(f"{result.iterations} Uzawa steps, M(u*, l*) = {result.summary['M']:.7e} "
      f"(paper: -6.700472e-05), peak pressure {result.pressure.max():.4f} MPa")
