#!/usr/bin/env bash
# What a user waits for when drawing the figures: `signorini plot` on the results of the paper's
# problem on a 480 x 160 mesh (77,000 nodes), whole processes timed from the shell, for each set
# of formats, interleaved, best and median of N runs (docs/output.md, "Speed").
#
#   bash bench/plot_speed.sh [RUNS [MESH]]        # defaults: 7 runs, 480x160
#
# SIGNORINI names the executable (default: the release build).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${SIGNORINI:-$root/build/release/app/signorini}
runs=${1:-7}
mesh=${2:-480x160}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$exe" solve "$root/examples/paper.toml" -q -o "$work/out" --set "mesh.nx=${mesh%x*}" \
  --set "mesh.ny=${mesh#*x}"
formats=(png png,svg png,svg,pdf)
for ((i = 0; i < runs; i++)); do
  for f in "${formats[@]}"; do
    /usr/bin/time -a -o "$work/$f.txt" -f "%e %U %S" "$exe" plot "$work/out" --format "$f" >/dev/null
  done
done
echo "signorini plot, paper's problem on $mesh, $runs runs each (seconds; CPU = user + system)"
printf "%-12s %8s %8s %10s\n" formats best median "mean CPU"
for f in "${formats[@]}"; do
  sort -n "$work/$f.txt" | awk -v f="$f" '{w[NR] = $1; c += $2 + $3}
    END {printf "%-12s %8.2f %8.2f %10.2f\n", f, w[1], w[int((NR + 1) / 2)], c / NR}'
done
