#!/usr/bin/python3
"""The paper's contact problem solved by PETSc's SNESVI: a peer for `signorini bench --peers`.

Poses the discrete problem that `signorini solve examples/paper.toml --set mesh.nx=NX
--set mesh.ny=NY` solves (bench/peers/README.md states it in full): the strip (0,3) x (0,1),
NX x NY bilinear (Q1) cells, plane strain, E = 21.19e4, nu = 0.277, 2 x 2 Gauss points, clamped on
the left, traction (0, 1) on the right and (0, -2/3 (3 - x)) on top integrated consistently with
two Gauss points per edge, and u_y >= 0 at every movable node of the bottom edge (outward normal
(0, -1), gap 0). Minimising J(u) = 1/2 u.Au - b.u under these bounds is the complementarity
problem "F(u) = Au - b, u_y >= 0 on the bottom", which SNESVI solves with a reduced-space active
set Newton method (vinewtonrsls): each iteration solves A restricted to the inactive unknowns.

    /usr/bin/python3 bench/peers/petsc_snesvi.py --nx 480 --ny 160
    /usr/bin/python3 bench/peers/petsc_snesvi.py --nx 480 --ny 160 --config gamg --json out.json
    /usr/bin/python3 bench/peers/petsc_snesvi.py --nx 120 --ny 40 -snes_monitor -snes_vi_monitor

Arguments that start with '-' and are not ours go to PETSc (they override the configuration's
options). Exit status: 0 converged, 2 bad arguments or petsc4py/numpy missing, 3 not converged,
1 anything else. Needs numpy and petsc4py only (Debian: apt-get install python3-petsc4py).
"""

import time

T_START = time.perf_counter()

import argparse  # noqa: E402
import json  # noqa: E402
import os  # noqa: E402
import resource  # noqa: E402
import sys  # noqa: E402

LENGTH, HEIGHT = 3.0, 1.0
YOUNG, POISSON = 21.19e4, 0.277

