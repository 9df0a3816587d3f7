#!/usr/bin/env bash
# What ptxas makes of every sweep kernel instantiation (each law, vehicle,
# formation shape, precision, history capacity, link: ideal or each thread's
# link model, and the predictor): registers per thread, stack frame (the
# delay history and a link's channels live there) and spills. Needs nvcc
# only, no GPU (about 10 minutes on 2 cores). Registers bound how many
# threads an SM keeps resident; spills mean local-memory traffic per step.
# Fails when no kernel is recognised (a renamed kernel must not print an
# empty table).
# Usage: bench/cuda_registers.sh [ARCH] [PTXAS_LOG]   (default sm_90, the H100/H200)
#   PTXAS_LOG: read a saved `nvcc -Xptxas -v` log instead of compiling.
set -eo pipefail
ARCH=${1:-sm_90}
NVCC=$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)
cd "$(dirname "$0")/.."
if [ -n "$2" ]; then
  LOG=$2
else
  LOG=$(mktemp /tmp/aurora_ptxas.XXXXXX)
  trap 'rm -f "$LOG"' EXIT
  "$NVCC" -c aurora_sweep/cuda/cuda_backend.cu -o /dev/null -arch="$ARCH" --fmad=false -O3 -std=c++14 \
    -Xptxas -v -Iaurora_sweep/include -Iaurora_control/include -Iaurora_sim/include -Iaurora_common/include \
    > "$LOG" 2>&1 || { cat "$LOG"; exit 1; }
fi
python3 bench/ptxas_table.py < "$LOG"
