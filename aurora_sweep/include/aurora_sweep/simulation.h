// One simulation of a sweep, from its combination index: the per-thread body
// of the CUDA kernel and the body of the scalar backend's loop (host and
// device, no allocation, no exceptions).
#pragma once

#include "aurora_control/positioning_runner.h"
#include "aurora_sweep/combination.h"

namespace aurora_sweep {

// Everything a simulation needs besides its combination, in precision T.
template <typename T>
struct SimSetup {
  aurora_sim::ArdroneParams<T> params;
  aurora_control::RunnerConfig<T> config;
  long iterations;  // loop iterations of the study (1801 for 60 s)
};

// Compact result (what the kernel writes back; 48 bytes).
struct SimResult {
  float final_pos[3];   // [m]
  int steps;            // model steps run
  double iae, itae, iasc;
  unsigned char ok;     // bit i: check i + 1 held; bit 4: feasible
};

AURORA_HD inline SimResult compactResult(const aurora_control::RunnerResult& r) {
  SimResult s;
  for (int i = 0; i < 3; ++i) s.final_pos[i] = static_cast<float>(r.final_pos[i]);
  s.steps = static_cast<int>(r.steps);
  s.iae = r.iae;
  s.itae = r.itae;
  s.iasc = r.iasc;
  s.ok = 0;
  for (int i = 0; i < 4; ++i) s.ok |= static_cast<unsigned char>((r.ok[i] ? 1 : 0) << i);
  s.ok |= static_cast<unsigned char>((r.feasible ? 1 : 0) << 4);
  return s;
}

template <typename T, int Capacity>
AURORA_HD inline SimResult simulateCombination(const SimSetup<T>& setup, const GridView& grid,
                                               long index) {
  const Combination c = grid.decode(index);
  const aurora_control::PdGains<T> gains{T(c.kp), T(c.kd)};
  aurora_control::NoObserver none;
  return compactResult(aurora_control::runPositioningCore<T, Capacity>(
      setup.params, setup.config, gains, c.delay, setup.iterations, none));
}

}  // namespace aurora_sweep
