#!/usr/bin/env bash
# Runs on a machine with an NVIDIA GPU, from the repository root, with .device/ packed by
# scripts/device-pack.sh: the GPU tests, --version and the GPU benchmark, each writing its
# output into OUTDIR (docs/gpu.md).
#   bash scripts/device-run.sh OUTDIR [bench arguments...]   (default: --huge --largest)
set -uo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: device-run.sh OUTDIR [bench arguments]}"
shift
bench_args=("$@")
[[ ${#bench_args[@]} -gt 0 ]] || bench_args=(--huge --largest)
mkdir -p "$out"
export LD_LIBRARY_PATH="$PWD/.device/lib:/usr/local/cuda/lib64${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
nvidia-smi > "$out/nvidia-smi.txt" 2>&1
.device/bin/signorini --version > "$out/version.txt" 2>&1
cat "$out/version.txt"
.device/bin/signorini_gpu_tests > "$out/gpu-tests.txt" 2>&1
echo "gpu tests: exit $?"
tail -5 "$out/gpu-tests.txt"
.device/bin/signorini bench --device cuda --repeats 3 --json "$out/bench-gpu.json" \
  "${bench_args[@]}" > "$out/bench-gpu.txt" 2> "$out/bench-gpu.err"
echo "bench: exit $?"
cat "$out/bench-gpu.txt"
