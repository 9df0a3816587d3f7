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
#include "../lanes/batch_isa.h"

namespace aurora_sweep {

void runThreadedScalar(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                       Progress& progress) {
  threads = std::max(1, threads);
  runEachCombination(spec, out, progress, [threads](long n, const std::function<void(long)>& simulate) {
    std::atomic<long> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
      pool.emplace_back([&] {
        for (long i = next.fetch_add(1); i < n; i = next.fetch_add(1)) simulate(i);
      });
    }
    for (auto& th : pool) th.join();
  });
}

}  // namespace aurora_sweep
