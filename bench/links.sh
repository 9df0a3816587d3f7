#!/usr/bin/env bash
# The link model's cost in the offline runner (figures measured, never
# asserted): the flight tool's time per step (law and model included) over
# the ideal link and over each shipped preset, interleaved in one run, 15
# rounds each; the median and its ratio to the ideal link's.
set -eo pipefail
BUILD=${1:-build}
export PATH=/usr/bin:/bin:$PATH
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"
cd "$(dirname "$0")/.."
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
