#!/usr/bin/env bash
# Benchmark of sweeps at scale, measured side by side in one run on this
# machine: the 1,048,576-combination grid (bench/sweeps/grid_1m.yaml, float)
# on 1 MPI rank vs 2 ranks (2 cores either way); time simulating vs writing
# results.csv and results.h5 (rows per second of each writer); what making a
# run resumable costs (chunk files) and a run killed halfway then resumed.
# Usage: bench/sweep_scale.sh [BUILD_DIR] [SWEEP_FILE]
set -eo pipefail
BUILD=${1:-build}
SWEEP=${2:-bench/sweeps/grid_1m.yaml}
export PATH=/usr/bin:/bin:$PATH
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"
BIN=$BUILD/devel/lib/aurora_sweep/sweep
OUT=$(mktemp -d /tmp/aurora_sweep_scale.XXXXXX)
MPIRUN=(mpirun --allow-run-as-root --oversubscribe --bind-to none)
sweep() { "$BIN" --config "$SWEEP" --out "$OUT/$1" --backend cpu --no-plots --quiet "${@:2}" > /dev/null; }
echo "sweep scale benchmark: $SWEEP, $(nproc) cores"
start=$(date +%s.%N); "${MPIRUN[@]}" -np 1 "$BIN" --config "$SWEEP" --out "$OUT/rank1" --backend cpu --threads 2 \
  --no-plots --quiet --output hdf5 > /dev/null; end=$(date +%s.%N)
echo "1 rank x 2 threads: $(python3 -c "print(round($end - $start, 2))") s process wall"
start=$(date +%s.%N); "${MPIRUN[@]}" -np 2 "$BIN" --config "$SWEEP" --out "$OUT/rank2" --backend cpu --threads 1 \
  --no-plots --quiet --output hdf5 > /dev/null; end=$(date +%s.%N)
echo "2 ranks x 1 thread: $(python3 -c "print(round($end - $start, 2))") s process wall"
cmp "$OUT/rank1/results.h5" "$OUT/rank2/results.h5" && echo "results.h5 of 1 and 2 ranks: identical bytes"
python3 - "$OUT" <<'PY'
import sys, h5py, numpy as np
a, b = (h5py.File("%s/%s/results.h5" % (sys.argv[1], r), "r") for r in ("rank1", "rank2"))
print("columns equal for 1 and 2 ranks:", all(np.array_equal(a[k][...], b[k][...]) for k in a))
PY
sweep both --output both
# Killed halfway (SIGKILL at half of the chunks), then the same command again.
"$BIN" --config "$SWEEP" --out "$OUT/killed" --backend cpu --no-plots --quiet --output hdf5 --chunk-size 65536 > /dev/null &
pid=$!
while [ "$(ls "$OUT/killed/progress" 2>/dev/null | grep -c '\.bin$')" -lt 8 ]; do sleep 0.02; done
kill -KILL $pid; wait $pid 2>/dev/null || true
start=$(date +%s.%N); sweep killed --output hdf5 --chunk-size 65536; end=$(date +%s.%N)
echo "resumed after SIGKILL at 8 of 16 chunks: $(python3 -c "print(round($end - $start, 2))") s for the rest"
python3 - "$OUT" <<'PY'
import json, sys
out = sys.argv[1]
s = {n: json.load(open("%s/%s/summary.json" % (out, n))) for n in ("rank1", "rank2", "both", "killed")}
for n in ("rank1", "rank2"):
    r = s[n]
    print("%-6s %d ranks: simulate %.2f s (%.0f sims/s); per rank: %s" % (
        n, r.get("mpi", {}).get("ranks", 1), r["wall_time_s"], r["simulations_per_s"],
        ", ".join("rank %d %d chunks %.0f sims/s" % (p["rank"], p["chunks_computed"], p["simulations_per_s"])
                  for p in r.get("mpi", {}).get("per_rank", []))))
b = s["both"]
print("simulate %.2f s; chunk files (what resume costs) %.3f s" % (b["timing"]["compute_s"], b["timing"]["chunk_write_s"]))
for f, w in sorted(b["output"]["files"].items()):
    print("write %-12s %9d rows in %.3f s: %.3g rows/s" % (f, w["rows"], w["write_s"], w["rows_per_s"]))
k = s["killed"]["chunks"]
print("resumed run: %d chunks read back, %d computed (%d combinations)" % (k["resumed"], k["computed"], k["computed_combinations"]))
PY
echo "results: $OUT"
