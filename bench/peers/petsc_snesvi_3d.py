#!/usr/bin/python3
"""A rigid ball pressed into an elastic block, solved by PETSc's SNESVI: the 3D peer.

Poses the discrete problem that `signorini solve examples/box_on_sphere.toml --set mesh.nx=N
--set mesh.ny=N --set mesh.nz=N/2 --set 'mesh.cell="hex8"'` solves (bench/peers/README.md states
it in full): the block (0,1) x (0,1) x (0,0.5) of N x N x N/2 trilinear (Q1) cubes, E = 1000,
nu = 0.3, 2 x 2 x 2 Gauss points; the top face z = 0.5 moved by (0, 0, -0.005) (its unknowns
eliminated, A_fD u_D taken to the right-hand side); the bottom face z = 0 against the rigid ball
of centre c = (0.5, 0.5, -4) and radius 4, each bottom node's constraint along the ball's normal
at its closest point, as the tool poses it against a rigid obstacle: u . nu <= |x - c| - 4 with
nu = (c - x) / |x - c|. SNESVI bounds single unknowns, so each bottom node's displacement is
written in an orthonormal frame whose first axis is nu (u = Q v, a reflection per node): the
constraint is the bound v_0 <= |x - c| - 4, the matrix Q^T A Q and the load Q^T b, the energy
unchanged. SNESVI's reduced-space active-set Newton method (vinewtonrsls) minimises
J = 1/2 v.(Q^T A Q)v - (Q^T b).v under these bounds; each iteration solves the matrix restricted
to the inactive unknowns.

    /usr/bin/python3 bench/peers/petsc_snesvi_3d.py --n 24
    /usr/bin/python3 bench/peers/petsc_snesvi_3d.py --n 40 --config gamg-reduced --json out.json

Arguments that start with '-' and are not ours go to PETSc. Exit status: 0 converged, 2 bad
arguments or petsc4py/numpy missing, 3 not converged, 1 anything else.
"""

import time

T_START = time.perf_counter()

import argparse  # noqa: E402
import os  # noqa: E402
import sys  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from petsc_snesvi import (energy_of, fail, isolate_mpi, make_snes, outcome,  # noqa: E402
                          phase_seconds, print_outcome, reduced_rows, set_options,
                          solve_from_zero, write_json)

YOUNG, POISSON = 1000.0, 0.3
PUSH = -0.005                      # the top face's displacement along z
CENTRE, RADIUS = (0.5, 0.5, -4.0), 4.0

CONFIGS = {
    "mumps": (
        "sparse Cholesky by MUMPS on each reduced system (AMD ordering)",
        {"ksp_type": "preonly", "pc_type": "cholesky", "pc_factor_mat_solver_type": "mumps",
         "mat_mumps_icntl_7": "0"},
    ),
    "gamg": (
        "conjugate gradients preconditioned by GAMG (smoothed aggregation, the six rigid-body "
        "modes as near-null space) set up once on the full matrix and restricted to each "
        "reduced system",
        {"ksp_type": "cg", "ksp_rtol": "1e-12", "ksp_atol": "1e-300", "ksp_max_it": "5000",
         "pc_type": "python"},
    ),
    "gamg-reduced": (
        "conjugate gradients preconditioned by GAMG set up anew on each reduced system, the "
        "rigid-body modes of its unknowns as near-null space",
        {"ksp_type": "cg", "ksp_rtol": "1e-12", "ksp_atol": "1e-300", "ksp_max_it": "5000",
         "pc_type": "python"},
    ),
}
DEFAULT_CONFIG = "gamg"


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="A rigid ball pressed into a block (examples/box_on_sphere.toml, hex8 cells) "
        "by PETSc SNESVI.",
        epilog="Other arguments starting with '-' are PETSc options, e.g. -snes_monitor.")
    parser.add_argument("--n", type=int, default=24,
                        help="cells along x and y, n/2 along z (even; default 24)")
    parser.add_argument("--config", default=DEFAULT_CONFIG, choices=sorted(CONFIGS),
                        help=f"solver configuration (default {DEFAULT_CONFIG})")
    parser.add_argument("--json", metavar="FILE", help="also write the results as JSON here")
    parser.add_argument("--quiet", action="store_true", help="print nothing but errors")
    args, petsc_args = parser.parse_known_args(argv)
    for a in petsc_args:
        if a.startswith("--"):
            parser.error(f"unrecognised argument {a} (PETSc options take a single dash)")
    if args.n < 2 or args.n % 2:
        parser.error("--n must be even and at least 2")
    return args, petsc_args


