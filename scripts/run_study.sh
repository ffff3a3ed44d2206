#!/usr/bin/env bash
# The study: installs what is missing, builds, generates the paper's meshes
# (cached in meshes/), runs bench_smooth with repetitions and writes
# results/<device>/bench_smooth.json with its tables and figures.
#
#   scripts/run_study.sh [bench_smooth flags...]
#
# Environment: REPS (repetitions, default 3), BUILD_DIR (default build),
# TETSMOOTH_MESH_CACHE (default ./meshes). Flags are passed to bench_smooth
# after the defaults, so they win: e.g. --models=5k,109k, --no-cpu,
# --scaling=none (no lattice), --precision=float, --benchmark_filter=REGEX
# (bench_smooth --help lists them). On a machine without a GPU only the CPU families run (the lattice
# scaling mesh is GPU-only and is then not generated); for the GPU machine
# see scripts/gpu_bundle.sh and scripts/device_run.sh (README: Results).
set -euo pipefail
cd "$(dirname "$0")/.."
# Checked before the install and the build, which take minutes.
reps=${REPS:-3}
if ! [[ $reps =~ ^[1-9][0-9]*$ ]]; then
  echo "run_study: REPS must be a positive whole number of repetitions, got '$reps'" >&2
  exit 2
fi
scripts/install_deps.sh
build=${BUILD_DIR:-build}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target bench_smooth
export TETSMOOTH_MESH_CACHE=${TETSMOOTH_MESH_CACHE:-$PWD/meshes}
TETSMOOTH_GIT_SHA=$(scripts/git_version.sh)
export TETSMOOTH_GIT_SHA
tmp=$(mktemp -d)
# A failed run keeps what bench_smooth wrote, and says where; a run that
# wrote nothing (a bad flag, no benchmark selected) leaves no folder behind.
trap 'status=$?
if [ $status -eq 0 ]; then rm -rf "$tmp"
elif [ -s "$tmp/bench_smooth.json" ]; then echo "run_study: failed; raw results kept in $tmp/bench_smooth.json" >&2
else rm -rf "$tmp"; echo "run_study: failed before bench_smooth wrote any result" >&2; fi' EXIT
"$build"/bench/bench_smooth --scaling=lattice-215 --benchmark_repetitions="$reps" --benchmark_min_time=0.01 \
  --benchmark_out="$tmp/bench_smooth.json" --benchmark_out_format=json "$@"
# --help and --benchmark_list_tests=true succeed without a result: nothing to publish.
[ -s "$tmp/bench_smooth.json" ] || exit 0
scripts/publish_results.sh "$tmp/bench_smooth.json"
