#!/usr/bin/env bash
# The tool under mpirun (docs/distributed.md): `mpirun -n 2 signorini solve` on the paper's
# problem, on SSNV128's friction history and on the 3D example gives the serial answer (the same
# Uzawa steps, energies to 1e-10, contact pressures, displacements and resultants to 1e-8),
# written from the ranks' parts of the mesh; bad input stops every rank with one message, exit
# status 2, and leaves earlier results as they were.
#   mpirun_solve_test.sh SIGNORINI MPIRUN EXAMPLES_DIR
set -euo pipefail
tool=$1
mpirun=$2
examples=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
run_mpi() { "$mpirun" --allow-run-as-root --oversubscribe -n 2 "$tool" "$@"; }

# Runs the tool under mpirun expecting it to stop: exit status $2 and the grep pattern $3 in its
# stderr ($tmp/stderr, kept for further checks); $1 names the case where it does not.
expect_stop() {
  local what=$1 expected=$2 pattern=$3 status=0
  shift 3
  run_mpi "$@" 2> "$tmp/stderr" || status=$?
  [ "$status" -eq "$expected" ] ||
    { echo "$what: exit status $status, expected $expected"; cat "$tmp/stderr"; exit 1; }
  grep -q "$pattern" "$tmp/stderr" ||
    { echo "$what: the message does not say '$pattern'"; cat "$tmp/stderr"; exit 1; }
}

compare() {  # serial folder, distributed folder
  /usr/bin/python3 - "$1" "$2" <<'PY'
import csv, json, sys
serial, mpi = (json.load(open(f"{d}/summary.json")) for d in sys.argv[1:3])
assert mpi["path"] == "distributed", mpi["path"]
assert mpi["ranks"] == 2, mpi["ranks"]
assert serial["ranks"] == 1, serial["ranks"]
assert mpi["converged"] and serial["converged"]
assert mpi["uzawa_iterations"] == serial["uzawa_iterations"], (mpi["uzawa_iterations"], serial["uzawa_iterations"])
rel = abs(mpi["energy"] - serial["energy"]) / abs(serial["energy"])
assert rel < 1e-10, f"energies differ by {rel:.2e}"
def rows(d):
    with open(f"{d}/contact.csv") as f:
        return list(csv.DictReader(f))
a, b = rows(sys.argv[1]), rows(sys.argv[2])
assert len(a) == len(b) and len(a) > 0
for key in ("pressure", "u_n"):
    scale = max(abs(float(r[key])) for r in a)
    worst = max(abs(float(r[key]) - float(s[key])) for r, s in zip(a, b))
    assert worst <= 1e-8 * scale, f"{key} differs by {worst:.2e} of {scale:.2e}"
# The resultants, summed over the ranks' parts of the mesh, as the serial run's.
ra, rb = serial["resultants"], mpi["resultants"]
scale = max(abs(x) for x in ra["contact"]) + max(abs(x) for x in ra["applied"])
pairs = [(ra["applied"], rb["applied"]), (ra["contact"], rb["contact"])]
assert [c["boundary"] for c in ra["reactions"]] == [c["boundary"] for c in rb["reactions"]]
pairs += [(c["force"], d["force"]) for c, d in zip(ra["reactions"], rb["reactions"])]
worst = max(abs(x - y) for a, b in pairs for x, y in zip(a, b))
assert worst <= 1e-8 * scale, f"resultants differ by {worst:.2e} of {scale:.2e}"
assert mpi["n_dofs"] == serial["n_dofs"], (mpi["n_dofs"], serial["n_dofs"])
print(f"ok: {mpi['uzawa_iterations']} Uzawa steps, energies within {rel:.1e}; {mpi['device']}")
PY
}

