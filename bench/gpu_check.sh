#!/usr/bin/env bash
# Everything of the CUDA backend that needs a GPU, in one run: the device,
# the CUDA gtests with a device required (AURORA_REQUIRE_CUDA=1: a missing
# or unusable GPU fails instead of skipping), then the kernels on the
# shipped studies (bench/cuda_studies.sh). For a GPU machine without ROS:
# build here with the GPU's architecture (-DAURORA_CUDA_ARCHITECTURES=90
# for an H100/H200), copy the build's lib/aurora_sweep folder and the
# shared libraries its programs need (bench/gpu_bundle.sh), and run this
# there from the repository's root. Logs go to LOG_DIR.
# Usage: bench/gpu_check.sh BUILD_DIR LOG_DIR
set -o pipefail
BUILD=${1:-build}
LOG=${2:-/tmp/aurora_gpu_check}
mkdir -p "$LOG"
BIN=$BUILD/devel/lib/aurora_sweep
nvidia-smi --query-gpu=name,driver_version,compute_cap,memory.total,clocks.sm,clocks.max.sm --format=csv |
  tee "$LOG/device.txt"
rc=0
AURORA_REQUIRE_CUDA=1 "$BIN/test_sweep_cuda" --gtest_output="xml:$LOG/test_sweep_cuda.xml" > "$LOG/test_sweep_cuda.txt" 2>&1 || rc=1
grep -E "^\[( +OK|  FAILED|  PASSED|  SKIPPED) |Failure|device: " "$LOG/test_sweep_cuda.txt" | cut -c1-400
AURORA_SWEEP_BIN=$BIN/sweep ./bench/cuda_studies.sh "$BUILD" 2>&1 | tee "$LOG/cuda_studies.txt" || rc=1
exit $rc
