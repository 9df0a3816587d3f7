#!/usr/bin/env bash
# Each vehicle's speed on the SIMD engine per simulated robot-second (issue
# 33: the Bebop 2 and the Pioneer, simpler models, at least as fast as the
# AR.Drone), measured side by side in one run, never asserted: each
# vehicle's delay study (the AR.Drone's thesis grid, bebop2_delay,
# pioneer_delay) without early stop (every run flies its whole 60 s) on the
# cpu backend, in float and in double, ROUNDS rounds interleaved. Prints per
# study the median simulated robot-seconds per second (control steps per
# second x Ts) and its ratio to the AR.Drone's.
# Usage: bench/vehicles.sh [BUILD] [ROUNDS]
set -eo pipefail
BUILD=$(cd "${1:-build}" && pwd)
ROUNDS=${2:-3}
source "$(dirname "$0")/workspace.sh"
SWEEP="$BUILD/devel/lib/aurora_sweep/sweep"
DIR=$(mktemp -d /tmp/aurora_vehicles_bench.XXXXXX)
STUDIES="positioning_delay bebop2_delay pioneer_delay"
for study in $STUDIES; do
  sed 's/early_stop: true/early_stop: false/' "config/sweeps/$study.yaml" > "$DIR/$study.yaml"
done
echo "vehicles: $ROUNDS rounds, $(nproc) threads, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
for precision in float double; do
  for round in $(seq "$ROUNDS"); do
    for study in $STUDIES; do
      out="$DIR/out_${study}_$precision"
      "$SWEEP" --config "$DIR/$study.yaml" --config-dir config --out "$out" --overwrite --backend cpu \
        --precision "$precision" --no-plots --quiet --output none > /dev/null
      python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(sys.argv[2], sys.argv[3], s["control_steps_per_s"], s["control_steps"], s["combinations"], s["device"])' \
        "$out/summary.json" "$study" "$precision" >> "$DIR/times"
    done
  done
done
python3 - "$DIR/times" <<'PY'
import statistics, sys
ts = {"positioning_delay": 1 / 30, "bebop2_delay": 1 / 30, "pioneer_delay": 0.1}
vehicle = {"positioning_delay": "AR.Drone 2.0", "bebop2_delay": "Bebop 2", "pioneer_delay": "Pioneer P3-DX"}
rate = {}
for line in open(sys.argv[1]):
    study, precision, steps_per_s, steps, combinations, device = line.split(None, 5)
    rate.setdefault((study, precision), []).append(float(steps_per_s) * ts[study])
    rate[(study, precision, "info")] = (int(combinations), int(steps), device.strip())
for precision in ("float", "double"):
    base = statistics.median(rate[("positioning_delay", precision)])
    for study in ("positioning_delay", "bebop2_delay", "pioneer_delay"):
        med = statistics.median(rate[(study, precision)])
        n, steps, device = rate[(study, precision, "info")]
        print("%-6s %-14s %-18s %6d flights, %9d steps: %.3g robot-s/s (%.2fx the AR.Drone's) [%s]" % (
            precision, vehicle[study], study, n, steps, med, med / base, device))
PY
rm -rf "$DIR"