"$tool" solve "$examples/paper.toml" -q -o "$tmp/paper_serial" --set mesh.nx=120 --set mesh.ny=40
run_mpi solve "$examples/paper.toml" -q -o "$tmp/paper_mpi" --set mesh.nx=120 --set mesh.ny=40
compare "$tmp/paper_serial" "$tmp/paper_mpi"
# The figures of a distributed run (no whole solution.vtu): the plot puts the pieces together,
# the serial solution.vtu's points and values (tools/signorini_figures.py read_solution).
/usr/bin/python3 - "$tmp/paper_serial" "$tmp/paper_mpi" "$examples/../tools" <<'PY'
import sys
import numpy as np
sys.path.insert(0, sys.argv[3])
import signorini_figures as f
serial, mpi = f.read_vtu(f"{sys.argv[1]}/solution.vtu"), f.read_solution(sys.argv[2])
assert len(mpi["points"]) == len(serial["points"]) and len(mpi["types"]) == len(serial["types"])
order = np.lexsort(serial["points"].T[::-1])
assert (mpi["points"] == serial["points"][order]).all()
u, v = mpi["point_data"]["displacement"], serial["point_data"]["displacement"][order]
assert abs(u - v).max() <= 1e-8 * abs(v).max(), abs(u - v).max()
print(f"ok: the pieces put together, {len(mpi['points'])} points as solution.vtu's")
PY
"$tool" plot "$tmp/paper_mpi" > /dev/null
[ -s "$tmp/paper_mpi/deformed_von_mises.png" ] || { echo "no deformed figure from the pieces"; exit 1; }

ssn=(--set mesh.nx=60 --set mesh.ny=20 --set solver.method='"semismooth_newton"')
"$tool" solve "$examples/paper.toml" -q -o "$tmp/ssn_serial" "${ssn[@]}"
run_mpi solve "$examples/paper.toml" -q -o "$tmp/ssn_mpi" "${ssn[@]}"
compare "$tmp/ssn_serial" "$tmp/ssn_mpi"

# Friction with a loading history (Code_Aster's SSNV128, Coulomb, five proportional steps):
# every step's contact.csv as the serial run's, the tangential traction, slip and node states
# too, and the .pvd time series of the steps' pieces.
"$tool" solve "$examples/ssnv128.toml" -q -o "$tmp/friction_serial"
run_mpi solve "$examples/ssnv128.toml" -q -o "$tmp/friction_mpi"
compare "$tmp/friction_serial" "$tmp/friction_mpi"
/usr/bin/python3 - "$tmp/friction_serial" "$tmp/friction_mpi" <<'PY'
import csv, glob, json, os, sys
serial, mpi = sys.argv[1:3]
reason = json.load(open(f"{mpi}/summary.json"))["path_reason"]
assert reason.startswith("distributed on 2 MPI ranks"), reason
steps = sorted(os.path.basename(f) for f in glob.glob(f"{serial}/steps/contact_*.csv"))
assert len(steps) == 5 and os.path.exists(f"{mpi}/solution.pvd"), steps
# Each step's solution in pieces, one per rank, that the .pvd's .pvtu files name.
import re
listed = re.findall(r'file="([^"]+)"', open(f"{mpi}/solution.pvd").read())
assert listed == [f"steps/solution_{k:04d}.pvtu" for k in range(1, 6)], listed
for name in listed:
    pieces = re.findall(r'<Piece Source="([^"]+)"/>', open(f"{mpi}/{name}").read())
    assert len(pieces) == 2 and all(os.path.exists(f"{mpi}/steps/{p}") for p in pieces), pieces
for name in ["../contact.csv"] + steps:
    a, b = (list(csv.DictReader(open(f"{d}/steps/{name}"))) for d in (serial, mpi))
    assert len(a) == len(b) > 0, name
    assert [r["state"] for r in a] == [r["state"] for r in b], name
    for key in ("pressure", "tangential", "slip", "u_t"):
        scale = max(abs(float(r[key])) for r in a)
        worst = max(abs(float(r[key]) - float(s[key])) for r, s in zip(a, b))
        assert worst <= 1e-8 * scale, f"{name} {key} differs by {worst:.2e} of {scale:.2e}"
print(f"ok: friction under mpirun, {len(steps)} load steps as the serial run's")
PY