# Each configuration: what it is, and its PETSc options (any of them can be overridden on the
# command line). All use the reduced-space method with a full Newton step projected onto the
# bounds ("basic" line search): on this quadratic problem the default backtracking search takes
# about twice the iterations (15 against 8 at 240x80). The tolerances keep the energy within
# 1e-10 relative of the exact minimiser of the discrete problem; the function norm stalls at
# about 1e-12 relative (rounding), so rtol = 1e-9 is the tightest that always terminates.
COMMON = {
    "snes_type": "vinewtonrsls",
    "snes_linesearch_type": "basic",
    "snes_rtol": "1e-9",
    "snes_atol": "1e-300",
    "snes_stol": "1e-300",
    "snes_max_it": "500",
}
CONFIGS = {
    "mumps": (
        "sparse Cholesky by MUMPS on each reduced system (AMD ordering)",
        {"ksp_type": "preonly", "pc_type": "cholesky", "pc_factor_mat_solver_type": "mumps",
         "mat_mumps_icntl_7": "0"},
    ),
    "cholmod": (
        "sparse Cholesky by CHOLMOD (SuiteSparse, through PETSc) on each reduced system",
        {"ksp_type": "preonly", "pc_type": "cholesky", "pc_factor_mat_solver_type": "cholmod"},
    ),
    "petsc": (
        "PETSc's own sparse Cholesky (not supernodal), AMD ordering",
        {"ksp_type": "preonly", "pc_type": "cholesky", "pc_factor_mat_solver_type": "petsc",
         "pc_factor_mat_ordering_type": "amd"},
    ),
    "gamg": (
        "conjugate gradients preconditioned by GAMG (smoothed aggregation, the rigid-body modes "
        "as near-null space) set up once on the full matrix and restricted to each reduced "
        "system",
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
DEFAULT_CONFIG = "mumps"
CONFIG_ALIASES = {"direct": "mumps"}


def fail(status, message):
    print(f"petsc_snesvi.py: error: {message}", file=sys.stderr)
    return status


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        description="The paper's Signorini problem (examples/paper.toml) by PETSc SNESVI.",
        epilog="Other arguments starting with '-' are PETSc options, e.g. -snes_monitor.")
    parser.add_argument("--nx", type=int, default=480, help="cells along x (default 480)")
    parser.add_argument("--ny", type=int, default=160, help="cells along y (default 160)")
    names = sorted(list(CONFIGS) + list(CONFIG_ALIASES))
    parser.add_argument("--config", default=DEFAULT_CONFIG, choices=names,
                        help=f"solver configuration (default {DEFAULT_CONFIG}; direct = "
                        f"{CONFIG_ALIASES['direct']})")
    parser.add_argument("--json", metavar="FILE", help="also write the results as JSON here")
    parser.add_argument("--quiet", action="store_true", help="print nothing but errors")
    args, petsc_args = parser.parse_known_args(argv)
    for a in petsc_args:
        if a.startswith("--"):
            parser.error(f"unrecognised argument {a} (PETSc options take a single dash)")
    if args.nx < 1 or args.ny < 1:
        parser.error("--nx and --ny must be positive")
    return args, petsc_args


def element_stiffness(np, hx, hy):
    """The 8 x 8 Q1 stiffness of an hx x hy cell, plane strain, 2 x 2 Gauss points; local nodes
    (0,0), (1,0), (1,1), (0,1), dofs (x, y) per node."""
    c = YOUNG / ((1.0 + POISSON) * (1.0 - 2.0 * POISSON))
    d = c * np.array([[1.0 - POISSON, POISSON, 0.0], [POISSON, 1.0 - POISSON, 0.0],
                      [0.0, 0.0, 0.5 - POISSON]])
    xi = np.array([-1.0, 1.0, 1.0, -1.0])
    eta = np.array([-1.0, -1.0, 1.0, 1.0])
    g = 1.0 / np.sqrt(3.0)
    ke = np.zeros((8, 8))
    for s in (-g, g):
        for t in (-g, g):
            dndx = 0.25 * xi * (1.0 + eta * t) * (2.0 / hx)
            dndy = 0.25 * eta * (1.0 + xi * s) * (2.0 / hy)
            b = np.zeros((3, 8))
            b[0, 0::2] = dndx
            b[1, 1::2] = dndy
            b[2, 0::2] = dndy
            b[2, 1::2] = dndx
            ke += b.T @ d @ b * (hx * hy / 4.0)
    return ke


def stiffness_csr(np, nx, ny, ke, int_type):
    """A in CSR on the free dofs. Free node k = j*nx + (i-1) for the node (i, j), i >= 1 (the
    left edge is clamped and eliminated); dofs 2k (x) and 2k+1 (y). Every cell has the same ke,
    so the entries are summed per node and neighbour offset with array slices, no sorting."""
    # v[j, i, dj+1, di+1, a, b]: the coupling of node (i, j), component a, with node
    # (i+di, j+dj), component b.
    v = np.zeros((ny + 1, nx + 1, 3, 3, 2, 2))
    local = [(0, 0), (1, 0), (1, 1), (0, 1)]
    for p, (pi, pj) in enumerate(local):
        for q, (qi, qj) in enumerate(local):
            v[pj:pj + ny, pi:pi + nx, qj - pj + 1, qi - pi + 1] += ke[2 * p:2 * p + 2,
                                                                       2 * q:2 * q + 2]
    v = v[:, 1:]
    j, i = np.meshgrid(np.arange(ny + 1), np.arange(1, nx + 1), indexing="ij")
    off = np.arange(-1, 2)
    jj = j[:, :, None, None] + off[None, None, :, None]
    ii = i[:, :, None, None] + off[None, None, None, :]
    exists = (jj >= 0) & (jj <= ny) & (ii >= 1) & (ii <= nx)
    nodes = (ny + 1) * nx
    shape = (ny + 1, nx, 2, 3, 3, 2)  # row node (j, i), component a, offsets, component b
    values = np.ascontiguousarray(v.transpose(0, 1, 4, 2, 3, 5)).reshape(2 * nodes, 18)
    columns = 2 * (jj * nx + ii - 1)[:, :, None, :, :, None] + np.arange(2)
    columns = np.broadcast_to(columns, shape).reshape(2 * nodes, 18)
    mask = np.broadcast_to(exists[:, :, None, :, :, None], shape).reshape(2 * nodes, 18)
    indptr = np.zeros(2 * nodes + 1, dtype=int_type)
    np.cumsum(mask.sum(axis=1), out=indptr[1:])
    return indptr, columns[mask].astype(int_type), values[mask]


def load_vector(np, nx, ny):
    """b: the tractions integrated with 2 Gauss points per boundary edge and linear shape
    functions, on the free dofs (the load on the clamped top-left node is dropped)."""
    b = np.zeros(2 * (ny + 1) * nx)
    hx, hy = LENGTH / nx, HEIGHT / ny
    g = 1.0 / np.sqrt(3.0)
    for s in (-g, g):
        t = 0.5 * (1.0 + s)  # position along the edge; weight 1/2 of its length
        # Right edge x = 3: edges (nx, j) - (nx, j+1), p = (0, 1).
        j = np.arange(ny)
        y_low, y_high = 2 * (j * nx + nx - 1) + 1, 2 * ((j + 1) * nx + nx - 1) + 1
        b[y_low] += (1.0 - t) * 1.0 * hy / 2.0
        b[y_high] += t * 1.0 * hy / 2.0
        # Top edge y = 1: edges (i, ny) - (i+1, ny), p = (0, -2/3 (3 - x)).
        i = np.arange(nx)
        py = -2.0 / 3.0 * (LENGTH - (i + t) * hx)
        left, right = ny * nx + i - 1, ny * nx + i
        free = i >= 1
        b[2 * left[free] + 1] += ((1.0 - t) * py * hx / 2.0)[free]
        b[2 * right + 1] += t * py * hx / 2.0
    return b


def reduced_rows(snes, n, n_full):
    """The unknowns of the reduced system that SNESVI hands to its KSP, as indices into the full
    vector (None: all of them)."""
    inactive = snes.getVIInactiveSet()
    rows = inactive.getIndices() if inactive is not None else None
    if rows is not None and len(rows) == n:
        return rows
    if n == n_full:
        return None
    raise RuntimeError("gamg: cannot tell which unknowns the reduced system holds")


class GamgOnce:
    """--config gamg, a PETSc python preconditioner for the reduced systems of SNESVI: GAMG set
    up once, on the full matrix A (block size 2, the rigid-body modes from
    MatNullSpaceCreateRigidBody as its near-null space), and applied to a reduced residual by
    padding it with zeros on the active unknowns and keeping the inactive part of the result.
    The reduced matrix is A without at most one row and column per contact node, so this stays a
    good (symmetric positive definite) preconditioner, and GAMG's set-up (aggregation, Galerkin
    products, eigenvalue estimates) is not repeated at each SNES iteration. GAMG options take
    the prefix -rigid_ (e.g. -rigid_pc_gamg_threshold 0.02)."""

    def __init__(self, PETSc, snes, full, coordinates):
        self.snes, self.full = snes, full
        full.setNearNullSpace(PETSc.NullSpace().createRigidBody(coordinates))
        self.inner = PETSc.PC().create(comm=full.getComm())
        self.inner.setOptionsPrefix("rigid_")
        self.inner.setType("gamg")
        self.inner.setOperators(full, full)
        self.inner.setFromOptions()
        self.inner.setUp()
        self.rows = None
        self.x_full, self.y_full = full.createVecRight(), full.createVecRight()

    def setUp(self, pc):
        self.rows = reduced_rows(self.snes, pc.getOperators()[1].getSize()[0],
                                 self.full.getSize()[0])

    def apply(self, pc, x, y):
        if self.rows is None:
            self.inner.apply(x, y)
            return
        padded = self.x_full.getArray()
        padded[:] = 0.0
        padded[self.rows] = x.getArray(readonly=True)
        self.inner.apply(self.x_full, self.y_full)
        y.getArray()[:] = self.y_full.getArray(readonly=True)[self.rows]


class GamgReduced:
    """--config gamg-reduced: GAMG set up anew on each reduced matrix, with the rigid-body modes
    restricted to its unknowns as the near-null space (the submatrix has lost the block size and
    the near-null space of A). GAMG options take the prefix -rigid_."""

    def __init__(self, np, PETSc, snes, full, xy):
        self.np, self.PETSc, self.snes, self.full, self.xy = np, PETSc, snes, full, xy
        self.inner = None

    def setUp(self, pc):
        np, PETSc = self.np, self.PETSc
        a, p = pc.getOperators()
        n = p.getSize()[0]
        rows = reduced_rows(self.snes, n, self.full.getSize()[0])
        rows = np.arange(n) if rows is None else rows
        node_xy = self.xy.reshape(-1, 2)[rows // 2]
        x_component = rows % 2 == 0
        modes = np.zeros((n, 3))
        modes[x_component, 0] = 1.0
        modes[~x_component, 1] = 1.0
        modes[:, 2] = np.where(x_component, -node_xy[:, 1], node_xy[:, 0])
        q, _ = np.linalg.qr(modes)  # MatNullSpace wants orthonormal vectors
        vectors = []
        for k in range(3):
            v = p.createVecRight()
            v.setArray(q[:, k])
            vectors.append(v)
        p.setNearNullSpace(PETSc.NullSpace().create(vectors=vectors))
        if self.inner is not None:
            self.inner.destroy()  # GAMG cannot change sizes, and the active set changed
        self.inner = PETSc.PC().create(comm=pc.getComm())
        self.inner.setOptionsPrefix("rigid_")
        self.inner.setType("gamg")
        self.inner.setOperators(a, p)
        self.inner.setFromOptions()
        self.inner.setUp()

    def apply(self, pc, x, y):
        self.inner.apply(x, y)


def isolate_mpi():
    """A single process: Open MPI then needs no launcher daemon and no network transports, which
    saves about half a second of MPI_Init (petsc4py initialises MPI). The caller's settings
    win."""
    os.environ.setdefault("OMPI_MCA_ess_singleton_isolated", "1")
    os.environ.setdefault("OMPI_MCA_btl", "self")
    os.environ.setdefault("OMPI_MCA_pml", "ob1")


def set_options(PETSc, config_options):
    """COMMON and the configuration's options, each unless the command line gave it; returns the
    options in effect."""
    options = PETSc.Options()
    effective = {}
    for key, value in list(COMMON.items()) + list(config_options.items()):
        if not options.hasName(key):
            options.setValue(key, value)
        effective[key] = options.getString(key)
    return effective


def make_snes(PETSc, a, b, lower, upper):
    """SNESVI on F(u) = A u - b under lower <= u <= upper (A constant: the Jacobian is A)."""
    snes = PETSc.SNES().create(comm=PETSc.COMM_SELF)

    def function(_snes, x, f):
        a.mult(x, f)
        f.axpy(-1.0, b)

    def jacobian(_snes, _x, _j, _p):
        pass  # A is constant; the reduced-space method never changes it

    snes.setFunction(function, a.createVecLeft())
    snes.setJacobian(jacobian, a, a)
    snes.setVariableBounds(lower, upper)
    return snes


def energy_of(a, b, u):
    """J(u) = 1/2 u.Au - b.u."""
    au = a.createVecLeft()
    a.mult(u, au)
    return 0.5 * au.dot(u) - b.dot(u)


def outcome(PETSc, snes):
    """(the converged reason, its name, SNES iterations, KSP iterations); converged: reason > 0."""
    reason = snes.getConvergedReason()
    names = {v: k for k, v in vars(PETSc.SNES.ConvergedReason).items() if isinstance(v, int)}
    return (reason, names.get(reason, str(reason)), snes.getIterationNumber(),
            snes.getLinearSolveIterations())


def write_json(path, result):
    """The result as JSON at path, written to a temporary name first and renamed."""
    result["peak_rss_bytes"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as out:
        json.dump(result, out, indent=2)
        out.write("\n")
    os.replace(tmp, path)


def solve_from_zero(np, PETSc, snes, a, config, effective, xyz, reduced_pc):
    """Installs the python preconditioner where the configuration asks for one (`gamg`: GAMG set
    up once on the full matrix, with the node coordinates `xyz`, one row per node; otherwise
    reduced_pc(), GAMG on each reduced matrix), then solves from u = 0. Returns u and the times
    before and after the solve."""
    if effective.get("pc_type") == "python":
        pc = snes.getKSP().getPC()
        pc.setType("python")
        if config == "gamg":
            # The vector keeps the array it wraps alive.
            coordinates = PETSc.Vec().createWithArray(np.ascontiguousarray(xyz).ravel(),
                                                      comm=PETSc.COMM_SELF)
            coordinates.setBlockSize(xyz.shape[1])
            pc.setPythonContext(GamgOnce(PETSc, snes, a, coordinates))
        else:
            pc.setPythonContext(reduced_pc())
    snes.setFromOptions()
    u = a.createVecLeft()
    u.set(0.0)
    t_setup = time.perf_counter()
    snes.solve(None, u)
    return u, t_setup, time.perf_counter()


def phase_seconds(t_start, t_import, t_assembly, t_setup, t_solve, t_end):
    """The phases of a run from the script's first line; the interpreter's own start-up comes on
    top."""
    return {
        "import": t_import - t_start,  # numpy, petsc4py and MPI_Init
        "assembly": t_assembly - t_import,
        "setup": t_setup - t_assembly,
        "solve": t_solve - t_setup,
        "post": t_end - t_solve,
        "total": t_end - t_start,
    }


def print_outcome(config, effective, description, energy, active, bounded, snes_outcome,
                  seconds):
    reason, reason_name, its, lits = snes_outcome
    print(f"config {config}: {effective['snes_type']}, {description}")
    print(f"J(u) = {energy:.11e}")
    print(f"active contact nodes: {active} of {bounded}")
    print(f"SNES iterations: {its}, KSP iterations: {lits}, {reason_name} ({reason})")
    print("seconds: " + ", ".join(f"{k} {v:.3f}" for k, v in seconds.items()))


def main(argv):
    args, petsc_args = parse_arguments(argv)
    config = CONFIG_ALIASES.get(args.config, args.config)
    isolate_mpi()
    hint = "" if sys.executable == "/usr/bin/python3" else \
        " (or run the script with /usr/bin/python3, which has the Debian packages)"
    try:
        import numpy as np
    except ImportError:
        return fail(2, f"numpy is not importable by {sys.executable}: apt-get install "
                    f"python3-numpy python3-petsc4py{hint}")
    try:
        import petsc4py
        petsc4py.init([sys.argv[0]] + petsc_args)
        from petsc4py import PETSc
    except ImportError:
        return fail(2, f"petsc4py is not importable by {sys.executable}: apt-get install "
                    f"python3-petsc4py{hint}")
    t_import = time.perf_counter()

    nx, ny = args.nx, args.ny
    description, config_options = CONFIGS[config]
    effective = set_options(PETSc, config_options)

    # Assembly: A on the free dofs, b, the bounds.
    hx, hy = LENGTH / nx, HEIGHT / ny
    indptr, indices, values = stiffness_csr(np, nx, ny, element_stiffness(np, hx, hy),
                                            PETSc.IntType)
    n = indptr.size - 1
    # The arrays become the matrix's own (no copy, no insertion): keep them alive with it.
    a = PETSc.Mat().createAIJWithArrays(size=(n, n), csr=(indptr, indices, values),
                                        comm=PETSc.COMM_SELF)
    a.setBlockSize(2)
    a.assemble()
    a.setOption(PETSc.Mat.Option.SYMMETRIC, True)
    a.setOption(PETSc.Mat.Option.SPD, True)
    b = a.createVecLeft()
    b.setArray(load_vector(np, nx, ny))
    lower = a.createVecLeft()
    lower.set(PETSc.NINFINITY)
    lower.getArray()[1:2 * nx:2] = 0.0  # u_y >= 0 at the bottom nodes (i, 0), i = 1..nx
    upper = a.createVecLeft()
    upper.set(PETSc.INFINITY)
    t_assembly = time.perf_counter()

    snes = make_snes(PETSc, a, b, lower, upper)
    node = np.arange(n // 2)
    xy = np.empty(n)  # node coordinates, x and y interleaved like the unknowns
    xy[0::2] = (node % nx + 1) * hx
    xy[1::2] = (node // nx) * hy
    u, t_setup, t_solve = solve_from_zero(np, PETSc, snes, a, config, effective,
                                          xy.reshape(-1, 2),
                                          lambda: GamgReduced(np, PETSc, snes, a, xy))

    energy = energy_of(a, b, u)
    uy_bottom = u.getArray(readonly=True)[1:2 * nx:2]
    active = int(np.count_nonzero(uy_bottom <= 0.0))
    snes_outcome = outcome(PETSc, snes)
    reason, reason_name, its, lits = snes_outcome
    converged = reason > 0
    seconds = phase_seconds(T_START, t_import, t_assembly, t_setup, t_solve, time.perf_counter())
    if not args.quiet:
        print(f"petsc_snesvi: mesh {nx}x{ny}, {n} unknowns (left edge eliminated), {nx} bounded "
              f"(bottom u_y >= 0); PETSc {'.'.join(map(str, PETSc.Sys.getVersion()))}")
        print_outcome(config, effective, description, energy, active, nx, snes_outcome, seconds)
    if args.json:
        result = {
            "peer": "petsc_snesvi",
            "mesh": f"{nx}x{ny}",
            "nx": nx,
            "ny": ny,
            "config": config,
            "description": description,
            "petsc_options": effective,
            "petsc_version": ".".join(map(str, PETSc.Sys.getVersion())),
            "n_unknowns": n,
            "n_bounded": nx,
            "energy": energy,
            "active_nodes": active,
            "snes_iterations": its,
            "ksp_iterations": lits,
            "converged": converged,
            "reason": reason_name,
            "seconds": seconds,
        }
        write_json(args.json, result)
    return 0 if converged else 3


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except KeyboardInterrupt:
        sys.exit(130)
    except OSError as e:
        sys.exit(fail(2, str(e)))
    except Exception as e:  # noqa: BLE001 (one line, like the tool's errors)
        sys.exit(fail(1, f"{type(e).__name__}: {e}"))