def element_stiffness(np, h):
    """The 24 x 24 Q1 stiffness of an h x h x h cube, 2 x 2 x 2 Gauss points; local node
    (a, b, c) in {0, 1}^3 is number a + 2 b + 4 c, dofs (x, y, z) per node."""
    lam = YOUNG * POISSON / ((1.0 + POISSON) * (1.0 - 2.0 * POISSON))
    mu = YOUNG / (2.0 * (1.0 + POISSON))
    d = np.zeros((6, 6))
    d[:3, :3] = lam
    d[np.arange(3), np.arange(3)] += 2.0 * mu
    d[np.arange(3, 6), np.arange(3, 6)] = mu
    corners = np.array([(a, b, c) for c in (0, 1) for b in (0, 1) for a in (0, 1)], float)
    s = 2.0 * corners - 1.0  # reference coordinates of the corners
    g = 1.0 / np.sqrt(3.0)
    ke = np.zeros((24, 24))
    for p in (-g, g):
        for q in (-g, g):
            for r in (-g, g):
                f = 1.0 + s * np.array([p, q, r])  # (8, 3): 1 + s_i xi_i per direction
                grad = np.empty((8, 3))
                grad[:, 0] = s[:, 0] * f[:, 1] * f[:, 2] / 8.0 * (2.0 / h)
                grad[:, 1] = s[:, 1] * f[:, 0] * f[:, 2] / 8.0 * (2.0 / h)
                grad[:, 2] = s[:, 2] * f[:, 0] * f[:, 1] / 8.0 * (2.0 / h)
                b = np.zeros((6, 24))
                for k in range(3):
                    b[k, k::3] = grad[:, k]
                b[3, 0::3], b[3, 1::3] = grad[:, 1], grad[:, 0]  # gamma_xy
                b[4, 1::3], b[4, 2::3] = grad[:, 2], grad[:, 1]  # gamma_yz
                b[5, 0::3], b[5, 2::3] = grad[:, 2], grad[:, 0]  # gamma_xz
                ke += b.T @ d @ b * (h ** 3 / 8.0)
    return ke


def stiffness_csr(np, n, nz, ke, int_type):
    """A over every node in CSR. Node (i, j, k) is number (k (n+1) + j) (n+1) + i, dofs 3 id + c.
    Every cell has the same ke: the entries are summed per node and neighbour offset with array
    slices, as in the 2D peer."""
    m = n + 1
    # v[k, j, i, dk+1, dj+1, di+1, a, b]: node (i, j, k) component a with node (i+di, j+dj, k+dk)
    # component b.
    v = np.zeros((nz + 1, m, m, 3, 3, 3, 3, 3))
    local = [(a, b, c) for c in (0, 1) for b in (0, 1) for a in (0, 1)]
    for p, (pi, pj, pk) in enumerate(local):
        for q, (qi, qj, qk) in enumerate(local):
            v[pk:pk + nz, pj:pj + n, pi:pi + n, qk - pk + 1, qj - pj + 1, qi - pi + 1] += \
                ke[3 * p:3 * p + 3, 3 * q:3 * q + 3]
    k, j, i = np.meshgrid(np.arange(nz + 1), np.arange(m), np.arange(m), indexing="ij")
    off = np.arange(-1, 2)
    kk = k[..., None, None, None] + off[:, None, None]
    jj = j[..., None, None, None] + off[None, :, None]
    ii = i[..., None, None, None] + off[None, None, :]
    exists = (kk >= 0) & (kk <= nz) & (jj >= 0) & (jj < m) & (ii >= 0) & (ii < m)
    nodes = (nz + 1) * m * m
    shape = (nz + 1, m, m, 3, 3, 3, 3, 3)  # row node, component a, offsets, component b
    values = np.ascontiguousarray(v.transpose(0, 1, 2, 6, 3, 4, 5, 7)).reshape(3 * nodes, 81)
    column_node = (kk * m + jj) * m + ii
    columns = 3 * column_node[:, :, :, None, :, :, :, None] + np.arange(3)
    columns = np.broadcast_to(columns, shape).reshape(3 * nodes, 81)
    mask = np.broadcast_to(exists[:, :, :, None, :, :, :, None], shape).reshape(3 * nodes, 81)
    indptr = np.zeros(3 * nodes + 1, dtype=int_type)
    np.cumsum(mask.sum(axis=1), out=indptr[1:])
    return indptr, columns[mask].astype(int_type), values[mask]


