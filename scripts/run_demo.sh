#!/usr/bin/env bash
# The main job: fly the thesis's four-waypoint mission with a feedback delay
# in lockstep, record a bag, and write a report (metrics, figures, video) to
# out/. Usage: run_demo.sh BUILD_DIR   (env: DELAY samples, default 10)
set -eo pipefail
BUILD=${1:-build}
DELAY=${DELAY:-10}
OUT=${OUT:-out}
export PATH=/usr/bin:/bin:$PATH
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"
export ROS_LOG_DIR=${ROS_LOG_DIR:-$PWD/$OUT/ros_log}
mkdir -p "$OUT/bags"
# A private master port, so a roscore the user already runs is left alone.
export ROS_MASTER_URI=http://localhost:${DEMO_PORT:-11391}

echo "demo: flying mission4 with a delay of $DELAY samples ($(python3 -c "print(round($DELAY/30, 4))") s), lockstep, recording to $OUT/bags"
start=$(date +%s.%N)
# aurora_launch (package aurora_bringup): roslaunch that starts its own master
# on the port, ends quietly when the sim stops at stop_after, and returns
# non-zero, naming the node, when one fails (plain roslaunch returns 0).
rosrun aurora_bringup aurora_launch -p "${DEMO_PORT:-11391}" aurora_bringup sim.launch mode:=lockstep \
  task:=mission4 delay:="$DELAY" record:=true bag_dir:="$PWD/$OUT/bags" bag_name:=demo stop_after:=60 \
  sim_output:=log > "$OUT/demo_launch.log" 2>&1 || {
  grep -E "FAILED|FATAL|ERROR" "$OUT/demo_launch.log" >&2
  echo "demo: the launch failed, see $OUT/demo_launch.log" >&2
  exit 1
}
grep -h "mission complete" "$OUT/demo_launch.log" | sed -E 's/\x1b\[[0-9;]*m//g; s/^.*controller: /demo: controller: /' || true
end=$(date +%s.%N)
bag=$(ls -t "$OUT"/bags/demo_*.bag 2>/dev/null | head -1)
[ -n "$bag" ] || { echo "demo: no bag was written, see $OUT/demo_launch.log" >&2; exit 1; }
echo "demo: 60 s mission flown in $(python3 -c "print(round($end-$start, 2))") s wall; bag $bag"
rm -rf "$OUT/report"
rosrun aurora report "$bag" --out "$OUT/report"
python3 - "$OUT/report/metrics.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))["drones"][0]
print("demo: %s delay %d samples (%.3f s), Kp %g Kd %g" % (m["namespace"], m["delay_samples"], m["delay_seconds"], m["kp"], m["kd"]))
print("demo: IAE %.4f  ITAE %.4f  IASC %.4f  max error %.3f m  final error %.4f m" % (
    m["iae"], m["itae"], m["iasc"], m["max_position_error_m"], m["final_position_error_m"]))
for s in m["segments"]:
    st = ("settled after %.2f s" % s["settling_time_s"] if s["settling_time_s"] is not None
          else "not settled (still swinging %.3f m at the end)" % s["final_swing_m"])
    print("demo:   waypoint %d: %s, overshoot %.1f %%, closest %.3f m" % (
        s["waypoint_index"] + 1, st, s["overshoot_percent"], s["closest_approach_m"]))
PY
echo "demo: report in $OUT/report/report.md"
