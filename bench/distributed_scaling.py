#!/usr/bin/env python3
"""The distributed path against the serial tool on one problem, in one run (docs/distributed.md,
"Measured"): the whole process from the shell, with its peak memory, for

  - the serial tool (its own threads, and one thread: OMP_NUM_THREADS=1),
  - the PETSc path on 1 rank (solver.distributed = "petsc"; its threads, and one thread) and on
    2 ranks (mpirun -n 2; one thread each on two cores),

with the Uzawa and CG counts and the energies, which must agree. Two problems:

  python3 bench/distributed_scaling.py box N     # examples/box_on_sphere.toml, N x N x N/2 hex8
  python3 bench/distributed_scaling.py hertz S   # examples/hertz_sphere.toml on a gmsh mesh of
                                                 # hertz_sphere.geo at -clscale S (0.185: about
                                                 # a million unknowns; needs the gmsh program)

--repeats R keeps the best of R runs of each; --petsc-multigrid auto|gamg|aggregation chooses the
PETSc path's multigrid levels (solver.petsc_multigrid). SIGNORINI names the serial executable (default:
the release build; signorini-mpi must be beside it)."""

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


def run(cmd, env=None):
    """Runs cmd under /usr/bin/time; returns (wall seconds, peak MB of the largest process)."""
    full = ["/usr/bin/time", "-f", "TIME %e %M"] + cmd
    p = subprocess.run(full, capture_output=True, text=True, env=env)
    if p.returncode != 0:
        sys.exit(f"distributed_scaling.py: {' '.join(cmd)} failed:\n{p.stderr[-2000:]}")
    m = re.search(r"TIME ([0-9.]+) ([0-9]+)", p.stderr)
    return float(m.group(1)), int(m.group(2)) / 1024.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("problem", choices=["box", "hertz"])
    ap.add_argument("size", type=float, help="N for box, -clscale for hertz")
    ap.add_argument("--repeats", type=int, default=1)
    ap.add_argument("--petsc-multigrid", choices=["auto", "gamg", "aggregation"],
                    help="solver.petsc_multigrid of the PETSc path (default: the problem's)")
    args = ap.parse_args()
    exe = pathlib.Path(os.environ.get("SIGNORINI", ROOT / "build/release/app/signorini"))
    mpirun = shutil.which("mpirun")
    if mpirun is None or not (exe.parent / "signorini-mpi").exists():
        sys.exit("distributed_scaling.py: needs mpirun and a build with PETSc (signorini-mpi)")
    work = pathlib.Path(tempfile.mkdtemp())
    try:
        if args.problem == "box":
            n = int(args.size)
            problem = ROOT / "examples/box_on_sphere.toml"
            sets = ["--set", f"mesh.nx={n}", "--set", f"mesh.ny={n}", "--set", f"mesh.nz={n // 2}",
                    "--set", 'mesh.cell="hex8"']
        else:
            if shutil.which("gmsh") is None:
                sys.exit("distributed_scaling.py: needs the gmsh program (apt-get install gmsh)")
            mesh = work / "hertz_sphere.msh"
            subprocess.run(["gmsh", "-3", str(ROOT / "examples/gmsh/hertz_sphere.geo"), "-clscale",
                            str(args.size), "-format", "msh41", "-bin", "-o", str(mesh), "-v", "1"],
                           check=True)
            problem = ROOT / "examples/hertz_sphere.toml"
            sets = ["--set", f'mesh.file="{mesh}"']
        base = ["solve", str(problem), "-q"] + sets
        if args.petsc_multigrid:  # (the serial tool reads the key and has no use for it)
            base += ["--set", f'solver.petsc_multigrid="{args.petsc_multigrid}"']
        petsc = ["--set", 'solver.distributed="petsc"']
        runs = [
            ("serial tool", [str(exe)] + base, None, ""),
            ("serial tool, 1 thread", [str(exe)] + base, {"OMP_NUM_THREADS": "1"}, ""),
            ("PETSc path, 1 rank", [str(exe.parent / "signorini-mpi")] + base + petsc, None, ""),
            ("PETSc path, 1 rank, 1 thread", [str(exe.parent / "signorini-mpi")] + base + petsc,
             {"OMP_NUM_THREADS": "1"}, ""),
            ("PETSc path, 2 ranks", [mpirun, "--allow-run-as-root", "--oversubscribe", "-n", "2",
                                     str(exe)] + base, None, "per process"),
        ]
        rows = []
        for name, cmd, extra, note in runs:
            out = work / re.sub(r"[^a-z0-9]+", "_", name)
            env = dict(os.environ, **extra) if extra else None
            best = None
            for _ in range(args.repeats):
                wall, mb = run(cmd + ["-o", str(out)], env)
                if best is None or wall < best[0]:
                    best = (wall, mb)
            s = json.loads((out / "summary.json").read_text())
            rows.append((name, best[0], best[1], note, s))
        unknowns = rows[0][4]["n_free_dofs"]
        mg = f", petsc_multigrid {args.petsc_multigrid}" if args.petsc_multigrid else ""
        print(f"{args.problem} {args.size:g}: {unknowns:,} unknowns, best of {args.repeats}{mg}\n")
        print("| run | whole process | peak memory | Uzawa steps | CG iterations | energy |")
        print("|---|---|---|---|---|---|")
        for name, wall, mb, note, s in rows:
            mem = f"{mb / 1024:.2f} GB" + (f" {note}" if note else "")
            print(f"| {name} | {wall:.2f} s | {mem} | {s['outer_iterations']} | "
                  f"{sum(s['linear_iterations'])} | {s['energy']!r} |")
        t = {name: wall for name, wall, *_ in rows}
        print()
        print(f"- 1 rank / serial tool: {t['PETSc path, 1 rank'] / t['serial tool']:.2f}; "
              f"/ serial tool on 1 thread: {t['PETSc path, 1 rank'] / t['serial tool, 1 thread']:.2f}")
        print(f"- 2 ranks / serial tool (both on the 2 cores): "
              f"{t['PETSc path, 2 ranks'] / t['serial tool']:.2f}")
        print(f"- 1 rank on 1 thread / serial tool on 1 thread: "
              f"{t['PETSc path, 1 rank, 1 thread'] / t['serial tool, 1 thread']:.2f}")
        # One core against two: the one-thread rank (a rank's threads use the cores too).
        print(f"- strong scaling 1 -> 2 ranks (1 thread each): efficiency "
              f"{t['PETSc path, 1 rank, 1 thread'] / (2 * t['PETSc path, 2 ranks']):.2f}")
        energies = [s["energy"] for *_, s in rows]
        spread = (max(energies) - min(energies)) / abs(energies[0])
        print(f"- energies agree to {spread:.1e} (relative)")
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
