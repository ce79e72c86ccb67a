#!/usr/bin/env bash
# Installs the Debian 12 packages that signorini needs to build, test and plot, and only those
# that are missing (so a second run does nothing). Runs as root, or through sudo when it is
# available. (The fuzzing of tests/fuzz/run.sh also needs clang, which that script installs.)
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev libsuitesparse-dev libopenblas-dev
  libtomlplusplus-dev libmuparser-dev libcli11-dev libfmt-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev
  # `signorini plot` and `solve --plot` draw with matplotlib; the tests read the .vtu files with
  # meshio as a second, independent reader (both for /usr/bin/python3).
  python3-matplotlib python3-meshio
  # The gmsh program (never linked: GPL) meshes a .geo given as [mesh] file, and a test checks
  # that it does; the .msh files of the examples and tests are committed, made by it.
  gmsh
  # PETSc with Open MPI (and hypre, MUMPS, PT-Scotch): the distributed engine and signorini-mpi
  # (docs/distributed.md), and the PETSc peer of the benchmarks (python3-petsc4py).
  petsc-dev python3-petsc4py
  # The Python package (python/, docs/python.md): pybind11 and the interpreter's headers to build
  # it, pytest for its tests.
  pybind11-dev python3-dev python3-pytest
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages are installed"
  exit 0
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
  else
    echo "setup: these packages are missing and I am not root: ${missing[*]}" >&2
    exit 1
  fi
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
