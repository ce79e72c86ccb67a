#!/usr/bin/env python3
"""Digests of the result files of every example, for refactorings that must not change an answer.

Runs the tool on each problem file of examples/ (on 1 rank, or under mpirun on several) and prints
one line per result file: example, ranks, file, SHA-256. summary.json is digested without its
timings ("timings", and the "seconds" of each load step: the only parts that differ between two
runs of the same build). Compare two builds:

    tools/result_digests.py --tool build/release/app/signorini > before.txt
    ... change the code, rebuild ...
    tools/result_digests.py --tool build/release/app/signorini > after.txt && diff before.txt after.txt

Runs on several ranks are not reproducible to the last bit (the order of MPI's and PETSc's sums
varies from run to run), so for them keep the files and compare their numbers instead:

    tools/result_digests.py --tool /tmp/before/signorini --ranks 2 4 --keep /tmp/before-results
    tools/result_digests.py --ranks 2 4 --keep /tmp/after-results
    tools/result_digests.py --compare /tmp/before-results /tmp/after-results

which prints, per file, "identical", or the largest relative difference of its numbers (all other
text must be equal), and fails where one is above --tolerance.
"""
import argparse
import hashlib
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
RESULT_FILES = ("summary.json", "contact.csv", "solution.vtu", "contact.vtu")


def without_timings(value):
    if isinstance(value, dict):
        return {k: without_timings(v) for k, v in value.items() if k not in ("timings", "seconds")}
    if isinstance(value, list):
        return [without_timings(v) for v in value]
    return value


def digest(path: pathlib.Path) -> str:
    data = path.read_bytes()
    if path.name == "summary.json":
        data = json.dumps(without_timings(json.loads(data)), sort_keys=True).encode()
    return hashlib.sha256(data).hexdigest()


NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def comparable_text(path: pathlib.Path) -> str:
    if path.name == "summary.json":
        return json.dumps(without_timings(json.loads(path.read_bytes())), sort_keys=True, indent=0)
    return path.read_text(errors="replace")


def largest_difference(a: str, b: str, floor: float) -> float:
    """The largest |x - y| / max(|x|, |y|, floor) over the numbers of a and b; inf where the text
    between the numbers differs, or their counts."""
    if NUMBER.sub("#", a) != NUMBER.sub("#", b):
        return float("inf")
    worst = 0.0
    for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
        if x != y:
            fx, fy = float(x), float(y)
            worst = max(worst, abs(fx - fy) / max(abs(fx), abs(fy), floor))
    return worst


def vtu_difference(a: pathlib.Path, b: pathlib.Path, floor: float) -> float:
    """The same for two VTU files (binary arrays): their points, cells and data arrays, read with
    meshio."""
    import meshio  # (python3-meshio; only here, so that the digests need nothing beyond Python)
    import numpy as np
    ma, mb = meshio.read(a), meshio.read(b)
    pairs = [(ma.points, mb.points)]
    if [c.type for c in ma.cells] != [c.type for c in mb.cells] or \
            sorted(ma.point_data) != sorted(mb.point_data) or \
            sorted(ma.cell_data) != sorted(mb.cell_data):
        return float("inf")
    pairs += [(ca.data, cb.data) for ca, cb in zip(ma.cells, mb.cells)]
    pairs += [(ma.point_data[k], mb.point_data[k]) for k in ma.point_data]
    pairs += [(x, y) for k in ma.cell_data for x, y in zip(ma.cell_data[k], mb.cell_data[k])]
    worst = 0.0
    for x, y in pairs:
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        if x.shape != y.shape:
            return float("inf")
        if x.size:
            scale = np.maximum(np.maximum(np.abs(x), np.abs(y)), floor)
            worst = max(worst, float(np.max(np.abs(x - y) / scale)))
    return worst


def compare(before: pathlib.Path, after: pathlib.Path, tolerance: float, floor: float) -> int:
    status = 0
    for old in sorted(before.rglob("*")):
        if not old.is_file():
            continue
        name = old.relative_to(before)
        new = after / name
        if not new.exists():
            print(f"{name} missing", flush=True)
            status = 1
        elif old.read_bytes() == new.read_bytes():
            print(f"{name} identical", flush=True)
        else:
            worst = (vtu_difference(old, new, floor) if old.suffix == ".vtu" else
                     largest_difference(comparable_text(old), comparable_text(new), floor))
            verdict = "ok" if worst <= tolerance else "DIFFERS"
            print(f"{name} {verdict}: largest relative difference {worst:.2e}", flush=True)
            status = status or (worst > tolerance)
    return int(status)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tool", default=str(ROOT / "build/release/app/signorini"))
    parser.add_argument("--mpi-tool", default=None,
                        help="the tool run under mpirun (default: signorini-mpi beside --tool)")
    parser.add_argument("--ranks", type=int, nargs="+", default=[1])
    parser.add_argument("--skip", nargs="*", default=["paper_gpu"],
                        help="examples left out (default: paper_gpu, which needs a GPU)")
    parser.add_argument("--keep", default=None,
                        help="also copy the result files to KEEP/<example>-<ranks>/")
    parser.add_argument("--compare", nargs=2, metavar=("BEFORE", "AFTER"), default=None,
                        help="compare two --keep folders instead of running anything")
    parser.add_argument("--tolerance", type=float, default=1e-8,
                        help="with --compare: the largest relative difference allowed")
    parser.add_argument("--floor", type=float, default=1e-12,
                        help="with --compare: numbers below it in magnitude count as this large")
    parser.add_argument("examples", nargs="*", help="problem files (default: examples/*.toml)")
    args = parser.parse_args()
    if args.compare:
        return compare(pathlib.Path(args.compare[0]), pathlib.Path(args.compare[1]),
                       args.tolerance, args.floor)
    tool = pathlib.Path(args.tool).resolve()
    mpi_tool = pathlib.Path(args.mpi_tool or tool.parent / "signorini-mpi").resolve()
    examples = [pathlib.Path(e) for e in args.examples] or sorted((ROOT / "examples").glob("*.toml"))
    env = dict(os.environ, OMPI_MCA_btl_vader_single_copy_mechanism="none")
    status = 0
    for example in examples:
        if example.stem in args.skip:
            continue
        for ranks in args.ranks:
            with tempfile.TemporaryDirectory() as out:
                command = [str(tool), "solve", str(example), "-o", out, "-q"]
                if ranks > 1:
                    command = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-n", str(ranks),
                               str(mpi_tool)] + command[1:]
                run = subprocess.run(command, env=env, capture_output=True, text=True)
                if run.returncode not in (0, 3):
                    print(f"{example.stem} {ranks} exit-{run.returncode} "
                          f"{run.stderr.strip().splitlines()[-1:]}", flush=True)
                    status = 1
                    continue
                for name in RESULT_FILES:
                    path = pathlib.Path(out) / name
                    if path.exists():
                        print(f"{example.stem} {ranks} {name} {digest(path)}", flush=True)
                        if args.keep:
                            kept = pathlib.Path(args.keep) / f"{example.stem}-{ranks}"
                            kept.mkdir(parents=True, exist_ok=True)
                            shutil.copy(path, kept / name)
    return status


if __name__ == "__main__":
    sys.exit(main())
