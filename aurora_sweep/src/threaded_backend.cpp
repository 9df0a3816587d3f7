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

namespace {

template <typename T, int Capacity>
void runThreaded(const SweepSpec& spec, int threads, std::vector<SimResult>& out, Progress& progress) {
  const SimSetup<T> setup = makeSetup<T>(spec);
  const GridView grid = spec.view();
  const long first = spec.rangeBegin(), n = spec.rangeSize();
  out.resize(n);
  std::atomic<long> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&] {
      for (long i = next.fetch_add(1); i < n; i = next.fetch_add(1)) {
        out[i] = simulateCombination<T, Capacity>(setup, grid, first + i);
        progress.fetch_add(1, std::memory_order_relaxed);
      }
    });
  }
  for (auto& th : pool) th.join();
}

}  // namespace

void runThreadedScalar(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                       Progress& progress) {
  threads = std::max(1, threads);
  aurora_control::withHistoryCapacity(spec.max_delay, [&](auto capacity) {
    constexpr int kCapacity = decltype(capacity)::value;
    if (spec.precision == Precision::kDouble) {
      runThreaded<double, kCapacity>(spec, threads, out, progress);
    } else {
      runThreaded<float, kCapacity>(spec, threads, out, progress);
    }
  });
}

}  // namespace aurora_sweep