"$tool" solve "$examples/box_on_sphere.toml" -q -o "$tmp/box_serial"
run_mpi solve "$examples/box_on_sphere.toml" -q -o "$tmp/box_mpi"
compare "$tmp/box_serial" "$tmp/box_mpi"

# The same run twice gives the same numbers to the last bit: the same partition each time
# (PT-Scotch on one thread, petsc_engine.cpp), on a mesh large enough that its threads made
# another one from run to run. (The box through the graph partitioner, not made in parts.)
box40=(--set mesh.nx=40 --set mesh.ny=40 --set mesh.nz=20 --set 'solver.partition="graph"')
run_mpi solve "$examples/box_on_sphere.toml" -q -o "$tmp/box40_a" "${box40[@]}"
run_mpi solve "$examples/box_on_sphere.toml" -q -o "$tmp/box40_b" "${box40[@]}"
cmp -s "$tmp/box40_a/contact.csv" "$tmp/box40_b/contact.csv" ||
  { echo "two runs on 2 ranks differ"; diff "$tmp/box40_a/contact.csv" "$tmp/box40_b/contact.csv" | head; exit 1; }
echo "ok: two runs on 2 ranks, the same contact.csv to the last bit"

# `check` under mpirun says that the solve would be distributed, and how.
run_mpi check "$examples/box_on_sphere.toml" > "$tmp/check" ||
  { echo "check under mpirun failed"; cat "$tmp/check"; exit 1; }
grep -q "^distributed: PETSc .* on 2 MPI ranks" "$tmp/check" ||
  { echo "check under mpirun does not say distributed"; cat "$tmp/check"; exit 1; }
echo "ok: check under mpirun"

# plot and bench are one process's work: refused under mpirun, one message, status 2.
status=0
run_mpi plot "$tmp/box_mpi" > /dev/null 2> "$tmp/stderr" || status=$?
[ "$status" -eq 2 ] && [ "$(grep -c "signorini: error:" "$tmp/stderr")" -eq 1 ] &&
  grep -q "without mpirun" "$tmp/stderr" ||
  { echo "plot under mpirun: status $status"; cat "$tmp/stderr"; exit 1; }
echo "ok: plot refused under mpirun"

# solution.pvtu: one piece per rank, no whole solution.vtu (every rank holds its part of the
# mesh), the pieces' cells those of the serial run's solution.vtu, each piece's values those of
# the serial solution.vtu at the same points (meshio, an independent reader).
/usr/bin/python3 - "$tmp/box_mpi" "$tmp/box_serial" <<'PY'
import os, re, sys
import meshio
out, serial = sys.argv[1:3]
assert not os.path.exists(f"{out}/solution.vtu"), "a whole solution.vtu from a distributed run"
pvtu = open(f"{out}/solution.pvtu").read()
pieces = re.findall(r'<Piece Source="([^"]+)"/>', pvtu)
assert pieces == ["solution_0.vtu", "solution_1.vtu"], pieces
whole = meshio.read(f"{serial}/solution.vtu")
at = {tuple(p): i for i, p in enumerate(whole.points.round(12))}
cells = 0
for name in pieces:
    piece = meshio.read(f"{out}/{name}")
    cells += sum(len(c.data) for c in piece.cells)
    for field in ("displacement", "contact_pressure", "von_mises"):
        scale = abs(whole.point_data[field]).max()
        for k, p in enumerate(piece.points.round(12)):
            a, b = piece.point_data[field][k], whole.point_data[field][at[tuple(p)]]
            assert (abs(a - b) <= 1e-8 * scale).all(), (name, field, a, b)
assert cells == sum(len(c.data) for c in whole.cells), cells
print(f"ok: solution.pvtu, {len(pieces)} pieces, {cells} cells, as the serial solution.vtu")
PY

# One rank on the distributed path: its one piece is solution.vtu itself, which solution.pvtu
# names (no copy of it as solution_0.vtu), and the serial file's values.
"$mpirun" --allow-run-as-root -n 1 "$tool" solve "$examples/box_on_sphere.toml" -q \
  --set 'solver.distributed="petsc"' -o "$tmp/box_one_rank" > /dev/null
