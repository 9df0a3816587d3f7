#!/usr/bin/env bash
# The control laws side by side (figures measured, never asserted): cost per
# call of every law this build knows (scalar double, same run, each on its
# own vehicle's flight: law_cost), and lockstep speed of the whole ROS loop
# with each AR.Drone law (60 s mission4, sim + controller).
set -eo pipefail
BUILD=${1:-build}
source "$(dirname "$0")/workspace.sh"
"$BUILD/devel/lib/aurora_control/law_cost"
LOG=$(mktemp -d /tmp/aurora_laws.XXXXXX)
for law in pd_saturated underactuated; do
  # The sim logs the wall time from its first step to stop_after.
  ROS_LOG_DIR=$LOG/$law roslaunch launch/sim.launch mode:=lockstep stop_after:=60 controller:=$law delay:=5 \
    > "$LOG/$law.log" 2>&1 || true
  line=$(grep -rh "stop_after .* reached" "$LOG/$law.log" "$LOG/$law" 2>/dev/null | head -1)
  python3 - "$law" "$line" <<'PY'
import re, sys
m = re.search(r"after (\d+) steps in ([0-9.]+) s wall \(sim time / wall time = ([0-9.]+)\)", sys.argv[2])
if not m:
    sys.exit("lockstep %s: no timing line found" % sys.argv[1])
print("lockstep 60 s mission4, delay 5, %-14s %s steps in %.3f s wall: %.0fx real time" % (
    sys.argv[1] + ":", m.group(1), float(m.group(2)), float(m.group(3))))
PY
done
echo "logs: $LOG"
