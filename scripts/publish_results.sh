#!/usr/bin/env bash
# Files a bench_smooth JSON under results/<device>/ (device from the JSON's
# gpu_name, e.g. "NVIDIA H200" -> h200; "cpu-<host>" without a GPU) and
# renders its tables and figures there.
set -euo pipefail
cd "$(dirname "$0")/.."
json=$1
device=$(/usr/bin/python3 -c '
import json, re, sys
ctx = json.load(open(sys.argv[1]))["context"]
name = ctx.get("gpu_name")
print(re.sub(r"[^a-z0-9]+", "-", name.lower().replace("nvidia", "")).strip("-") if name else "cpu-" + ctx.get("host_name", "unknown"))
' "$json")
dest=results/$device
mkdir -p "$dest"
cp "$json" "$dest/bench_smooth.json"
/usr/bin/python3 plots/report.py "$dest/bench_smooth.json" "$dest"
echo "results written to $dest"
