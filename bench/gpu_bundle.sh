#!/usr/bin/env bash
# Copies the shared libraries that the sweep program and the CUDA gtests
# need (as ldd resolves them here; the C library and the dynamic loader
# stay the GPU machine's) into DIR, for bench/gpu_check.sh on a GPU machine
# without ROS: run there with LD_LIBRARY_PATH=DIR.
# Usage: bench/gpu_bundle.sh BUILD_DIR DIR
set -eo pipefail
BUILD=${1:-build}
DIR=${2:-gpu_libs}
mkdir -p "$DIR"
BIN=$BUILD/devel/lib/aurora_sweep
for exe in "$BIN/sweep" "$BIN/test_sweep_cuda" "$BIN"/lib*.so; do
  [ -e "$exe" ] || continue
  ldd "$exe" | awk '/=> \// {print $3}'
done | sort -u | grep -vE '/(libc|libm|libpthread|libdl|librt|libresolv|ld-linux[^/]*)\.so' |
  while read -r lib; do cp -L "$lib" "$DIR/"; done
du -sh "$DIR"
