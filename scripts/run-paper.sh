#!/usr/bin/env bash
# The main job: installs what is missing, builds, and solves the paper's benchmark (480 x 160
# mesh, examples/paper.toml) into an output folder (default results/paper), printing the summary,
# and draws the paper's figures there (PNG and SVG, docs/output.md).
#   scripts/run-paper.sh [OUTDIR] [extra arguments for `signorini solve`, e.g. --set mesh.nx=60]
set -euo pipefail
cd "$(dirname "$0")/.."
outdir="${1:-results/paper}"
shift || true
bash scripts/build.sh release
build/release/app/signorini solve examples/paper.toml -o "$outdir" --plot --plot-format png,svg "$@"
echo "results written to $outdir (summary.json, contact.csv, solution.vtu, contact.vtu and the figures)"
