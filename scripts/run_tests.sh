#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds (with the CUDA
# backend when nvcc is found), runs every CTest test (GPU tests skip with
# their reason when there is no device) and the fuzzers for a bounded time.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
build=${BUILD_DIR:-build-tests}
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DTETSMOOTH_EXODUS=ON >/dev/null
cmake --build "$build" -j"$(nproc)"
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" --timeout 1500
FUZZ_SECONDS=${FUZZ_SECONDS:-15} scripts/run_fuzzers.sh
