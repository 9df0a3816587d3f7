// The ROS-free runner of one whole positioning-study simulation (plain scalar
// loop, one simulation at a time). The sweep's `scalar` backend is this
// function; the rostests compare the ROS loop with it.
#pragma once

#include <stdexcept>
#include <string>

#include "aurora_control/delay_buffer.h"
#include "aurora_control/limits.h"
#include "aurora_control/positioning_study.h"

namespace aurora_control {

template <typename T>
struct RunnerConfig {
  Task<T> task = positioningTask(T(2), T(1), T(2), T(60));
  FeasibilityCriteria<T> criteria = FeasibilityCriteria<T>::study();
  bool clamp_commands = false;  // false reproduces the study; true matches the drivers
  bool early_stop = false;      // stop at the first failed check
};

// One simulation's own parameters: the simulated drone, the gains and the
// delay. `model` is what the underactuated law inverts (the vehicle file's
// nominal values; `plant` differs from it in a robustness study).
template <typename T>
struct StudyRun {
  aurora_sim::ArdroneParams<T> plant;
  aurora_sim::ArdroneParams<T> model;
  LawGains<T> gains;
  long delay;  // [samples]
};

struct RunnerResult {
  bool ok[4];
  bool feasible;
  double iae, itae, iasc;
  long steps;           // model steps run
  double final_pos[3];  // [m], world frame
};

// Largest delay (samples) the runner's history holds: the same limit as the
// node's (limits.h).
constexpr long kMaxRunnerDelay = kMaxDelaySamples;

struct NoObserver {
  template <typename... Args>
  AURORA_HD void operator()(const Args&...) const {}
};

// The early stop, written once for the runner and the SIMD engine (masks
// of lanes there): with early_stop, a run ends at its first failed check.
template <typename Mask>
AURORA_HD inline Mask stoppedEarly(bool early_stop, const Mask& feasible) {
  return early_stop ? !feasible : (feasible & !feasible);
}

// A finished run's result (the SIMD engine builds one lane's sim and calls it).
template <typename T>
AURORA_HD inline RunnerResult runnerResult(const PositioningSim<T, bool>& sim, long steps) {
  RunnerResult r;
  for (int i = 0; i < 4; ++i) r.ok[i] = sim.metrics.ok[i];
  r.feasible = sim.metrics.feasible();
  r.iae = double(sim.metrics.iae);
  r.itae = double(sim.metrics.itae);
  r.iasc = double(sim.metrics.iasc);
  r.steps = steps;
  for (int i = 0; i < 3; ++i) r.final_pos[i] = double(sim.model.X[aurora_sim::kX + i]);
  return r;
}

// One whole simulation of law `Law` with a history of `Capacity` samples
// (delay < Capacity, checked by the caller). No exceptions, no allocation:
// this is also the CUDA kernel's per-thread body. `iterations` comes from
// studyIterationCount() on the host. Iteration k (1-based) gives the law the
// delayed state by the delay rule and the task's reference at (k - 1) Ts.
template <LawType Law, typename T, int Capacity, typename Observer>
AURORA_HD RunnerResult runPositioningCore(const StudyRun<T>& run, const RunnerConfig<T>& cfg,
                                          long iterations, Observer& observe) {
  using Sim = PositioningSim<T, bool>;
  using Sample = LawSample<T, Law>;
  Sim sim;
  sim.reset(cfg.task.at(T(0)).pos);
  // On the stack: Capacity x (6 or 12) scalars, no allocation.
  DelayBuffer<Sample, Capacity> history;
  history.push(Sample::fromState(sim.model.X));
  long k = 0;
  while (k < iterations) {
    ++k;
    T xc[aurora_sim::kStateSize];
    history.delayed(run.delay).toState(xc);
    const Reference<T> ref = cfg.task.at(WaypointTask<T>::timeOfStep(k - 1, run.plant.Ts));
    T U[4];
    positioningIteration<Law>(run.plant, run.model, cfg.criteria, run.gains, ref, cfg.clamp_commands, xc,
                              sim, U);
    history.push(Sample::fromState(sim.model.X));
    observe(k, sim, U, xc);
    if (stoppedEarly(cfg.early_stop, sim.metrics.feasible())) break;
  }
  return runnerResult(sim, k);
}

// Runs one simulation; `observe(k, sim, U, xc)` is called after each model
// step (k 1-based, xc the 12-state the law received) for callers that record
// the trajectory.
template <typename T, typename Observer = NoObserver>
RunnerResult runStudy(LawType law, const StudyRun<T>& run, const RunnerConfig<T>& cfg,
                      Observer observe = Observer()) {
  if (run.delay < 0 || run.delay > kMaxRunnerDelay) {
    throw std::invalid_argument("delay " + std::to_string(run.delay) +
                                " samples is outside the accepted range [0, " +
                                std::to_string(kMaxRunnerDelay) + "]");
  }
  const long n = studyIterationCount(double(cfg.task.duration()), double(run.plant.Ts));
  RunnerResult result;
  withHistoryCapacity(run.delay, [&](auto capacity) {
    withLaw(law, [&](auto law_tag) {
      result = runPositioningCore<decltype(law_tag)::value, T, decltype(capacity)::value>(run, cfg, n, observe);
    });
  });
  return result;
}

// The delay study's PD law on drone `p` (the thesis's runs).
template <typename T, typename Observer = NoObserver>
RunnerResult runPositioning(const aurora_sim::ArdroneParams<T>& p, const RunnerConfig<T>& cfg,
                            const PdGains<T>& gains, long delay, Observer observe = Observer()) {
  StudyRun<T> run{p, p, LawGains<T>{gains, UnderactuatedGains<T>::defaults()}, delay};
  return runStudy(LawType::kPdSaturated, run, cfg, observe);
}

}  // namespace aurora_control
