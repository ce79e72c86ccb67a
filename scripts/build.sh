#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release) after installing what is missing.
#   scripts/build.sh [release|debug|asan-ubsan]
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
bash scripts/setup.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
# The Python package, where Debian's python3 finds it (/usr/local/lib/python3.X/dist-packages),
# so that `python3 -c "import signorini"` works: the release build's, as root (docs/python.md).
if [ "$preset" = release ] && compgen -G "build/release/python/signorini/_signorini*.so" >/dev/null; then
  if [ "$(id -u)" -eq 0 ]; then
    cmake --install build/release --component python >/dev/null
  else
    echo "build: not root, so the Python package is not installed; use" \
         "PYTHONPATH=$PWD/build/release/python, or run: sudo cmake --install build/release --component python"
  fi
fi
