#!/usr/bin/env bash
# Packs what the GPU checks need onto a machine that cannot install anything (the device machine
# of docs/gpu.md): the tool and the GPU tests of a build, with the shared libraries they load
# except the C library and CUDA's own (the device has its CUDA toolkit), and the C++ runtime
# apart, as a fallback for a device whose own is older.
#   scripts/device-pack.sh [preset]        (release by default) -> .device/
# Then, on the device, from the repository root: bash scripts/device-run.sh OUTDIR
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
build="build/$preset"
for f in "$build/app/signorini" "$build/tests/signorini_gpu_tests"; do
  [[ -x "$f" ]] || { echo "device-pack: $f is missing: build the $preset preset first" >&2; exit 2; }
done
if ! grep -q "CMAKE_CUDA_COMPILER:.*nvcc" "$build/CMakeCache.txt"; then
  echo "device-pack: $build was configured without CUDA" >&2
  exit 2
fi
rm -rf .device
mkdir -p .device/bin .device/lib .device/lib-compat
cp "$build/app/signorini" "$build/tests/signorini_gpu_tests" .device/bin/
strip .device/bin/* 2>/dev/null || true
for bin in .device/bin/*; do
  ldd "$bin" | awk '/=> \// {print $3}'
done | sort -u | while read -r lib; do
  case "$lib" in
    */libc.so.*|*/libm.so.*|*/libdl.so.*|*/libpthread.so.*|*/librt.so.*|*/ld-linux*) ;;
    /usr/local/cuda*|*/libcuda.so*) ;;
    # The C++ runtime only as a fallback: a newer system one must win (device-run.sh decides).
    */libstdc++.so.*|*/libgcc_s.so.*) cp -L "$lib" .device/lib-compat/ ;;
    *) cp -L "$lib" .device/lib/ ;;
  esac
done
du -sh .device
echo "carry .device (run: bash scripts/device-run.sh \$OUT)"
