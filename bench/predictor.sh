#!/usr/bin/env bash
# The state predictor's cost (figures measured, never asserted;
# docs/predictor.md, "What it costs"), interleaved in one run: 16 x 16 gains
# of the thesis grid's range at each delay d in {0, 8, 16, 32, 63}, the plain
# law, resimulate and smith, on the scalar backend (one simulation at a
# time), no early stop so that every run has the study's 1801 steps; 3
# rounds, medians. Prints the time per control step of each, the ratios to
# the plain law at the same delay, and resimulate's extra cost per unit of
# delay (the slope over d). Then the thesis grid (65,536 runs, delay 0..63)
# on the cpu backend's SIMD lanes, plain, resimulate and smith, one round:
# control steps per second and the ratios.
set -eo pipefail
BUILD=${1:-build}
source "$(dirname "$0")/workspace.sh"
DIR=$(mktemp -d /tmp/aurora_predictor_bench.XXXXXX)
CONFIG=$PWD/config
for d in 0 8 16 32 63; do
  for form in off resimulate smith; do
    cat > "$DIR/$form-$d.yaml" <<YAML
sweep:
  name: bench_${form}_${d}
  controller: pd_saturated
  vehicle: $CONFIG/vehicles/ardrone2.yaml
  task: $CONFIG/tasks/positioning.yaml
  parameters:
    kp: {from: 0.0, to: 0.75, count: 16}
    kd: {from: 0.0, to: 1.0, count: 16}
    delay: $d
  early_stop: false
  predictor: {form: '$form'}
YAML
  done
done
for round in 1 2 3; do
  for d in 0 8 16 32 63; do
    for form in off resimulate smith; do
      line=$("$BUILD/devel/lib/aurora_sweep/sweep" --config "$DIR/$form-$d.yaml" --out "$DIR/out" --backend scalar \
             --output none --overwrite --quiet 2>&1 | grep -E "control steps/s")
      echo "$form $d $(echo "$line" | sed -nE 's/.* ([0-9.e+]+) control steps\/s.*/\1/p')" >> "$DIR/times"
    done
  done
done
python3 - "$DIR/times" <<'PY'
import statistics, sys
rate = {}
for line in open(sys.argv[1]):
    form, d, r = line.split()
    rate.setdefault((form, int(d)), []).append(float(r))
us = {k: 1e6 / statistics.median(v) for k, v in rate.items()}
for d in sorted({d for _, d in us}):
    plain = us[("off", d)]
    print("thesis grid gains, delay %2d: plain %.3f us per control step; resimulate %.3f (%.2fx); smith %.3f (%.2fx)" % (
        d, plain, us[("resimulate", d)], us[("resimulate", d)] / plain, us[("smith", d)], us[("smith", d)] / plain))
ds = sorted({d for _, d in us})
ys = [us[("resimulate", d)] for d in ds]
mx, my = statistics.mean(ds), statistics.mean(ys)
slope = sum((x - mx) * (y - my) for x, y in zip(ds, ys)) / sum((x - mx) ** 2 for x in ds)
plain = statistics.mean(us[("off", d)] for d in ds)
print("resimulate costs %.3f us per control step more per sample of delay (least squares over d = %s): "
      "%.2f plain control steps (%.3f us, their mean)" % (slope, ", ".join(map(str, ds)), slope / plain, plain))
PY
for form in off resimulate smith; do
  sed -E "s/^  name: .*/  name: bench_grid_$form/; s|vehicles/ardrone2.yaml|$CONFIG/vehicles/ardrone2.yaml|; \
          s|tasks/positioning.yaml|$CONFIG/tasks/positioning.yaml|; s/^    form: resimulate/    form: '$form'/" \
    config/sweeps/positioning_delay_predictor.yaml > "$DIR/grid-$form.yaml"
  line=$("$BUILD/devel/lib/aurora_sweep/sweep" --config "$DIR/grid-$form.yaml" --out "$DIR/out" --backend cpu \
         --output none --overwrite --quiet 2>&1 | grep -E "control steps/s")
  echo "$form $(echo "$line" | sed -nE 's/.*; ([0-9.]+) s, .* ([0-9.e+]+) control steps\/s.*/\1 \2/p')" >> "$DIR/grid"
done
python3 - "$DIR/grid" <<'PY'
import sys
runs = {f: (float(s), float(r)) for f, s, r in (line.split() for line in open(sys.argv[1]))}
plain = runs["off"][1]
for form, (s, r) in runs.items():
    print("thesis grid on the SIMD lanes, %-10s %7.2f s, %.3g control steps/s (%.2fx the plain law's time per step)" % (
        form + ":", s, r, plain / r))
PY
echo "sweep files and times: $DIR"
