#!/usr/bin/env bash
# Benchmark of the sweep on the thesis grid (65,536 simulations), measured in
# one run on this machine: the scalar backend on one thread, then the cpu
# backend on all cores in double and in float. Prints times, simulations and
# control steps per second, the ratios, the feasible counts, and how well the
# backends agree (flags, metrics, float vs double). With a usable GPU, the
# cuda backend too.
# Usage: bench/sweep.sh [BUILD_DIR] [SWEEP_FILE]
set -eo pipefail
BUILD=${1:-build}
SWEEP=${2:-config/sweeps/positioning_delay.yaml}
[ -f /opt/ros/noetic/setup.bash ] && source /opt/ros/noetic/setup.bash
source "$BUILD/devel/setup.bash"  # the sweep finds aurora_config through the package path
BIN=$BUILD/devel/lib/aurora_sweep/sweep
OUT=$(mktemp -d /tmp/aurora_sweep_bench.XXXXXX)
export PATH=/usr/bin:/bin:$PATH
THREADS=$(nproc)

run() {  # name backend precision threads
  "$BIN" --config "$SWEEP" --out "$OUT/$1" --backend "$2" --precision "$3" --threads "$4" --no-plots --quiet > /dev/null
}
echo "sweep benchmark: $SWEEP, $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs))"
run scalar_double scalar double 1
run cpu_double cpu double "$THREADS"
run cpu_float cpu float "$THREADS"
backends="scalar_double cpu_double cpu_float"
if "$BIN" --config "$SWEEP" --out "$OUT/cuda_double" --backend cuda --precision double --no-plots --quiet > /dev/null 2> "$OUT/cuda.err"; then
  run cuda_float cuda float 1
  backends="$backends cuda_double cuda_float"
else
  echo "cuda: not measured: $(tail -1 "$OUT/cuda.err")"
fi
python3 - "$OUT" $backends <<'PY'
import csv, json, sys
out, names = sys.argv[1], sys.argv[2:]
s = {n: json.load(open("%s/%s/summary.json" % (out, n))) for n in names}
base = s["scalar_double"]["wall_time_s"]
print("%-14s %9s %10s %12s %14s %8s %9s" % ("backend", "time [s]", "kernel [s]", "sims/s", "steps/s", "ratio", "feasible"))
for n in names:
    r = s[n]
    print("%-14s %9.3f %10s %12.0f %14.3g %7.1fx %9d   (%s, %d threads, %d lanes)" % (
        n, r["wall_time_s"], "%.4f" % r["kernel_time_s"] if "kernel_time_s" in r else "-",
        r["simulations_per_s"], r["control_steps_per_s"], base / r["wall_time_s"], r["feasible"],
        r["device"], r["threads"], r["lanes"]))
def rows(n):
    return list(csv.DictReader(open("%s/%s/results.csv" % (out, n))))
ref = rows("scalar_double")
flags = ("ok1", "ok2", "ok3", "ok4", "feasible")
for n in names[1:]:
    other = rows(n)
    if s[n]["precision"] == "double":
        flag_diff = sum(1 for a, b in zip(ref, other) if any(a[k] != b[k] for k in flags))
        worst = 0.0
        for a, b in zip(ref, other):
            if a["ok1"] == "1":
                for k in ("iae", "itae", "iasc"):
                    x, y = float(a[k]), float(b[k])
                    worst = max(worst, abs(x - y) / max(abs(x), 1e-300))
        print("%s vs scalar_double: %d combinations with a different flag, largest relative metric difference %.2e (non-diverged runs)" % (n, flag_diff, worst))
    else:
        agree = sum(1 for a, b in zip(ref, other) if a["feasible"] == b["feasible"])
        print("%s vs scalar_double: feasible flag agrees on %d of %d (%.4f %%)" % (n, agree, len(ref), 100.0 * agree / len(ref)))
PY
echo "results: $OUT"
