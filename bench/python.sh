#!/usr/bin/env bash
# `import aurora`'s cost (figures measured, never asserted): aurora.simulate
# of a 60 s flight; aurora.sweep against the sweep program on the thesis grid
# (65,536 runs, cpu backend), interleaved in one run; the peak memory of
# aurora.sweep returning the 1,048,576 results of a 64 x 64 x 256 grid.
set -eo pipefail
BUILD=${1:-build}
source "$(dirname "$0")/workspace.sh"
exec /usr/bin/python3 bench/python_speed.py
