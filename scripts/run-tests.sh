#!/usr/bin/env bash
# The test suite: installs what is missing, builds the release preset and runs every test with
# CTest (unit tests, the paper's Table 1 up to 240x80, the command-line tool on the examples).
#   scripts/run-tests.sh [preset]      (release by default; debug and asan-ubsan work too)
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
bash scripts/build.sh "$preset"
ctest --preset "$preset" -j "$(nproc)"
