#!/usr/bin/env python3
"""What a distributed solve costs, measured at several sizes and rank counts, for the cost model
of docs/performance.md ("Distributed runs: measurements and a cost model").

For each size N of examples/box_on_sphere.toml (N x N x N/2 hex8 cells, CG with GAMG's levels
kept, the plan's choice; or with --problem hertz, examples/hertz_sphere.toml on gmsh meshes of
tetrahedra, sizes given as -clscale) and each rank count (1 rank: solver.distributed = "petsc"; more:
mpirun -n R, oversubscribed where R exceeds the cores), one run prints:

  - the whole process from the shell and the peak memory of the largest rank (/usr/bin/time
    around each rank),
  - the Uzawa steps, GNM iterations and CG iterations (summary.json),
  - PETSc's -log_view totals over the ranks: messages, bytes and reductions, and per GNM
    iteration and rank,

and, from the runs on the two largest rank counts, a fit of the memory per rank as
R + D / ranks: R held by every rank whatever the count, D shared among them.

  python3 bench/distributed_cost_model.py --sizes 24 40 64 88 --ranks 1 2 4
  python3 bench/distributed_cost_model.py --problem hertz --sizes 0.5 0.185 --ranks 1 2 4

Times on more ranks than cores measure the message counts and the memory, not the speed.
SIGNORINI names the serial executable (default: the release build; signorini-mpi beside it)."""

import argparse
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def number(pattern, text, column):
    """Column `column` (0: max per rank, 3: total) of a -log_view summary line."""
    m = re.search(pattern + r"\s+(.*)", text)
    if m is None:
        return None
    fields = m.group(1).split()
    return float(fields[column]) if column < len(fields) else None


def problem_of(kind, size, work):
    """The problem file and its --set options for one size."""
    if kind == "box":
        n = int(size)
        return ROOT / "examples/box_on_sphere.toml", [
            "--set", f"mesh.nx={n}", "--set", f"mesh.ny={n}", "--set", f"mesh.nz={n // 2}",
            "--set", 'mesh.cell="hex8"']
    if shutil.which("gmsh") is None:
        sys.exit("distributed_cost_model.py: --problem hertz needs the gmsh program")
    mesh = work / f"hertz_{size:g}.msh"
    subprocess.run(["gmsh", "-3", str(ROOT / "examples/gmsh/hertz_sphere.geo"), "-clscale",
                    str(size), "-format", "msh41", "-bin", "-o", str(mesh), "-v", "1"], check=True)
    return ROOT / "examples/hertz_sphere.toml", ["--set", f'mesh.file="{mesh}"']


def run(exe, mpirun, problem, sets, ranks, out):
    tool = [str(exe.parent / "signorini-mpi"), "solve", str(problem), "-q", "-o", str(out)] + sets
    # Each rank's /usr/bin/time writes a file of its own: on stderr the ranks' lines may be
    # interleaved by mpirun's forwarding.
    stamp = out.parent / f"{out.name}.time"
    timed = ["bash", "-c",
             'exec /usr/bin/time -f "%e %M" -o "$0.${OMPI_COMM_WORLD_RANK:-0}" "$@"', str(stamp)]
    if ranks == 1:
        cmd = timed + tool + ["--set", 'solver.distributed="petsc"']
    else:
        cmd = [mpirun, "--allow-run-as-root", "--oversubscribe", "-n", str(ranks)] + timed + tool
    env = dict(os.environ, PETSC_OPTIONS="-log_view")
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if p.returncode != 0:
        said = [l for l in (p.stdout + p.stderr).splitlines() if "signorini" in l]
        sys.exit(f"distributed_cost_model.py: {' '.join(cmd)} failed (status {p.returncode}):\n"
                 + "\n".join(said[-10:] or [p.stderr[-2000:]]))
    per_rank = []
    for r in range(ranks):
        t, k = pathlib.Path(f"{stamp}.{r}").read_text().split()[-2:]
        per_rank.append((float(t), int(k) / 1024.0))
    text = p.stdout + p.stderr
    s = json.loads((out / "summary.json").read_text())
    return {
        "ranks": ranks,
        "unknowns": s["n_free_dofs"],
        "wall": max(t for t, _ in per_rank),
        "peak_mb": max(m for _, m in per_rank),
        "uzawa": s["outer_iterations"],
        "gnm": sum(s["gnm_iterations"]),
        "cg": sum(s["linear_iterations"]),
        "energy": s["energy"],
        # (On one rank PETSc reports no messages.)
        "messages": number(r"MPI Msg Count:", text, 3) or 0.0,
        "bytes": number(r"MPI Msg Len \(bytes\):", text, 3) or 0.0,
        "reductions": number(r"MPI Reductions:", text, 0) or 0.0,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--problem", choices=["box", "hertz"], default="box",
                    help="box: examples/box_on_sphere.toml on N x N x N/2 hex8 cells (sizes: N); "
                         "hertz: examples/hertz_sphere.toml on a gmsh mesh of hertz_sphere.geo "
                         "(sizes: -clscale; 0.185 makes about a million unknowns)")
    ap.add_argument("--sizes", type=float, nargs="+", default=[24, 40, 64, 88])
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    args = ap.parse_args()
    exe = pathlib.Path(os.environ.get("SIGNORINI", ROOT / "build/release/app/signorini"))
    mpirun = shutil.which("mpirun")
    if mpirun is None or not (exe.parent / "signorini-mpi").exists():
        sys.exit("distributed_cost_model.py: needs mpirun and a build with PETSc (signorini-mpi)")
    work = pathlib.Path(tempfile.mkdtemp())
    try:
        print("| unknowns | ranks | whole process | peak per rank | Uzawa / GNM / CG | messages "
              "| bytes | reductions | per GNM iteration and rank: messages, bytes |")
        print("|---|---|---|---|---|---|---|---|---|")
        fits = []
        for n in args.sizes:
            problem, sets = problem_of(args.problem, n, work)
            rows = [run(exe, mpirun, problem, sets, r, work / f"out_{n:g}_{r}") for r in args.ranks]
            for row in rows:
                per = row["gnm"] * row["ranks"]
                print(f"| {row['unknowns']:,} | {row['ranks']} | {row['wall']:.2f} s "
                      f"| {row['peak_mb']:.0f} MB | {row['uzawa']} / {row['gnm']} / {row['cg']} "
                      f"| {row['messages']:,.0f} | {row['bytes'] / 1e6:.1f} MB "
                      f"| {row['reductions']:,.0f} "
                      f"| {row['messages'] / per:,.0f}, {row['bytes'] / per / 1e6:.2f} MB |")
            energies = [row["energy"] for row in rows]
            spread = (max(energies) - min(energies)) / abs(energies[0])
            if len(rows) >= 2:
                a, b = rows[-2], rows[-1]
                shared = (a["peak_mb"] - b["peak_mb"]) / (1 / a["ranks"] - 1 / b["ranks"])
                held = a["peak_mb"] - shared / a["ranks"]
                fits.append((rows[0]["unknowns"], held, shared, spread))
            else:
                fits.append((rows[0]["unknowns"], None, None, spread))
        print()
        for unknowns, held, shared, spread in fits:
            line = f"- {unknowns:,} unknowns: energies agree to {spread:.1e}"
            if held is not None:
                line += (f"; memory per rank {held:.0f} MB + {shared:.0f} MB / ranks "
                         f"({held * 1e3 / unknowns:.2f} KB per unknown of the problem on every "
                         f"rank, {shared * 1e3 / unknowns:.2f} KB per unknown shared)")
            print(line)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
