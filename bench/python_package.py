#!/usr/bin/env python3
"""The Python package against the command-line tool (docs/performance.md, "From Python").

1. The paper's problem (examples/paper.toml, 480 x 160 by default): the whole process from the
   shell, `signorini solve ... -o OUT` against `python3 -c "import signorini; signorini.solve(...,
   output=OUT)"`, alternating, best of --repeats; and, inside one Python process, the same solve
   again (no start-up) beside the tool's own phase total.
2. A parameter study on the 60 x 20 mesh: --solves solves at load factors from 0.5 to 1.5, one
   Solver set up once, each solve warm-started from the last, against --tool-runs runs of the tool
   (each a whole process writing its results), scaled to the same number of solves.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_package.py [--repeats 5]
        [--nx 480 --ny 160] [--solves 10000] [--tool-runs 200]
"""

import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]


def seconds(args, env=None):
    start = time.perf_counter()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL, env=env)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tool", default=str(ROOT / "build/release/app/signorini"))
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--nx", type=int, default=480)
    parser.add_argument("--ny", type=int, default=160)
    parser.add_argument("--solves", type=int, default=10000)
    parser.add_argument("--tool-runs", type=int, default=200)
    a = parser.parse_args()

    import signorini
    paper = ROOT / "examples/paper.toml"
    overrides = [f"mesh.nx={a.nx}", f"mesh.ny={a.ny}"]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(pathlib.Path(signorini.__file__).parents[1])] +
        os.environ.get("PYTHONPATH", "").split(os.pathsep)))
    with tempfile.TemporaryDirectory() as tmp:
        out = pathlib.Path(tmp)
        tool_cmd = [a.tool, "solve", str(paper), "-q", "-o", str(out / "tool")]
        for o in overrides:
            tool_cmd += ["--set", o]
        py_cmd = [sys.executable, "-c",
                  "import signorini, sys; signorini.solve(signorini.Problem(sys.argv[1], "
                  "overrides=sys.argv[3:]), output=sys.argv[2])",
                  str(paper), str(out / "python"), *overrides]
        tool_times, py_times, tool_phases = [], [], []
        for _ in range(a.repeats):
            tool_times.append(seconds(tool_cmd))
            tool_phases.append(
                json.loads((out / "tool/summary.json").read_text())["timings"]["total"])
            py_times.append(seconds(py_cmd, env))
        tool_phases = min(tool_phases)
        in_process = []
        for _ in range(a.repeats):
            start = time.perf_counter()
            signorini.solve(signorini.Problem(paper, overrides=overrides), output=out / "again")
            in_process.append(time.perf_counter() - start)
        same = all((out / "tool" / f).read_bytes() == (out / "python" / f).read_bytes()
                   for f in ("solution.vtu", "contact.csv"))
        print(f"paper {a.nx} x {a.ny}, best of {a.repeats}, alternating:")
        print(f"  tool, whole process            {min(tool_times):8.3f} s   (its phases, best: "
              f"{tool_phases:.3f} s)")
        print(f"  python3 -c, whole process      {min(py_times):8.3f} s   "
              f"ratio {min(py_times) / min(tool_times):.3f}")
        print(f"  in one Python process (problem, model, solve, write) {min(in_process):8.3f} s   "
              f"ratio to the tool's whole process {min(in_process) / min(tool_times):.3f}")
        print(f"  result files identical to the tool's: {same}")

        # The parameter study.
        small = ["mesh.nx=60", "mesh.ny=20"]
        model = signorini.Model(signorini.Problem(paper, overrides=small))
        start = time.perf_counter()
        solver = signorini.Solver(model)
        previous = None
        forces = []
        for k in range(a.solves):
            solver.set_load_factor(0.5 + k / max(a.solves - 1, 1))
            if previous is not None:
                solver.warm_start(previous)
            previous = solver.solve()
            forces.append(previous.contact_force)
        study = time.perf_counter() - start
        run_cmd = [a.tool, "solve", str(paper), "-q", "-o", str(out / "run")] + \
            [x for o in small for x in ("--set", o)]
        start = time.perf_counter()
        for _ in range(a.tool_runs):
            subprocess.run(run_cmd, check=True, stdout=subprocess.DEVNULL)
        per_run = (time.perf_counter() - start) / a.tool_runs
        print(f"parameter study, 60 x 20, {a.solves} solves (load factors 0.5 .. 1.5):")
        print(f"  one Solver, warm starts        {study:8.3f} s   ({1e3 * study / a.solves:.3f} ms "
              f"per solve; contact force {forces[0]:.5g} .. {forces[-1]:.5g})")
        print(f"  tool runs                      {per_run * a.solves:8.3f} s   ({1e3 * per_run:.2f} "
              f"ms per run, mean of {a.tool_runs} runs, times {a.solves})")
        print(f"  speed-up {per_run * a.solves / study:.1f}x")


if __name__ == "__main__":
    main()
