#!/usr/bin/env bash
# Runs every gtest and rostest of the workspace (built in $1) one after
# another (each rostest starts its own roscore) and fails on any failure.
set -o pipefail
BUILD=${1:-build}
export PATH=/usr/bin:/bin:$PATH
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"
export ROS_LOG_DIR=${ROS_LOG_DIR:-$PWD/$BUILD/ros_log}
rm -rf "$BUILD/test_results"
start=$(date +%s)
make -C "$BUILD" run_tests -j1 2>&1 | grep -vE "^make\[|^\[ *[0-9]+%\]|Built target"
summary=$(catkin_test_results "$BUILD/test_results" --all 2>&1)
rc=$?
echo "$summary" | grep -vE "^Skipping" | tail -40
echo "test time: $(( $(date +%s) - start )) s"
# A plain closing line for CI: N passed, N failed.
line=$(echo "$summary" | grep -E "^Summary:" | tail -1)
total=$(echo "$line" | sed -nE 's/.* ([0-9]+) tests.*/\1/p')
errors=$(echo "$line" | sed -nE 's/.* ([0-9]+) errors.*/\1/p')
failures=$(echo "$line" | sed -nE 's/.* ([0-9]+) failures.*/\1/p')
skipped=$(echo "$line" | sed -nE 's/.* ([0-9]+) skipped.*/\1/p')
if [ -z "$total" ]; then
  echo "no test results found"
  echo "0 passed, 1 failed"
  exit 1
fi
failed=$(( errors + failures ))
echo "$(( total - failed - skipped )) passed, $failed failed, $skipped skipped"
[ "$rc" -eq 0 ] && [ "$failed" -eq 0 ]
