#!/usr/bin/env bash
# The link model's cost (figures measured, never asserted), interleaved in
# one run: (1) the flight tool's time per step (law and model included) over
# the ideal link and over each shipped preset, 15 rounds each; (2) the
# thesis grid (65,536 runs) on the cpu backend's SIMD lanes over the ideal
# link and over wifi_lab, in double and float, 3 rounds each. Medians and
# their ratio to the ideal link's.
set -eo pipefail
BUILD=${1:-build}
source "$(dirname "$0")/workspace.sh"
FLIGHT="$BUILD/devel/lib/aurora_control/flight"
OUT=$(mktemp /tmp/aurora_links.XXXXXX)
for round in $(seq 15); do
  for link in ideal tum_ardrone wifi_lab wifi_congested; do
    us=$("$FLIGHT" --link "config/links/$link.yaml" | sed -nE 's/.*\(([0-9.]+) us per step.*/\1/p')
    echo "$link $us" >> "$OUT"
  done
done
python3 - "$OUT" <<'PY'
import statistics, sys
times = {}
for line in open(sys.argv[1]):
    name, us = line.split()
    times.setdefault(name, []).append(float(us))
ideal = statistics.median(times["ideal"])
for name, ts in times.items():
    m = statistics.median(ts)
    print("flight, mission4, PD law, link %-15s median %.3f us per step (%d rounds), %.2fx the ideal link" % (
        name + ":", m, len(ts), m / ideal))
PY
rm -f "$OUT"

SWEEP="$BUILD/devel/lib/aurora_sweep/sweep"
DIR=$(mktemp -d /tmp/aurora_links_sweep.XXXXXX)
cp config/sweeps/positioning_delay.yaml "$DIR/ideal.yaml"
{ cat config/sweeps/positioning_delay.yaml; echo "  link: links/wifi_lab.yaml"; } > "$DIR/wifi_lab.yaml"
for round in 1 2 3; do
  for precision in double float; do
    for link in ideal wifi_lab; do
      "$SWEEP" --config "$DIR/$link.yaml" --config-dir config --out "$DIR/out_${link}_$precision" --overwrite \
        --backend cpu --precision $precision --no-plots --quiet > /dev/null
      python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(sys.argv[2], s["wall_time_s"], s["feasible"], s["device"])' \
        "$DIR/out_${link}_$precision/summary.json" "${link}_$precision" >> "$DIR/times"
    done
  done
done
python3 - "$DIR/times" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, s, feasible, device = line.split(None, 3)
    runs.setdefault(name, []).append((float(s), int(feasible), device.strip()))
for precision in ("double", "float"):
    ideal = statistics.median(t for t, _, _ in runs["ideal_" + precision])
    for link in ("ideal", "wifi_lab"):
        r = runs["%s_%s" % (link, precision)]
        m = statistics.median(t for t, _, _ in r)
        print("thesis grid, cpu %s, link %-9s median %.3f s (%d rounds), %.2fx the ideal link, %d feasible, %s" % (
            precision, link + ":", m, len(r), m / ideal, r[0][1], r[0][2]))
PY
rm -rf "$DIR"
