// The `cpu` backend without SIMD lanes: where xsimd 8 is not available
// (Ubuntu 20.04 ships xsimd 7), on a CPU none of the engine builds runs, or
// with AURORA_SWEEP_SIMD=none. The same per-simulation body as the scalar
// backend (simulateCombination) on every core, one simulation per thread at
// a time. Slower than the SIMD engine (batch_engine.h), same results.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "aurora_sweep/backends.h"
#include "batch_isa.h"

namespace aurora_sweep {

void runThreadedScalar(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                       Progress& progress) {
  threads = std::max(1, threads);
  withSweepTypes(spec, [&](auto type, auto capacity, auto law) {
    using T = decltype(type);
    const SimSetup<T> setup = makeSetup<T>(spec);
    const GridView grid = spec.view();
    const long first = spec.rangeBegin(), n = spec.rangeSize();
    out.resize(n);
    std::atomic<long> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
      pool.emplace_back([&] {
        for (long i = next.fetch_add(1); i < n; i = next.fetch_add(1)) {
          out[i] = simulateCombination<decltype(law)::value, T, decltype(capacity)::value>(setup, grid, first + i);
          progress.fetch_add(1, std::memory_order_relaxed);
        }
      });
    }
    for (auto& th : pool) th.join();
  });
}

}  // namespace aurora_sweep
