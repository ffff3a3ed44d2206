#!/usr/bin/env bash
# Files a bench_smooth result under results/<device>/ and renders its tables
# and figures there.
#
#   scripts/publish_results.sh [--dest DIR] [--logs DIR] BENCH.json [FLOAT.json]
#
# <device> is the GPU model in the JSON's gpu_name without "NVIDIA", as a
# slug ("NVIDIA H100 80GB HBM3" -> h100-80gb-hbm3, "NVIDIA H100 PCIe" ->
# h100-pcie, so different boards never share a folder), or cpu-<host> for a
# run without a GPU; --dest names the folder instead. FLOAT.json (the float
# run) is filed beside it as bench_float.json. --logs DIR copies the GPU
# test and sanitizer logs, device.txt and run.txt of a device_run.sh output
# folder.
#
# The tables and figures are rendered into a fresh folder first; only when
# that succeeds do they replace the destination's result files, so a bad
# JSON leaves the old results whole, and files of an earlier run that this
# one does not produce (an old bench_float.json, a figure) do not linger
# beside it. The logs are replaced only with --logs. Other files there
# (Nsight Compute reports, notes) are kept. Paths are taken relative to the
# current folder; exit status 2 on bad arguments or input.
set -euo pipefail
usage() { echo "usage: $0 [--dest DIR] [--logs DIR] BENCH.json [FLOAT.json]" >&2; exit 2; }
fail() { echo "publish_results: $*" >&2; exit 2; }
# Paths are the caller's, resolved before the script moves to the repository.
absolute() { realpath -m -- "$1"; }
dest='' logs=''
while [ $# -gt 0 ]; do
  case $1 in
    --dest) [ $# -ge 2 ] && [ -n "$2" ] || usage; dest=$(absolute "$2"); shift 2 ;;
    --logs) [ $# -ge 2 ] && [ -n "$2" ] || usage; logs=$(absolute "$2"); shift 2 ;;
    -*) usage ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] && [ $# -le 2 ] || usage
[ -n "$1" ] || usage
json=$(absolute "$1") float=''
if [ $# -eq 2 ]; then [ -n "$2" ] || usage; float=$(absolute "$2"); fi
for f in "$json" ${float:+"$float"}; do
  [ -s "$f" ] || fail "$f is missing or empty (did any benchmark run?)"
done
log_files=(gpu_tests.log sanitizers.log device.txt run.txt)
if [ -n "$logs" ]; then
  found=0
  for f in "${log_files[@]}"; do [ ! -f "$logs/$f" ] || found=1; done
  [ $found -eq 1 ] || fail "--logs $logs holds none of ${log_files[*]}"
fi
cd "$(dirname "$0")/.."
# Each result is read before anything is staged: a message then names the
# caller's file, not the staged copy, and a FLOAT.json that report.py never
# renders is not filed when it is cut off or not benchmark JSON.
for f in "$json" ${float:+"$float"}; do
  /usr/bin/python3 -c '
import sys
sys.path.insert(0, "plots")
import bench_json
try:
    bench_json.load_result(sys.argv[1], need_runs=True)
except bench_json.BenchInputError as error:
    sys.exit(f"publish_results: {error}")
' "$f" || exit 2
done
if [ -z "$dest" ]; then
  device=$(/usr/bin/python3 -c '
import json, re, sys
try:
    ctx = json.load(open(sys.argv[1])).get("context", {})
except (OSError, ValueError) as error:
    sys.exit(f"publish_results: {sys.argv[1]}: not benchmark JSON: {error}")
name = ctx.get("gpu_name")
model = re.sub(r"\bnvidia\b", "", name.lower()) if name else "cpu " + ctx.get("host_name", "unknown")
print(re.sub(r"[^a-z0-9]+", "-", model).strip("-"))
' "$json") || exit 2
  dest=results/$device
fi
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
cp "$json" "$stage/bench_smooth.json"
[ -z "$float" ] || cp "$float" "$stage/bench_float.json"
if [ -n "$logs" ]; then
  for f in "${log_files[@]}"; do [ ! -f "$logs/$f" ] || cp "$logs/$f" "$stage/"; done
fi
# report.py lists what it writes; name the files where they will be.
/usr/bin/python3 plots/report.py "$stage/bench_smooth.json" "$stage" | sed "s#$stage#$dest#g"
mkdir -p "$dest"
if [ -f "$dest/bench_smooth.json" ]; then
  echo "replacing the results in $dest (git $(/usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["context"].get("git_sha", "?"))' "$dest/bench_smooth.json" 2>/dev/null || echo '?'))"
fi
# What a run produces; logs only when this run brings its own.
rm -f "$dest"/bench_smooth.json "$dest"/bench_float.json "$dest"/tables.md "$dest"/table*.csv \
      "$dest"/quality.csv "$dest"/runs.csv "$dest"/scaling.csv "$dest"/colours.csv "$dest"/phases.csv "$dest"/fig*.png
[ -z "$logs" ] || for f in "${log_files[@]}"; do rm -f "$dest/$f"; done
cp "$stage"/* "$dest"/
echo "results written to $dest"
