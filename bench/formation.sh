#!/usr/bin/env bash
# The formation delay study's speed (figures measured, never asserted;
# docs/formation.md, "The formation delay study"), interleaved in one run,
# 3 rounds: each law's study (65,536 two-drone flights of 90 s) on the cpu
# backend in float, and its cut to 4 link seeds (4,096 flights) on the cpu
# backend and on the scalar loop (one simulation at a time, one thread).
# Medians; the cpu backend's speed-up over the scalar loop on the same cut.
set -eo pipefail
BUILD=${1:-build}
source "$(dirname "$0")/workspace.sh"
SWEEP="$BUILD/devel/lib/aurora_sweep/sweep"
DIR=$(mktemp -d /tmp/aurora_formation_bench.XXXXXX)
for study in formation_delay formation_delay_ik; do
  cp "config/sweeps/$study.yaml" "$DIR/${study}_full.yaml"
  sed 's/repeats: 64/repeats: 4/' "config/sweeps/$study.yaml" > "$DIR/${study}_cut.yaml"
done
run() {  # study, size, backend
  "$SWEEP" --config "$DIR/$1_$2.yaml" --config-dir config --out "$DIR/out_$1_$2_$3" --overwrite \
    --backend "$3" --precision float --no-plots --quiet --output none > /dev/null
  python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(sys.argv[2], s["wall_time_s"], s["combinations"], s["feasible"], s["device"])' \
    "$DIR/out_$1_$2_$3/summary.json" "$1_$2_$3" >> "$DIR/times"
}
for round in 1 2 3; do
  for study in formation_delay formation_delay_ik; do
    run $study full cpu
    run $study cut cpu
    run $study cut scalar
  done
done
python3 - "$DIR/times" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, s, n, feasible, device = line.split(None, 4)
    runs.setdefault(name, []).append((float(s), int(n), int(feasible), device.strip()))
for study in ("formation_delay", "formation_delay_ik"):
    med = {k: statistics.median(t for t, _, _, _ in runs["%s_%s" % (study, k)]) for k in ("full_cpu", "cut_cpu", "cut_scalar")}
    full = runs[study + "_full_cpu"][0]
    print("%s: %d flights, %d feasible, cpu float %.2f s (%s, median of %d)" % (
        study, full[1], full[2], med["full_cpu"], full[3], len(runs[study + "_full_cpu"])))
    cut = runs[study + "_cut_cpu"][0]
    print("  cut to %d flights: cpu float %.3f s, scalar loop %.3f s: %.1fx" % (
        cut[1], med["cut_cpu"], med["cut_scalar"], med["cut_scalar"] / med["cut_cpu"]))
PY
rm -rf "$DIR"
