#!/usr/bin/env bash
# Runs every gtest and rostest of the workspace (built in $1), TEST_JOBS at
# a time (twice the cores by default, at most 8; each rostest starts its own roscore on a free port) and
# fails on any failure.
set -o pipefail
BUILD=${1:-build}
export PATH=/usr/bin:/bin:$PATH
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"
export ROS_LOG_DIR=${ROS_LOG_DIR:-$PWD/$BUILD/ros_log}
# The rostests' bags, in this build (two checkouts' runs at once on one
# machine would share /tmp/aurora_tests, the tests' default).
export AURORA_TEST_BAG_DIR=${AURORA_TEST_BAG_DIR:-$(cd "$BUILD" && pwd)/test_bags}
# Most rostests wait for simulated time in real time (the CPU is idle for much
# of a run): twice the cores, at most 8, keeps the machine busy.
cores=$(nproc 2>/dev/null || echo 2)
default_jobs=$(( 2 * cores > 8 ? 8 : 2 * cores ))
jobs=${TEST_JOBS:-$default_jobs}
if ! [[ "$jobs" =~ ^[1-9][0-9]*$ ]]; then
  echo "TEST_JOBS=$jobs is not a number of tests at a time: use TEST_JOBS=1, 2, ..." >&2
  exit 2
fi
rm -rf "$BUILD/test_results"
start=$(date +%s)
make -C "$BUILD" run_tests -j"$jobs" 2>&1 | grep -vE "^make\[|^\[ *[0-9]+%\]|Built target"
summary=$(catkin_test_results "$BUILD/test_results" --all 2>&1)
rc=$?
# The files with errors or failures (catkin_test_results prints counts only
# then), and why each failed test failed, last, where a CI log's tail shows it.
echo "$summary" | grep -E "errors|^Summary:"
if [ "$rc" -ne 0 ]; then
  echo "why they failed (the results are in $BUILD/test_results, the nodes' logs in $ROS_LOG_DIR):"
  /usr/bin/python3 "$(dirname "$0")/print_test_failures.py" "$BUILD/test_results" --lines 15
fi
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
