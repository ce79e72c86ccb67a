#!/usr/bin/env bash
# The 2D Hertz problem of examples/hertz.toml (a cylinder pressed onto a rigid plane) on an
# unstructured mesh of about one million unknowns, timed against one linear solve of the same
# discrete problem in the same run: `signorini bench --problem` (docs/performance.md, "Any problem
# against one linear solve"). The mesh is made by the gmsh program (Debian: gmsh), about a minute.
#
#   bash bench/hertz_million.sh [CLSCALE [more bench options]]
#
# CLSCALE scales every mesh size of examples/gmsh/hertz.geo (default 0.076: 471,156 nodes,
# 942,312 unknowns; 1 is the example's own mesh). SIGNORINI names the executable (default: the
# release build).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
exe=${SIGNORINI:-$root/build/release/app/signorini}
scale=${1:-0.076}
shift || true
command -v gmsh >/dev/null || { echo "hertz_million.sh: needs the gmsh program (apt-get install gmsh)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
SECONDS=0
gmsh -2 "$root/examples/gmsh/hertz.geo" -clscale "$scale" -format msh41 -bin -o "$work/hertz.msh" -v 1
echo "mesh made by gmsh in ${SECONDS} s ($(du -m "$work/hertz.msh" | cut -f1) MB)"
sed "s|gmsh/hertz.msh|$work/hertz.msh|" "$root/examples/hertz.toml" > "$work/hertz.toml"
"$exe" bench --problem "$work/hertz.toml" --repeats 2 "$@"
