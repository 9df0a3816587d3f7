#!/usr/bin/env bash
# Benchmark of the real-time loop (issue: real-time loop). Measured in one run:
#  - realtime mode: state rate over 30 s (target 30 Hz +- 1 %) and the
#    controller's latency from a state's arrival to its cmd_vel (p50, p99;
#    target p99 < 1 ms), seen by one probe process;
#  - lockstep mode: wall time of the 60 s mission and sim time / wall time
#    (target >= 60x), without recording.
# Usage: bench/realtime_loop.sh [BUILD_DIR]   (DURATION=30 by default)
set -eo pipefail
BUILD=${1:-build}
DURATION=${DURATION:-30}
export PATH=/usr/bin:/bin:$PATH
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"
PORT=${BENCH_PORT:-11392}
export ROS_MASTER_URI=http://localhost:$PORT
LOG=$(mktemp -d /tmp/aurora_bench.XXXXXX)
export ROS_LOG_DIR=$LOG

roscore -p "$PORT" > "$LOG/roscore.log" 2>&1 &
core=$!
trap 'kill $core 2>/dev/null; kill $launch 2>/dev/null; true' EXIT
sleep 2

echo "== realtime mode: ${DURATION} s"
roslaunch -p "$PORT" launch/sim.launch mode:=realtime delay:=5 sim_output:=log > "$LOG/realtime.log" 2>&1 &
launch=$!
sleep 3
rosrun aurora_tests latency_probe __ns:=/ardrone1 _duration:="$DURATION" > "$LOG/probe.json"
kill -INT $launch; wait $launch 2>/dev/null || true
python3 - "$LOG/probe.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
ok_rate = abs(r["state_rate_hz"] - 30.0) <= 0.3
print("state rate      %.3f Hz over %.1f s (%d states)  target 30 Hz +- 1 %%: %s" % (
    r["state_rate_hz"], r["duration_s"], r["states"], "met" if ok_rate else "NOT met"))
print("latency         p50 %.3f ms  p99 %.3f ms  max %.3f ms (%d samples)  target p99 < 1 ms: %s" % (
    r["latency_p50_ms"], r["latency_p99_ms"], r["latency_max_ms"], r["latency_samples"],
    "met" if r["latency_p99_ms"] < 1.0 else "NOT met"))
PY

echo "== lockstep mode: 60 s mission, no recording"
roslaunch -p "$PORT" launch/sim.launch mode:=lockstep delay:=5 stop_after:=60 > "$LOG/lockstep.log" 2>&1 &
launch=$!
wait $launch || true
line=$(grep -h "stop_after .* reached" "$LOG/lockstep.log" "$LOG"/*/*.log 2>/dev/null | head -1)
python3 - "$line" <<'PY'
import re, sys
m = re.search(r"after (\d+) steps in ([0-9.]+) s wall \(sim time / wall time = ([0-9.]+)\)", sys.argv[1])
if not m:
    sys.exit("lockstep: no timing line found")
steps, wall, ratio = int(m.group(1)), float(m.group(2)), float(m.group(3))
print("lockstep        %d steps (60 s) in %.3f s wall: sim/wall = %.1fx  target >= 60x: %s" % (
    steps, wall, ratio, "met" if ratio >= 60 else "NOT met"))
PY
echo "logs: $LOG"
