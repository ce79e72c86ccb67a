#!/usr/bin/env bash
# Runs on a machine with an NVIDIA GPU, from the repository root, with .device/ packed by
# scripts/device-pack.sh: the GPU tests, --version and the GPU benchmark, each writing its
# output into OUTDIR (docs/gpu.md).
#   bash scripts/device-run.sh OUTDIR [bench arguments...]   (default: --huge --largest)
# Time limits per step: DEVICE_TESTS_SECONDS (default 180), DEVICE_BENCH_SECONDS (default 360);
# DEVICE_REPEATS: the benchmark's best of N (default 3); DEVICE_SANITIZER=1: also the kernel
# tests under compute-sanitizer memcheck (sanitizer.txt; DEVICE_SANITIZER_SECONDS, default 150).
set -uo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: device-run.sh OUTDIR [bench arguments]}"
shift
bench_args=("$@")
[[ ${#bench_args[@]} -gt 0 ]] || bench_args=(--huge --largest)
mkdir -p "$out"
export LD_LIBRARY_PATH="$PWD/.device/lib:/usr/local/cuda/lib64${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# CUDA's libraries where the toolkit keeps them elsewhere (e.g. Python wheels of nvidia-*).
# cuBLAS and cuSPARSE are opened when a GPU solve starts (backend/cuda/cuda_libraries.hpp), so
# ldd does not list them: each is looked for on the library path, then anywhere.
on_library_path() {
  local d
  for d in ${LD_LIBRARY_PATH//:/ }; do [[ -e "$d/$1" ]] && return 0; done
  ldconfig -p 2>/dev/null | grep -q "$1"
}
for lib in libcusparse.so.12 libcublas.so.13; do  # the CUDA runtime is linked statically
  if ! on_library_path "$lib"; then
    dir=$(dirname "$(find / -name "$lib" -not -path "*/proc/*" 2>/dev/null | head -1)")
    [[ "$dir" != "." ]] && export LD_LIBRARY_PATH="$LD_LIBRARY_PATH:$dir"
  fi
done
# The packed C++ runtime only if the system's is too old for the build.
if ! .device/bin/signorini --version > /dev/null 2>&1; then
  export LD_LIBRARY_PATH="$PWD/.device/lib-compat:$LD_LIBRARY_PATH"
fi
ldd .device/bin/signorini > "$out/ldd.txt" 2>&1
nvidia-smi > "$out/nvidia-smi.txt" 2>&1
.device/bin/signorini --version > "$out/version.txt" 2>&1
cat "$out/version.txt"
# Each step under its own time limit (seconds; the device allows 10 minutes a command), so that
# a hang in one still leaves the others' output in OUTDIR.
tests_limit="${DEVICE_TESTS_SECONDS:-180}"
bench_limit="${DEVICE_BENCH_SECONDS:-360}"
timeout -k 5 "$tests_limit" .device/bin/signorini_gpu_tests > "$out/gpu-tests.txt" 2>&1
echo "gpu tests: exit $? (124: over ${tests_limit} s)"
grep -E "^\[  (PASSED|SKIPPED|FAILED) +\] [0-9]+ test" "$out/gpu-tests.txt"
grep -E "^\[  FAILED  \] [A-Za-z]|: Failure$|graph capture failed" "$out/gpu-tests.txt" | head -20
# Optional (DEVICE_SANITIZER=1): the kernel tests under compute-sanitizer's memcheck, which
# reports out-of-bounds and misaligned device accesses that a passing test can hide. The
# allocation-failure test is left out: its deliberate out-of-memory is reported as an error.
if [[ "${DEVICE_SANITIZER:-0}" == 1 ]]; then
  sanitizer=$(command -v compute-sanitizer || echo /usr/local/cuda/bin/compute-sanitizer)
  if [[ -x "$sanitizer" ]]; then
    timeout -k 5 "${DEVICE_SANITIZER_SECONDS:-150}" "$sanitizer" --tool memcheck \
      --error-exitcode 3 .device/bin/signorini_gpu_tests --gtest_filter='GpuBackend.*:-GpuBackend.AllocationFailure*' \
      > "$out/sanitizer.txt" 2>&1
    echo "compute-sanitizer memcheck: exit $? (3: errors found; 124: over the limit)"
    tail -3 "$out/sanitizer.txt"
  else
    echo "compute-sanitizer: not found" | tee "$out/sanitizer.txt"
  fi
fi
timeout -k 5 "$bench_limit" .device/bin/signorini bench --device cuda \
  --repeats "${DEVICE_REPEATS:-3}" \
  --json "$out/bench-gpu.json" "${bench_args[@]}" > "$out/bench-gpu.txt" 2> "$out/bench-gpu.err"
echo "bench: exit $? (124: over ${bench_limit} s)"
cat "$out/bench-gpu.txt"
tail -5 "$out/bench-gpu.err"
