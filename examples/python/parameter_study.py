"""A parameter study: the contact force and the contact length of the paper's strip against the
load, with one solver set up once and each solve warm-started from the last. Plots them with
matplotlib.

    python3 examples/python/parameter_study.py [FIGURE.png] [STEPS]
"""
import sys

import numpy as np

import signorini

figure = sys.argv[1] if len(sys.argv) > 1 else "parameter_study.png"
steps = int(sys.argv[2]) if len(sys.argv) > 2 else 40

problem = signorini.Problem("examples/paper.toml",
                            overrides={"mesh.nx": 60, "mesh.ny": 20, "solver.r": 1e8})
model = signorini.Model(problem)          # mesh, stiffness, contact set: once
solver = signorini.Solver(model)          # the condensation factorised: once
h = 3.0 / 60                              # the contact nodes' spacing

factors = np.linspace(0.05, 2.0, steps)
force, length = [], []
previous = None
for t in factors:
    solver.set_load_factor(t)             # loads times t
    if previous is not None:
        solver.warm_start(previous)
    previous = solver.solve()
    force.append(previous.contact_force)
    length.append(h * np.count_nonzero(previous.pressure > 0))

import matplotlib  # noqa: E402  (after the solves: only the plot needs it)

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(factors, force, "o-", ms=3, label="contact force (MN/m)")
ax.set_xlabel("load factor")
ax.set_ylabel("contact force (MN per m)")
ax2 = ax.twinx()
ax2.plot(factors, length, "s--", ms=3, color="tab:red", label="contact length (m)")
ax2.set_ylabel("contact length (m)")
fig.legend(loc="upper left", bbox_to_anchor=(0.12, 0.88))
fig.tight_layout()
fig.savefig(figure, dpi=120)
print(f"{len(factors)} solves; force {force[0]:.4g} .. {force[-1]:.4g} MN/m; figure {figure}")
