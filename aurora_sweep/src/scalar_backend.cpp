#include "aurora_sweep/backends.h"

namespace aurora_sweep {

void runScalar(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress) {
  withSweepTypes(spec, [&](auto type, auto capacity, auto law) {
    using T = decltype(type);
    const SimSetup<T> setup = makeSetup<T>(spec);
    const GridView grid = spec.view();
    const long first = spec.rangeBegin(), n = spec.rangeSize();
    out.resize(n);
    for (long i = 0; i < n; ++i) {
      out[i] = simulateCombination<decltype(law)::value, T, decltype(capacity)::value>(setup, grid, first + i);
      progress.fetch_add(1, std::memory_order_relaxed);
    }
  });
}

}  // namespace aurora_sweep
