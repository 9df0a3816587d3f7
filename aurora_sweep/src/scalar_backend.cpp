#include "aurora_sweep/backends.h"

namespace aurora_sweep {

namespace {

template <typename T, int Capacity>
void runScalarWith(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress) {
  const SimSetup<T> setup = makeSetup<T>(spec);
  const GridView grid = spec.view();
  const long n = grid.size();
  out.resize(n);
  for (long i = 0; i < n; ++i) {
    out[i] = simulateCombination<T, Capacity>(setup, grid, i);
    progress.fetch_add(1, std::memory_order_relaxed);
  }
}

template <typename T>
void runScalarPrecision(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress) {
  if (spec.max_delay < 64) return runScalarWith<T, 64>(spec, out, progress);
  if (spec.max_delay < 512) return runScalarWith<T, 512>(spec, out, progress);
  return runScalarWith<T, aurora_control::kDelayHistory>(spec, out, progress);
}

}  // namespace

void runScalar(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress) {
  if (spec.precision == Precision::kDouble) {
    runScalarPrecision<double>(spec, out, progress);
  } else {
    runScalarPrecision<float>(spec, out, progress);
  }
}

}  // namespace aurora_sweep
