#include "aurora_sweep/backends.h"

namespace aurora_sweep {

void runScalar(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress) {
  runEachCombination(spec, out, progress, [](long n, const std::function<void(long)>& simulate) {
    for (long i = 0; i < n; ++i) simulate(i);
  });
}

}  // namespace aurora_sweep
