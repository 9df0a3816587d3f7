// The sweep's execution backends (host side). Each fills one SimResult per
// combination index of the spec.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "aurora_control/limits.h"
#include "aurora_sweep/simulation.h"
#include "aurora_sweep/sweep_spec.h"

namespace aurora_sweep {

// Progress counter the backends advance (finished simulations); a monitor
// thread reads it for the ETA.
using Progress = std::atomic<long>;

template <typename T>
SimSetup<T> makeSetup(const SweepSpec& spec) {
  SimSetup<T> s;
  s.params = spec.vehicle.cast<T>();
  s.config.task = aurora_control::WaypointTask<T>::singlePoint(
      T(spec.desired[0]), T(spec.desired[1]), T(spec.desired[2]), T(spec.duration));
  s.config.criteria = spec.criteria.cast<T>();
  s.config.clamp_commands = spec.clamp_commands;
  s.config.early_stop = spec.early_stop;
  s.iterations = aurora_control::studyIterationCount(spec.duration, spec.vehicle.Ts);
  return s;
}

// One simulation at a time on the calling thread: the plain reference loop.
void runScalar(const SweepSpec& spec, std::vector<SimResult>& out, Progress& progress);

// Many simulations at once: SIMD lanes (a finished lane takes the next
// combination), on `threads` threads.
void runCpuBatch(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                 Progress& progress);

// Lanes per SIMD batch the CPU engine uses for this precision, and the
// instruction set chosen at run time (for the summary): the widest this CPU
// runs among those built (cpu_dispatch.cpp), unless AURORA_SWEEP_SIMD names one.
// Throws std::runtime_error when AURORA_SWEEP_SIMD names a build that is
// missing or that this CPU cannot run.
int cpuBatchLanes(Precision precision);
std::string cpuBatchArch(Precision precision);

// The engine's builds, widest first ("none": threads without SIMD lanes),
// and whether this CPU runs each; running a chosen one (tests, benchmarks).
struct CpuIsa {
  std::string key, name;
  bool supported;
};
std::vector<CpuIsa> cpuBatchIsas();
void runCpuBatchOn(const std::string& key, const SweepSpec& spec, int threads,
                   std::vector<SimResult>& out, Progress& progress);

}  // namespace aurora_sweep
