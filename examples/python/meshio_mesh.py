"""A mesh made outside signorini: a 2D ring segment built with numpy as a meshio.Mesh (the kind
of mesh meshio reads from any format, or Gmsh's Python API makes), pressed onto a rigid plane.

    python3 examples/python/meshio_mesh.py [OUTPUT_FOLDER]

The half-ring 0.5 <= r <= 1 below the x axis is clamped on its two ends and pushed down by
0.005 onto the plane y = -1 + 0.005 (its lowest point starts at y = -1).
"""
import sys

import meshio
import numpy as np

import signorini

nr, nt = 12, 240                     # cells across and along the ring
r = np.linspace(0.5, 1.0, nr + 1)
t = np.linspace(np.pi, 2 * np.pi, nt + 1)
R, T = np.meshgrid(r, t, indexing="ij")
points = np.column_stack([(R * np.cos(T)).ravel(), (R * np.sin(T)).ravel()])
node = np.arange(points.shape[0]).reshape(nr + 1, nt + 1)
quads = np.column_stack([node[:-1, :-1].ravel(), node[:-1, 1:].ravel(),
                         node[1:, 1:].ravel(), node[1:, :-1].ravel()])
outer = np.column_stack([node[-1, :-1], node[-1, 1:]])      # r = 1: the contact side
ends = np.vstack([np.column_stack([node[:-1, 0], node[1:, 0]]),
                  np.column_stack([node[:-1, -1], node[1:, -1]])])
mesh = meshio.Mesh(points, [("quad", quads), ("line", outer), ("line", ends)],
                   cell_sets={"outer": [np.array([], int), np.arange(len(outer)), np.array([], int)],
                              "ends": [np.array([], int), np.array([], int), np.arange(len(ends))]})

problem = signorini.Problem({
    "name": "ring",
    "material": {"E": 1000.0, "nu": 0.3, "plane_model": "plane_strain"},
    "clamp": [{"boundary": "ends"}],
    "contact": {"boundary": "outer", "obstacle": "plane", "point": [0.0, -1.0 + 0.005],
                "normal": [0.0, 1.0]},
}, mesh=signorini.Mesh.from_meshio(mesh))
result = signorini.solve(problem, output=sys.argv[1] if len(sys.argv) > 1 else None)
print(f"{result.num_active} nodes in contact, contact force {result.contact_force:.5g}, "
      f"peak pressure {result.pressure.max():.5g}")
