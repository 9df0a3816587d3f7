#!/usr/bin/env bash
# The instructions two builds of the sweep execute on the same cut of a
# sweep, counted by valgrind's callgrind: the steady measure of a change's
# cost to the SIMD engine where wall times swing by several percent (a
# shared machine: see bench/compare_builds.sh for the wall-clock side).
# Each axis of the sweep file keeps its first VALUES values (default 16; a
# {from, to, count} axis at its own spacing); one thread, the cpu backend.
# valgrind has no AVX-512: the engine runs its AVX2 build. Prints each build's instructions
# in the engine's threads and in the whole program, the ratios new/old, and
# whether the results are the same bytes.
# Usage: bench/compare_instructions.sh OLD_BUILD NEW_BUILD [SWEEP_FILE] [VALUES]
#   (a build folder each, as `make build` makes; SWEEP_FILE default: the thesis grid)
set -eo pipefail
if [ $# -lt 2 ]; then
  sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
OLD=$1
NEW=$2
VALUES=${4:-16}
command -v valgrind > /dev/null || { echo "valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }
SWEEP=$3
source "$(dirname "$0")/two_builds.sh"  # also the cut file's relative paths: aurora_config through the package path
SWEEP=${SWEEP:-config/sweeps/positioning_delay.yaml}
OUT=$(mktemp -d /tmp/aurora_compare_instructions.XXXXXX)
trap 'rm -rf "$OUT"' EXIT
# The cut: every axis keeps its first VALUES values;
# its vehicle, task and other files are then found in config/ (the sweep
# looks there after the file's own folder).
python3 - "$SWEEP" "$VALUES" "$OUT/cut.yaml" <<'PY'
import sys, yaml
src, values, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
doc = yaml.safe_load(open(src))
params = doc["sweep"].get("parameters", {})
for name, axis in params.items():
    if not isinstance(axis, dict):
        continue  # a fixed value
    if "values" in axis:
        axis["values"] = axis["values"][:values]
    elif "count" in axis and int(axis["count"]) > values:
        # Its first VALUES values, at the same spacing (an integer axis stays integer).
        step = (float(axis["to"]) - float(axis["from"])) / (int(axis["count"]) - 1)
        to = axis["from"] + step * (values - 1)
        axis["to"], axis["count"] = (int(round(to)) if isinstance(axis["from"], int) and step.is_integer() else to), values
yaml.safe_dump(doc, open(out, "w"), sort_keys=False)
PY
echo "compare instructions: $SWEEP cut to $VALUES values per axis, one thread, cpu backend (AVX2 under valgrind)"
for side in old new; do
  build=$OLD; [ "$side" = new ] && build=$NEW
  LD_LIBRARY_PATH="$build/devel/lib:$LD_LIBRARY_PATH" valgrind --tool=callgrind --callgrind-out-file="$OUT/$side.cg" \
    "$build/devel/lib/aurora_sweep/sweep" --config "$OUT/cut.yaml" --out "$OUT/$side" --backend cpu --threads 1 \
    --no-plots --quiet > /dev/null 2> "$OUT/stderr" || { cat "$OUT/stderr" >&2; exit 1; }
done
python3 - "$OUT" <<'PY'
import filecmp, re, subprocess, sys
out = sys.argv[1]
def counts(side):
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "%s/%s.cg" % (out, side)],
                          capture_output=True, text=True, check=True).stdout
    total = engine = 0
    for line in text.splitlines():
        m = re.match(r"\s*([\d,]+) \([^)]*\)\s+(.*)", line)
        if not m:
            continue
        n = int(m.group(1).replace(",", ""))
        if "PROGRAM TOTALS" in m.group(2):
            total = n
        # The engine runs in its threads (onRange's workers): their entry's inclusive count.
        elif re.search(r"std::thread::_State_impl<.*aurora_sweep::.*onRange", m.group(2)) and "_M_run" in m.group(2):
            engine += n
    return engine, total
old, new = counts("old"), counts("new")
print("%-8s %16s %16s %10s" % ("", "old", "new", "new/old"))
for i, name in enumerate(("engine", "program")):
    print("%-8s %16d %16d %10.4f" % (name, old[i], new[i], new[i] / old[i] if old[i] else float("nan")))
same = filecmp.cmp("%s/old/results.csv" % out, "%s/new/results.csv" % out, shallow=False)
print("results:", "same bytes" if same else "DIFFER")
PY