/usr/bin/python3 - "$tmp/box_one_rank" "$tmp/box_serial" <<'PY'
import json, os, re, sys
import meshio
out, serial = sys.argv[1:3]
assert json.load(open(f"{out}/summary.json"))["path"] == "distributed"
pieces = re.findall(r'<Piece Source="([^"]+)"/>', open(f"{out}/solution.pvtu").read())
assert pieces == ["solution.vtu"], pieces
assert not os.path.exists(f"{out}/solution_0.vtu"), "a copy of solution.vtu"
one, whole = meshio.read(f"{out}/solution.vtu"), meshio.read(f"{serial}/solution.vtu")
assert len(one.points) == len(whole.points)
scale = abs(whole.point_data["displacement"]).max()
assert abs(one.point_data["displacement"] - whole.point_data["displacement"]).max() <= 1e-8 * scale
print("ok: one rank's solution.pvtu names solution.vtu")
PY

# Bad input: one message from rank 0, status 2, the earlier results untouched.
before=$(md5sum "$tmp/paper_mpi/summary.json")
expect_stop "bad input" 2 "material.E" solve "$examples/paper.toml" -q -o "$tmp/paper_mpi" \
  --set material.E=-1
lines=$(grep -c "signorini: error:" "$tmp/stderr" || true)
[ "$lines" -eq 1 ] || { echo "bad input: $lines error lines, expected 1"; cat "$tmp/stderr"; exit 1; }
[ "$before" = "$(md5sum "$tmp/paper_mpi/summary.json")" ] || { echo "earlier results changed"; exit 1; }
echo "ok: bad input under mpirun"

# A box made in parts: bad input that only some ranks' parts hold (a prescribed displacement
# that is NaN beyond x = 0.6) stops every rank with one message, status 2.
sed 's/^z = -0.001.*/z = "x > 0.6 ? 0\/0 : -0.001"/' "$examples/box_on_plane.toml" > "$tmp/bad_box.toml"
expect_stop "bad input in a box made in parts" 2 "displacement\[0\].z = .* is NaN at x = " \
  solve "$tmp/bad_box.toml" -q -o "$tmp/bad_box"
lines=$(grep -c "signorini: error:" "$tmp/stderr" || true)
[ "$lines" -eq 1 ] || { echo "bad box: $lines error lines, expected 1"; cat "$tmp/stderr"; exit 1; }
[ ! -e "$tmp/bad_box/summary.json" ] || { echo "bad box: results written"; exit 1; }
echo "ok: bad input in a box made in parts"

# A rank that dies during the solve (killed by a signal): mpirun ends the others, the status is
# not 0, and the earlier results stay as they were.
before=$(md5sum "$tmp/box_mpi/summary.json")
status=0
"$mpirun" --allow-run-as-root --oversubscribe -n 2 bash -c \
  'if [ "${OMPI_COMM_WORLD_RANK:-0}" = 1 ]; then exec timeout -s KILL 1 "$0" "$@"; else exec "$0" "$@"; fi' \
  "$tool" solve "$examples/box_on_sphere.toml" -q -o "$tmp/box_mpi" --set mesh.nx=40 \
  --set mesh.ny=40 --set mesh.nz=20 --set 'mesh.cell="hex8"' > "$tmp/stdout" 2> "$tmp/stderr" ||
  status=$?
[ "$status" -ne 0 ] || { echo "a killed rank: exit status 0"; cat "$tmp/stderr"; exit 1; }
[ "$before" = "$(md5sum "$tmp/box_mpi/summary.json")" ] || { echo "a killed rank: results changed"; exit 1; }
echo "ok: a killed rank stops the run (status $status), earlier results kept"

