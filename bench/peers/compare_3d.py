#!/usr/bin/python3
"""signorini against PETSc SNESVI on the same 3D discrete problem, in one run, each solve a
separate process timed from here (start-up, model, solve, output: what a user waits for).

    /usr/bin/python3 bench/peers/compare_3d.py --n 24 40 --config gamg gamg-reduced

For each n: `signorini solve examples/box_on_sphere.toml` on n x n x n/2 hex8 cells (the tool
chooses its path) and bench/peers/petsc_snesvi_3d.py with each configuration, best of
--repeats runs each; prints one Markdown row per solve with the whole-process seconds, the
peer's time over signorini's, the energies and their relative difference. Exit status 1 when a
solve fails or the energies differ by more than --energy-tolerance.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def timed(command):
    start = time.perf_counter()
    done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          check=False)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)}: exit status {done.returncode}: "
                           f"{done.stderr.strip().splitlines()[-1:]}")
    return seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--n", type=int, nargs="+", default=[24, 40])
    parser.add_argument("--config", nargs="*", default=["gamg", "gamg-reduced"],
                        help="peer configurations (petsc_snesvi_3d.py --config)")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--signorini", default=os.path.join(ROOT, "build/release/app/signorini"))
    parser.add_argument("--energy-tolerance", type=float, default=1e-8)
    args = parser.parse_args()
    example = os.path.join(ROOT, "examples/box_on_sphere.toml")
    peer = os.path.join(HERE, "petsc_snesvi_3d.py")
    status = 0
    print("| mesh | unknowns | solver | whole process | / signorini | energy | rel. difference |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for n in args.n:
            out = os.path.join(tmp, f"s{n}")
            command = [args.signorini, "solve", example, "-q", "-o", out,
                       "--set", f"mesh.nx={n}", "--set", f"mesh.ny={n}",
                       "--set", f"mesh.nz={n // 2}", "--set", 'mesh.cell="hex8"']
            ours = min(timed(command) for _ in range(args.repeats))
            with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
                summary = json.load(f)
            energy = summary["energy"]
            mesh = f"{n}x{n}x{n // 2}"
            print(f"| {mesh} | {summary['n_free_dofs']:,} | signorini ({summary['path']}) | "
                  f"{ours:.2f} s | 1 | {energy:.12e} | |", flush=True)
            for config in args.config:
                result = os.path.join(tmp, f"p{n}{config}.json")
                try:
                    theirs = min(timed(["/usr/bin/python3", peer, "--n", str(n), "--config",
                                        config, "--quiet", "--json", result])
                                 for _ in range(args.repeats))
                except RuntimeError as e:
                    print(f"| {mesh} | | PETSc SNESVI {config} | failed: {e} | | | |")
                    status = 1
                    continue
                with open(result, encoding="utf-8") as f:
                    r = json.load(f)
                difference = abs(r["energy"] - energy) / abs(energy)
                if difference > args.energy_tolerance:
                    status = 1
                print(f"| {mesh} | {r['n_unknowns']:,} | PETSc SNESVI {config} "
                      f"({r['snes_iterations']} Newton, {r['ksp_iterations']} KSP) | "
                      f"{theirs:.2f} s | {theirs / ours:.1f}x | {r['energy']:.12e} | "
                      f"{difference:.1e} |", flush=True)
    return status


if __name__ == "__main__":
    sys.exit(main())
