#!/usr/bin/env bash
# Builds the GPU bundle on this machine (which has nvcc but no GPU): sm_90
# binaries in gpu-bundle/ with the shared libraries the GPU machine lacks
# (Google Benchmark as Debian names it, TetGen, the CUDA runtime, OpenMP;
# zlib and liblzma too, to be safe, though every Linux has them) beside
# them, found through RPATH $ORIGIN. Then hand gpu-bundle/ to the device
# tool's `carry` and run scripts/device_run.sh there.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build-gpu}
bundle=gpu-bundle
# Without Exodus II: netCDF's libraries (HDF5, curl, ICU, ...) are missing
# on the GPU machine and too many to carry.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DTETSMOOTH_CUDA=ON -DCMAKE_CUDA_ARCHITECTURES=90 \
  -DTETSMOOTH_EXODUS=OFF -DCMAKE_BUILD_RPATH='$ORIGIN' -DCMAKE_BUILD_RPATH_USE_ORIGIN=ON >/dev/null
cmake --build "$build" -j"$(nproc)" --target bench_smooth test_gpu_smoother test_gpu_topology tetsmooth
rm -rf "$bundle"
mkdir -p "$bundle"
cp "$build"/bench/bench_smooth "$build"/tests/test_gpu_smoother "$build"/tests/test_gpu_topology "$build"/apps/tetsmooth \
  "$bundle"/
for lib in libbenchmark.so.1debian libtet.so.1.5 libcudart.so.13 libgomp.so.1 libz.so.1 liblzma.so.5; do
  path=$(ldd "$bundle"/bench_smooth | awk -v l="$lib" '$1 == l {print $3}')
  [ -n "$path" ] || path=$(ldconfig -p | awk -v l="$lib" '$1 == l && !found {print $NF; found = 1}')  # no early exit: that would end ldconfig with SIGPIPE, which pipefail turns into a silent stop
  [ -n "$path" ] || { echo "gpu_bundle: $lib not found" >&2; exit 1; }
  cp -L "$path" "$bundle/$lib"
done
cp scripts/device_run.sh scripts/run_on_pty.py "$bundle"/
scripts/git_version.sh > "$bundle"/GIT_SHA
du -sh "$bundle"
