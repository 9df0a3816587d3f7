#!/usr/bin/env bash
# What ptxas makes of the sweep kernel, per instantiation (law x precision x
# history capacity x link: ideal, or each thread's link model): registers per
# thread, stack frame (the delay history and a link's channels live there)
# and spills. Needs nvcc only, no GPU. Registers bound how many
# threads an SM keeps resident; spills mean local-memory traffic per step.
# Usage: bench/cuda_registers.sh [ARCH]   (default sm_90, the H100)
set -eo pipefail
ARCH=${1:-sm_90}
NVCC=$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)
cd "$(dirname "$0")/.."
"$NVCC" -c aurora_sweep/cuda/cuda_backend.cu -o /dev/null -arch="$ARCH" --fmad=false -O3 -std=c++14 \
  -Xptxas -v -Iaurora_sweep/include -Iaurora_control/include -Iaurora_sim/include -Iaurora_common/include 2>&1 |
python3 -c '
import re, sys
law = {"0": "pd_saturated", "1": "underactuated"}
kernel = None
print("%-14s %-6s %8s %-6s %9s %11s %13s" % ("law", "type", "capacity", "link", "registers", "stack [B]",
                                              "spills st/ld"))
for line in sys.stdin:
    m = re.search(r"sweepKernelILN14aurora_control7LawTypeE(\d)E(\w)Li(\d+)ELb(\d)E", line)
    if m:
        kernel = (law[m.group(1)], {"d": "double", "f": "float"}[m.group(2)], m.group(3),
                  "model" if m.group(4) == "1" else "ideal")
        continue
    m = re.search(r"(\d+) bytes stack frame, (\d+) bytes spill stores, (\d+) bytes spill loads", line)
    if m and kernel:
        frame = m.groups()
        continue
    m = re.search(r"Used (\d+) registers", line)
    if m and kernel:
        print("%-14s %-6s %8s %-6s %9s %11s %13s" % (kernel + (m.group(1), frame[0], frame[1] + "/" + frame[2])))
        kernel = None
'
