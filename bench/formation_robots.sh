#!/usr/bin/env bash
# Robot-steps per second of AuRoRA's formations against the two-drone line
# (figures measured, never asserted; docs/formation.md, "Sweeps of AuRoRA's
# formations"), interleaved in one run, 3 rounds, medians: each study's
# first 4,096 flights (every flight to its end: early_stop false) on the
# cpu backend in float: the two-drone line (formation_delay.yaml, 90 s),
# the UAV-UGV line (line_pioneer_delay.yaml, 130 s) and the triangle of
# three AR.Drones (triangle_delay.yaml, 50 s); and what a million of the
# triangle's 50 s flights take at that speed on this machine.
set -eo pipefail
BUILD=${1:-build}
source "$(dirname "$0")/workspace.sh"
SWEEP="$BUILD/devel/lib/aurora_sweep/sweep"
DIR=$(mktemp -d /tmp/aurora_formation_robots.XXXXXX)
cp "config/sweeps/formation_delay.yaml" "$DIR/formation_delay.yaml"
sed -i 's/repeats: 64/repeats: 4\n  early_stop: false/' "$DIR/formation_delay.yaml"
sed 's/^  precision: float/  precision: float\n  early_stop: false/; s/formation_law: {values: \[N, PSO, SPO, OSP, S-PO\]}/formation_law: N/' \
  config/sweeps/triangle_delay.yaml > "$DIR/triangle_delay.yaml"
sed 's/^  precision: float/  precision: float\n  early_stop: false/; s/from: 0, to: 47, count: 48/from: 0, to: 31, count: 32/g; s/formation_k1_x: {values: \[0.4, 0.8, 1.6\]}/formation_k1_x: {values: [0.4, 0.8, 1.6, 3.2]}/; s/formation_k1_y: {values: \[0.4, 0.8, 1.6\]}/formation_k1_y: 0.8/' \
  config/sweeps/line_pioneer_delay.yaml > "$DIR/line_pioneer_delay.yaml"
run() {  # study, robots, seconds per flight
  "$SWEEP" --config "$DIR/$1.yaml" --config-dir config --out "$DIR/out_$1" --overwrite --backend cpu \
    --no-plots --quiet --output none > /dev/null
  python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(sys.argv[2], sys.argv[3], sys.argv[4], s["wall_time_s"], s["combinations"], s["device"])' \
    "$DIR/out_$1/summary.json" "$1" "$2" "$3" >> "$DIR/times"
}
for round in 1 2 3; do
  run formation_delay 2 90
  run line_pioneer_delay 2 130
  run triangle_delay 3 50
done
python3 - "$DIR/times" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, robots, seconds, wall, n, device = line.split(None, 5)
    runs.setdefault(name, []).append((float(wall), int(robots), float(seconds), int(n), device.strip()))
rate = {}
for name in ("formation_delay", "line_pioneer_delay", "triangle_delay"):
    wall = statistics.median(r[0] for r in runs[name])
    _, robots, seconds, n, device = runs[name][0]
    steps = n * round(seconds * 30) * robots
    rate[name] = steps / wall
    print("%s: %d flights of %g s, %d robots: %.3f s, %.3g robot-steps/s (%s, median of %d)" % (
        name, n, seconds, robots, wall, rate[name], device, len(runs[name])))
for name in ("line_pioneer_delay", "triangle_delay"):
    print("  %s against the two-drone line: %.2fx its robot-steps per second" % (name, rate[name] / rate["formation_delay"]))
per_flight = 1500 * 3 / rate["triangle_delay"]
print("a million three-drone 50 s flights at that speed: %.0f s" % (1e6 * per_flight))
PY
rm -rf "$DIR"
