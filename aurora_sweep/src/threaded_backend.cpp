// The `cpu` backend where xsimd 8 is not available (Ubuntu 20.04 ships
// xsimd 7): the same per-simulation body as the scalar backend
// (simulateCombination) on every core, one simulation per thread at a time.
// Slower than the SIMD engine (batch_backend.cpp), same results.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "aurora_sweep/backends.h"

namespace aurora_sweep {

namespace {

template <typename T, int Capacity>
void runThreaded(const SweepSpec& spec, int threads, std::vector<SimResult>& out, Progress& progress) {
  const SimSetup<T> setup = makeSetup<T>(spec);
  const GridView grid = spec.view();
  const long n = grid.size();
  out.resize(n);
  std::atomic<long> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&] {
      for (long i = next.fetch_add(1); i < n; i = next.fetch_add(1)) {
        out[i] = simulateCombination<T, Capacity>(setup, grid, i);
        progress.fetch_add(1, std::memory_order_relaxed);
      }
    });
  }
  for (auto& th : pool) th.join();
}

template <typename T>
void runPrecision(const SweepSpec& spec, int threads, std::vector<SimResult>& out, Progress& progress) {
  if (spec.max_delay < 64) return runThreaded<T, 64>(spec, threads, out, progress);
  if (spec.max_delay < 512) return runThreaded<T, 512>(spec, threads, out, progress);
  return runThreaded<T, aurora_control::kDelayHistory>(spec, threads, out, progress);
}

}  // namespace

void runCpuBatch(const SweepSpec& spec, int threads, std::vector<SimResult>& out, Progress& progress) {
  threads = std::max(1, threads);
  if (spec.precision == Precision::kDouble) {
    runPrecision<double>(spec, threads, out, progress);
  } else {
    runPrecision<float>(spec, threads, out, progress);
  }
}

int cpuBatchLanes(Precision) { return 1; }

std::string cpuBatchArch(Precision) { return "threads without SIMD lanes (xsimd 8 not found)"; }

}  // namespace aurora_sweep
