#!/usr/bin/env bash
# The cuda backend on the shipped studies through the program's own path
# (chunked, resumable, chunk size from the occupancy API), not a single
# kernel call: compute time, chunks, launch shape and simulations per second
# from summary.json, float and double. Needs a GPU; says so without one.
# Usage: bench/cuda_studies.sh [BUILD_DIR]
set -eo pipefail
BUILD=${1:-build}
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
[ -f "$BUILD/devel/setup.bash" ] && source "$BUILD/devel/setup.bash"
BIN=${AURORA_SWEEP_BIN:-$BUILD/devel/lib/aurora_sweep/sweep}
CONFIG=${AURORA_CONFIG_DIR:-config}
OUT=$(mktemp -d /tmp/aurora_cuda_bench.XXXXXX)
export PATH=/usr/bin:/bin:$PATH
printf "%-20s %-7s %10s %8s %10s %22s %12s\n" study precision "compute[s]" chunks "chunk" "launch" "sims/s"
for study in positioning_delay underactuated_13 robustness; do
  for p in float double; do
    if ! "$BIN" --config "$CONFIG/sweeps/$study.yaml" --config-dir "$CONFIG" --out "$OUT/$study-$p" \
         --backend cuda --precision "$p" --no-plots --quiet --overwrite > /dev/null 2> "$OUT/err"; then
      echo "cuda: not measured: $(tail -1 "$OUT/err")"
      exit 0
    fi
    python3 - "$OUT/$study-$p/summary.json" "$study" "$p" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
c = s["chunks"]
t = s["timing"]["compute_s"]
print("%-20s %-7s %10.3f %8d %10d %22s %12.0f" % (sys.argv[2], sys.argv[3], t, c["count"], c["size"],
      s.get("note", "").split("; ")[-1], s["combinations"] / t if t > 0 else 0))
PY
  done
done
rm -rf "$OUT"