# A rank that fails alone, on 2 and 4 ranks: rank 1 runs out of memory (ulimit -v, in PETSc's
# set-up; a cap of 300 MB is below what a rank needs here and above what MPI needs to start)
# while the others wait for it in a collective call. It says so in one line naming itself, ends
# every rank (status 4, a numerical failure), and the earlier results stay as they were. The
# same run whole on 4 ranks fails alike on every rank for bad input: one line, status 2.
# (Not under AddressSanitizer, which reserves terabytes of address space at start: a cap on it
# stops the process before main.)
memory_ranks=(2 4)
if ldd "$tool" | grep -q libasan; then
  memory_ranks=()
  echo "skip: a rank out of memory (ulimit -v), under AddressSanitizer"
fi
# On a loaded machine the cap can stop rank 1 already in MPI_Init (PMIx cannot start its
# thread): that start failure is not what is tested here, and the run is tried again (3 times).
for ranks in "${memory_ranks[@]}"; do
  for attempt in 1 2 3; do
    status=0
    "$mpirun" --allow-run-as-root --oversubscribe -n "$ranks" bash -c \
      'if [ "${OMPI_COMM_WORLD_RANK:-0}" = 1 ]; then ulimit -v 300000; fi; exec "$0" "$@"' \
      "$tool" solve "$examples/box_on_sphere.toml" -q -o "$tmp/box_mpi" --set mesh.nx=40 \
      --set mesh.ny=40 --set mesh.nz=20 --set 'mesh.cell="hex8"' > "$tmp/stdout" \
      2> "$tmp/stderr" || status=$?
    grep -q "pmix_init failed\|before MPI_INIT completed" "$tmp/stderr" || break
    echo "note: rank 1 could not start MPI under the cap (attempt $attempt)"
  done
  [ "$status" -eq 4 ] &&
    [ "$(grep -c "signorini: error:" "$tmp/stderr")" -eq 1 ] &&
    grep -q "signorini: error: rank 1: numerical failure: PETSc: .*out of memory" "$tmp/stderr" ||
    { echo "rank 1 out of memory on $ranks ranks: status $status"; cat "$tmp/stderr"; exit 1; }
  [ "$before" = "$(md5sum "$tmp/box_mpi/summary.json")" ] ||
    { echo "rank 1 out of memory on $ranks ranks: results changed"; exit 1; }
  echo "ok: rank 1 out of memory alone on $ranks ranks stops them all (status 4), one message"
done
status=0
"$mpirun" --allow-run-as-root --oversubscribe -n 4 "$tool" solve "$examples/box_on_sphere.toml" \
  -q -o "$tmp/box_mpi" --set material.nu=0.5 2> "$tmp/stderr" || status=$?
[ "$status" -eq 2 ] && [ "$(grep -c "signorini: error:" "$tmp/stderr")" -eq 1 ] &&
  grep -q "material.nu = 0.5" "$tmp/stderr" ||
  { echo "bad input on 4 ranks: status $status"; cat "$tmp/stderr"; exit 1; }
echo "ok: bad input on 4 ranks, one message from rank 0"

# An output folder that rank 0 cannot make: every rank stops before the solve, one message.
# A cell whose mid-edge node makes it inverted, which the reader's corner check passes and the
# assembly finds (det J at the cell's nodes): rank 0, which assembles no cell itself, finds it
# for all, and every rank stops with the serial run's one message, status 2.
/usr/bin/python3 - "$examples/gmsh/hertz_p2.msh" "$tmp/inverted.msh" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
i = lines.index("$Nodes"); p = i + 2
at = {}
for _ in range(int(lines[i + 1].split()[0])):
    n = int(lines[p].split()[3]); p += 1
    for k in range(n): at[int(lines[p + k])] = p + n + k
    p += 2 * n
e = lines.index("$Elements"); p = e + 2
for _ in range(int(lines[e + 1].split()[0])):
    kind, n = map(int, lines[p].split()[2:4]); p += 1
    if kind == 9: tri6 = [list(map(int, lines[p + k].split())) for k in range(n)]
    p += n
