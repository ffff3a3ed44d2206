#!/usr/bin/env bash
# The study: installs what is missing, builds, generates the paper's meshes
# (cached in meshes/), runs bench_smooth with repetitions and writes
# results/<device>/bench_smooth.json with its tables and figures.
# On a machine without a GPU only the CPU families run; for the GPU machine
# see scripts/gpu_bundle.sh and scripts/device_run.sh (README: Results).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
build=${BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target bench_smooth
export TETSMOOTH_MESH_CACHE=${TETSMOOTH_MESH_CACHE:-$PWD/meshes}
tmp=$(mktemp -d)
"$build"/bench/bench_smooth --benchmark_repetitions="${REPS:-3}" --benchmark_min_time=0.01 \
  --benchmark_out="$tmp/bench_smooth.json" --benchmark_out_format=json "$@"
scripts/publish_results.sh "$tmp/bench_smooth.json"
