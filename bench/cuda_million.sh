#!/usr/bin/env bash
# A million three-drone flights (bench/sweeps/triangle_1m.yaml) as one
# sweep on each backend given (default: cuda float and double, then the cpu
# backend on every core, side by side in one run): wall and compute time,
# flights per second, and the feasible count (the same flights: the counts
# agree to the few runs on the edge of a check). No results written
# (--output none).
# Usage: bench/cuda_million.sh [BUILD_DIR] [BACKEND:PRECISION ...]
set -eo pipefail
BUILD=${1:-build}
shift || true
RUNS=${*:-cuda:float cuda:double cpu:float}
BIN=${AURORA_SWEEP_BIN:-$BUILD/devel/lib/aurora_sweep/sweep}
CONFIG=${AURORA_CONFIG_DIR:-config}
OUT=$(mktemp -d /tmp/aurora_million.XXXXXX)
trap 'rm -rf "$OUT"' EXIT
printf "%-8s %-7s %9s %11s %13s %9s\n" backend type "wall[s]" "compute[s]" "flights/s" feasible
for run in $RUNS; do
  b=${run%%:*} p=${run##*:}
  if ! "$BIN" --config "${AURORA_MILLION_FILE:-bench/sweeps/triangle_1m.yaml}" --config-dir "$CONFIG" --out "$OUT/$b-$p" --backend "$b" \
       --precision "$p" --output none --no-plots --quiet --overwrite > /dev/null 2> "$OUT/err"; then
    echo "$b $p: not measured: $(tail -1 "$OUT/err")"
    continue
  fi
  python3 - "$OUT/$b-$p/summary.json" "$b" "$p" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timing"]
print("%-8s %-7s %9.2f %11.2f %13.0f %9d" % (sys.argv[2], sys.argv[3], s["wall_time_s"], t["compute_s"],
      s["combinations"] / s["wall_time_s"], s["feasible"]))
PY
done
