#include "aurora_sweep/backends.h"

namespace aurora_sweep {

namespace {

template <typename T, int Capacity>
void runScalarWith(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress) {
  const SimSetup<T> setup = makeSetup<T>(spec);
  const GridView grid = spec.view();
  const long first = spec.rangeBegin(), n = spec.rangeSize();
  out.resize(n);
  for (long i = 0; i < n; ++i) {
    out[i] = simulateCombination<T, Capacity>(setup, grid, first + i);
    progress.fetch_add(1, std::memory_order_relaxed);
  }
}

}  // namespace

void runScalar(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress) {
  aurora_control::withHistoryCapacity(spec.max_delay, [&](auto capacity) {
    constexpr int kCapacity = decltype(capacity)::value;
    if (spec.precision == Precision::kDouble) {
      runScalarWith<double, kCapacity>(spec, out, progress);
    } else {
      runScalarWith<float, kCapacity>(spec, out, progress);
    }
  });
}

}  // namespace aurora_sweep
