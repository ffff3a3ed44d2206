#!/usr/bin/env bash
# Files a bench_smooth JSON under results/<device>/ (device: the model in the
# JSON's gpu_name, e.g. "NVIDIA H100 80GB HBM3" -> h100; "cpu-<host>" without
# a GPU) and renders its tables and figures there. A second JSON (the float
# run, bench_float.json) is copied beside it when given.
set -euo pipefail
cd "$(dirname "$0")/.."
json=$1
device=$(/usr/bin/python3 -c '
import json, re, sys
ctx = json.load(open(sys.argv[1]))["context"]
name = ctx.get("gpu_name")
model = name.lower().replace("nvidia", "").split() if name else []
print(re.sub(r"[^a-z0-9]+", "-", model[0]).strip("-") if model else "cpu-" + ctx.get("host_name", "unknown"))
' "$json")
dest=results/$device
mkdir -p "$dest"
cp "$json" "$dest/bench_smooth.json"
if [ $# -ge 2 ]; then cp "$2" "$dest/bench_float.json"; fi
/usr/bin/python3 plots/report.py "$dest/bench_smooth.json" "$dest"
echo "results written to $dest"