def main(argv):
    args, petsc_args = parse_arguments(argv)
    config = args.config
    isolate_mpi()
    try:
        import numpy as np
        import petsc4py
        petsc4py.init([sys.argv[0]] + petsc_args)
        from petsc4py import PETSc
    except ImportError as e:
        return fail(2, f"{e.name} is not importable by {sys.executable}: apt-get install "
                    "python3-numpy python3-petsc4py (and run the script with /usr/bin/python3)")
    t_import = time.perf_counter()

    n, nz = args.n, args.n // 2
    h = 1.0 / n
    m = n + 1
    description, config_options = CONFIGS[config]
    effective = set_options(PETSc, config_options)

    # A over all nodes; the top layer k = nz is prescribed and eliminated.
    indptr, indices, values = stiffness_csr(np, n, nz, element_stiffness(np, h), PETSc.IntType)
    n_all = indptr.size - 1
    full = PETSc.Mat().createAIJWithArrays(size=(n_all, n_all), csr=(indptr, indices, values),
                                           comm=PETSc.COMM_SELF)
    full.assemble()
    n_free = 3 * nz * m * m  # the free nodes come first in this numbering
    prescribed = full.createVecRight()
    prescribed.getArray()[n_free + 2::3] = PUSH  # u_z of the top layer
    lifted = full.createVecLeft()
    full.mult(prescribed, lifted)
    free = PETSc.IS().createStride(n_free, 0, 1, comm=PETSc.COMM_SELF)
    a = full.createSubMatrix(free, free)
    a.setBlockSize(3)
    a.setOption(PETSc.Mat.Option.SYMMETRIC, True)
    a.setOption(PETSc.Mat.Option.SPD, True)
    b = a.createVecLeft()
    b.setArray(-lifted.getArray(readonly=True)[:n_free])
    del full, indptr, indices, values

    # The bottom nodes k = 0 (the first m * m nodes): nu towards the ball's centre, the gap their
    # distance from the sphere, and the reflection Q_k = I - 2 w w^T / (w.w), w = nu - e_1, that
    # maps e_1 to nu; Q is the identity at the other nodes, and symmetric, so Q^T A Q = PtAP.
    jj, ii = np.meshgrid(np.arange(m), np.arange(m), indexing="ij")
    to_node = np.stack([(ii * h - CENTRE[0]).ravel(), (jj * h - CENTRE[1]).ravel(),
                        np.full(m * m, -CENTRE[2])], axis=1)
    distance = np.linalg.norm(to_node, axis=1)
    nu = -to_node / distance[:, None]
    w = nu - np.array([1.0, 0.0, 0.0])
    blocks = np.eye(3)[None] - 2.0 * w[:, :, None] * w[:, None, :] / (w * w).sum(axis=1)[:, None,
                                                                                           None]
    q = PETSc.Mat().createAIJ(size=(n_free, n_free), nnz=3, comm=PETSc.COMM_SELF)
    for k in range(m * m):
        rows = np.arange(3 * k, 3 * k + 3, dtype=PETSc.IntType)
        q.setValues(rows, rows, blocks[k].ravel())
    for i in range(3 * m * m, n_free):
        q.setValue(i, i, 1.0)
    q.assemble()
    rotated = a.PtAP(q)
    rotated.setBlockSize(3)
    rotated.setOption(PETSc.Mat.Option.SYMMETRIC, True)
    rotated.setOption(PETSc.Mat.Option.SPD, True)
    b_rotated = rotated.createVecLeft()
    q.multTranspose(b, b_rotated)
    a, b = rotated, b_rotated
    # The bounds: v_0 <= gap at the bottom nodes.
    lower = a.createVecLeft()
    lower.set(PETSc.NINFINITY)
    upper = a.createVecLeft()
    upper.set(PETSc.INFINITY)
    upper.getArray()[0:3 * m * m:3] = distance - RADIUS
    t_assembly = time.perf_counter()

    snes = make_snes(PETSc, a, b, lower, upper)
    node = np.arange(n_free // 3)
    xyz = np.empty((n_free // 3, 3))
    xyz[:, 0] = (node % m) * h
    xyz[:, 1] = (node // m % m) * h
    xyz[:, 2] = (node // (m * m)) * h
    u, t_setup, t_solve = solve_from_zero(np, PETSc, snes, a, config, effective, xyz,
                                          lambda: GamgReduced3d(np, PETSc, snes, a, xyz))

    energy = energy_of(a, b, u)
    bottom = u.getArray(readonly=True)[0:3 * m * m:3]
    active = int(np.count_nonzero(bottom >= upper.getArray(readonly=True)[0:3 * m * m:3]))
    snes_outcome = outcome(PETSc, snes)
    reason, reason_name, its, lits = snes_outcome
    converged = reason > 0
    seconds = phase_seconds(T_START, t_import, t_assembly, t_setup, t_solve, time.perf_counter())
    if not args.quiet:
        print(f"petsc_snesvi_3d: mesh {n}x{n}x{nz}, {n_free} unknowns (top face eliminated), "
              f"{m * m} bounded (bottom u . nu <= gap); PETSc "
              f"{'.'.join(map(str, PETSc.Sys.getVersion()))}")
        print_outcome(config, effective, description, energy, active, m * m, snes_outcome,
                      seconds)
    if args.json:
        result = {
            "peer": "petsc_snesvi_3d", "mesh": f"{n}x{n}x{nz}", "n": n, "config": config,
            "description": description, "petsc_options": effective,
            "petsc_version": ".".join(map(str, PETSc.Sys.getVersion())),
            "n_unknowns": n_free, "n_bounded": m * m, "energy": energy, "active_nodes": active,
            "snes_iterations": its, "ksp_iterations": lits, "converged": converged,
            "reason": reason_name, "seconds": seconds,
        }
        write_json(args.json, result)
    return 0 if converged else 3


class GamgReduced3d:
    """--config gamg-reduced: GAMG set up anew on each reduced matrix, the six rigid-body modes
    restricted to its unknowns as the near-null space. GAMG options take the prefix -rigid_."""

    def __init__(self, np, PETSc, snes, full, xyz):
        self.np, self.PETSc, self.snes, self.full, self.xyz = np, PETSc, snes, full, xyz
        self.inner = None

    def setUp(self, pc):
        np, PETSc = self.np, self.PETSc
        a, p = pc.getOperators()
        n = p.getSize()[0]
        rows = reduced_rows(self.snes, n, self.full.getSize()[0])
        rows = np.arange(n) if rows is None else rows
        x = self.xyz[rows // 3]
        c = rows % 3
        modes = np.zeros((n, 6))
        for k in range(3):
            modes[c == k, k] = 1.0  # translations
        # rotations about z, x, y: (-y, x, 0), (0, -z, y), (z, 0, -x)
        modes[:, 3] = np.where(c == 0, -x[:, 1], np.where(c == 1, x[:, 0], 0.0))
        modes[:, 4] = np.where(c == 1, -x[:, 2], np.where(c == 2, x[:, 1], 0.0))
        modes[:, 5] = np.where(c == 0, x[:, 2], np.where(c == 2, -x[:, 0], 0.0))
        q, _ = np.linalg.qr(modes)
        vectors = []
        for k in range(6):
            v = p.createVecRight()
            v.setArray(q[:, k])
            vectors.append(v)
        p.setNearNullSpace(PETSc.NullSpace().create(vectors=vectors))
        if self.inner is not None:
            self.inner.destroy()
        self.inner = PETSc.PC().create(comm=pc.getComm())
        self.inner.setOptionsPrefix("rigid_")
        self.inner.setType("gamg")
        self.inner.setOperators(a, p)
        self.inner.setFromOptions()
        self.inner.setUp()

    def apply(self, pc, x, y):
        self.inner.apply(x, y)


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except KeyboardInterrupt:
        sys.exit(130)
    except OSError as e:
        sys.exit(fail(2, str(e)))
    except Exception as e:  # noqa: BLE001 (one line, like the tool's errors)
        sys.exit(fail(1, f"{type(e).__name__}: {e}"))
