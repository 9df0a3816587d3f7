#include "aurora_sweep/backends.h"

namespace aurora_sweep {

void runEachCombination(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress,
                        const CombinationLoop& loop) {
  const GridView grid = spec.view();
  const long first = spec.rangeBegin();
  out.resize(spec.rangeSize());
  if (spec.formation()) {
    return withFormationTypes(spec, [&](auto type, auto capacity, auto law, const auto& run) {
      using T = decltype(type);
      using Law = decltype(law);
      constexpr int kCapacity = decltype(capacity)::value;
      const auto setup = makeFormationSetup<T>(spec, run);
      withFormationPredictor(run, [&](auto predicted) {
        constexpr bool kPredicted = decltype(predicted)::value;
        loop(spec.rangeSize(), [&](long i) {
          out[i] = setup.ideal_link ? simulateFormation<Law, T, kCapacity, false, kPredicted>(setup, grid, first + i)
                                    : simulateFormation<Law, T, kCapacity, true, kPredicted>(setup, grid, first + i);
          progress.fetch_add(1, std::memory_order_relaxed);
        });
      });
    });
  }
  withSweepTypes(spec, [&](auto type, auto capacity, auto law) {
    using T = decltype(type);
    using Law = decltype(law);
    constexpr int kCapacity = decltype(capacity)::value;
    const auto setup = makeSetup<typename Law::Vehicle, T>(spec);
    const bool predicted = spec.predicting();
    loop(spec.rangeSize(), [&](long i) {
      if (predicted) {
        out[i] = setup.ideal_link ? simulateCombination<Law, T, kCapacity, false, true>(setup, grid, first + i)
                                  : simulateCombination<Law, T, kCapacity, true, true>(setup, grid, first + i);
      } else {
        out[i] = setup.ideal_link ? simulateCombination<Law, T, kCapacity, false>(setup, grid, first + i)
                                  : simulateCombination<Law, T, kCapacity, true>(setup, grid, first + i);
      }
      progress.fetch_add(1, std::memory_order_relaxed);
    });
  });
}

void runScalar(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress) {
  runEachCombination(spec, out, progress, [](long n, const std::function<void(long)>& simulate) {
    for (long i = 0; i < n; ++i) simulate(i);
  });
}

}  // namespace aurora_sweep
