#!/usr/bin/env bash
# Speed of two builds of the sweep side by side, in one run on this machine
# (a change's "before" and "after"): the thesis grid on the cpu backend in
# double and in float, each build ROUNDS times, interleaved (old, new, old,
# new, ...) so that the machine's load falls on both alike. Prints each
# build's median wall time, the ratio new/old, and whether the results are
# the same bytes.
# Usage: bench/compare_builds.sh OLD_BUILD NEW_BUILD [ROUNDS] [SWEEP_FILE]
#   (a build folder each, as `make build` makes: BUILD/devel/lib/aurora_sweep/sweep)
set -eo pipefail
if [ $# -lt 2 ]; then
  sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
OLD=$1
NEW=$2
ROUNDS=${3:-5}
SWEEP=$4
source "$(dirname "$0")/two_builds.sh"
SWEEP=${SWEEP:-config/sweeps/positioning_delay.yaml}
OUT=$(mktemp -d /tmp/aurora_compare_builds.XXXXXX)
THREADS=$(nproc)
echo "compare builds: $SWEEP, $ROUNDS rounds, $THREADS threads, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
for precision in double float; do
  for r in $(seq "$ROUNDS"); do
    for side in old new; do
      build=$OLD; [ "$side" = new ] && build=$NEW
      # Each build with its own instruction-set libraries (the sourced
      # setup.bash puts NEW's first on the library path; OLD's may differ in ABI).
      LD_LIBRARY_PATH="$build/devel/lib:$LD_LIBRARY_PATH" "$build/devel/lib/aurora_sweep/sweep" --config "$SWEEP" --out "$OUT/$side-$precision-$r" --backend cpu \
        --precision "$precision" --threads "$THREADS" --no-plots --quiet > /dev/null 2> "$OUT/stderr" ||
        { cat "$OUT/stderr" >&2; exit 1; }
    done
  done
done
python3 - "$OUT" "$ROUNDS" <<'PY'
import filecmp, json, statistics, sys
out, rounds = sys.argv[1], int(sys.argv[2])
print("%-9s %12s %12s %10s %s" % ("precision", "old [s]", "new [s]", "new/old", "results"))
for p in ("double", "float"):
    t = {s: [json.load(open("%s/%s-%s-%d/summary.json" % (out, s, p, r)))["wall_time_s"] for r in range(1, rounds + 1)]
         for s in ("old", "new")}
    same = all(filecmp.cmp("%s/old-%s-%d/results.csv" % (out, p, r), "%s/new-%s-%d/results.csv" % (out, p, r),
                           shallow=False) for r in range(1, rounds + 1))
    o, n = statistics.median(t["old"]), statistics.median(t["new"])
    print("%-9s %12.3f %12.3f %10.3f %s" % (p, o, n, n / o, "same bytes" if same else "DIFFER"))
PY
rm -rf "$OUT"
