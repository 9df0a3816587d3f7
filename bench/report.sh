#!/usr/bin/env bash
# Benchmark of the bag report: records the 60 s four-waypoint mission (one
# drone, lockstep, delay 10) and times `report` on it, video included
# (target: under 30 s wall).
# Usage: bench/report.sh [BUILD_DIR]
set -eo pipefail
BUILD=${1:-build}
export PATH=/usr/bin:/bin:$PATH
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"
OUT=$(mktemp -d /tmp/aurora_report_bench.XXXXXX)
export ROS_LOG_DIR=$OUT/ros_log
PORT=${BENCH_PORT:-11395}
export ROS_MASTER_URI=http://localhost:$PORT
roscore -p "$PORT" > "$OUT/roscore.log" 2>&1 &
core=$!
trap 'kill $core 2>/dev/null; true' EXIT
sleep 2
roslaunch -p "$PORT" launch/sim.launch mode:=lockstep delay:=10 record:=true bag_dir:="$OUT" \
  bag_name:=bench stop_after:=60 sim_output:=log > "$OUT/launch.log" 2>&1 || true
bag=$(ls -t "$OUT"/bench_*.bag | head -1)
start=$(date +%s.%N)
rosrun aurora report "$bag" --out "$OUT/report" 2> "$OUT/report.log"
end=$(date +%s.%N)
python3 - "$OUT/report/metrics.json" "$start" "$end" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))["drones"][0]
wall = float(sys.argv[3]) - float(sys.argv[2])
print("report of a %.1f s one-drone bag (%d steps): %.1f s wall including a %d-frame video; target < 30 s: %s" % (
    m["duration_s"], m["steps"], wall, m["video_frames"], "met" if wall < 30 else "NOT met"))
PY
echo "output: $OUT/report"