cell = tri6[len(tri6) // 2]  # an inner tri6: its mid-edge node 1-2 moved 0.7 of the way to node 3
x = lambda t: [float(v) for v in lines[at[t]].split()]
m, c = x(cell[4]), x(cell[3])
lines[at[cell[4]]] = " ".join(repr(a + 0.7 * (b - a)) for a, b in zip(m, c))
open(sys.argv[2], "w").write("\n".join(lines))
PY
status=0
"$tool" solve "$examples/hertz_p2.toml" -q -o "$tmp/inverted_serial" \
  --set "mesh.file=\"$tmp/inverted.msh\"" 2> "$tmp/serial_stderr" || status=$?
[ "$status" -eq 2 ] && grep -q "inverted or degenerate tri6" "$tmp/serial_stderr" ||
  { echo "the inverted cell serially: status $status"; cat "$tmp/serial_stderr"; exit 1; }
expect_stop "inverted cell" 2 "inverted or degenerate tri6" solve "$examples/hertz_p2.toml" -q \
  -o "$tmp/inverted_mpi" --set "mesh.file=\"$tmp/inverted.msh\""
[ "$(grep -c "signorini: error:" "$tmp/stderr")" -eq 1 ] &&
  grep -qF "$(cat "$tmp/serial_stderr")" "$tmp/stderr" ||
  { echo "the inverted cell under mpirun: not the serial message"; cat "$tmp/stderr"; exit 1; }
echo "ok: an inverted cell stops every rank with the serial message"

expect_stop "unusable -o" 2 "no-such-folder" solve "$examples/paper.toml" -q -o /proc/no-such-folder
lines=$(grep -c "signorini: error:" "$tmp/stderr" || true)
[ "$lines" -eq 1 ] || { echo "unusable -o: $lines error lines, expected 1"; cat "$tmp/stderr"; exit 1; }
echo "ok: unusable output folder under mpirun"

# A distributed factorisation that fails says MUMPS's reason: here its working memory capped at
# 1 MB (ICNTL(23)), so INFOG(1) = -19; status 3, as for any solve that does not converge.
expect_stop "failed MUMPS" 3 "DIVERGED_PC_FAILED, MUMPS INFOG(1) = -19" \
  solve "$examples/paper.toml" -q -o "$tmp/mumps_failed" \
  --set 'solver.petsc_options="-mat_mumps_icntl_23 1"'
echo "ok: a failed MUMPS factorisation names INFOG(1)"

# A work space estimated short (INFOG(1) = -9, forced here by a negative ICNTL(14), as MUMPS's
# run-time scheduling on many ranks may cause by itself): the factorisation is done again with
# ICNTL(14) raised, the solve goes on to the serial answer, and the summary says so. Semismooth
# Newton too (its own PETSc solver).
run_mpi solve "$examples/paper.toml" -q -o "$tmp/mumps_retried" --set mesh.nx=120 --set mesh.ny=40 \
  --set 'solver.petsc_options="-mat_mumps_icntl_14 -50"'
compare "$tmp/paper_serial" "$tmp/mumps_retried"
grep -q "work space raised to ICNTL(14)" "$tmp/mumps_retried/summary.json" ||
  { echo "a retried MUMPS factorisation: summary.json does not say so"; exit 1; }
run_mpi solve "$examples/paper.toml" -q -o "$tmp/ssn_retried" "${ssn[@]}" \
  --set 'solver.petsc_options="-mat_mumps_icntl_14 -50"'
compare "$tmp/ssn_serial" "$tmp/ssn_retried"
grep -q "work space raised to ICNTL(14)" "$tmp/ssn_retried/summary.json" ||
  { echo "a retried MUMPS factorisation (semismooth Newton): summary.json does not say so"; exit 1; }
echo "ok: a short MUMPS work space raised and the factorisation done again"

# Still short after three raises (ICNTL(14) = -1000 stays negative): status 3, and the message
# says what was tried and which option gives more.
expect_stop "MUMPS short three times" 3 \
  "INFOG(1) = -9, INFOG(2) = [0-9]*: its work space was estimated short, also with ICNTL(14) raised three times" \
  solve "$examples/paper.toml" -q -o "$tmp/mumps_short" \
  --set 'solver.petsc_options="-mat_mumps_icntl_14 -1000"'
echo "ok: a work space still short after three raises is reported"
