// The offline runner: one whole run of the closed loop (closed_loop.h), one
// simulation at a time. The sweep's `scalar` backend and each CUDA thread
// run it as the study does (no clamp); the flight tool (flight_runner.h) as
// the lockstep ROS loop does (the drone clamps). The rostests compare the ROS
// loop with it.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "aurora_control/delay_buffer.h"
#include "aurora_control/limits.h"
#include "aurora_control/closed_loop.h"
#include "aurora_control/loop_link.h"
#include "aurora_sim/refusal_text.h"

namespace aurora_control {

template <typename T>
struct RunnerConfig {
  Task<T> task = positioningTask(T(2), T(1), T(2), T(60));
  FeasibilityCriteria<T> criteria = FeasibilityCriteria<T>::study();
  bool clamp_commands = false;  // the controller clamps: false reproduces the study, true the node
  bool clamp_at_drone = false;  // the drone clamps what it receives (the sim node and the drivers)
  bool early_stop = false;      // stop at the first failed check
  LinkParams link;              // the link (link.h); its uplink delay is the run's `delay`
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

// What an observer sees after each iteration.
template <typename T>
struct LoopObservation {
  long k;                            // the iteration (0-based): task time k Ts
  const T* X_before;                 // the state it started from (X_k, 12)
  const LoopState<T, bool>& after;   // after the model step (X_(k+1), metrics)
  const LoopStep<T>& step;           // its reference and the command applied
  const T* xc;                       // the delayed state the law received (12)
  long received;                     // its step: the delay in force is k - received
};

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
AURORA_HD inline RunnerResult runnerResult(const LoopState<T, bool>& sim, long steps) {
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

// One whole run of law `Law` with a history of `Capacity` samples (delay <
// Capacity, checked by the caller). No exceptions, no allocation: this is
// also the CUDA kernel's per-thread body. `iterations`: studyIterationCount()
// for the study, taskStepCount() for a flight. Iteration k (0-based) keeps
// X_k in the history and hands the law the delayed state by the delay rule.
template <LawType Law, typename T, int Capacity, typename Observer, typename Link>
AURORA_HD RunnerResult runClosedLoopOver(const StudyRun<T>& run, const RunnerConfig<T>& cfg, long iterations,
                                         Observer& observe, Link& link) {
  using Sample = LawSample<T, Law>;
  const LoopParams<T> params{run.plant, run.model, run.gains, cfg.criteria};
  const ClampPolicy clamp{cfg.clamp_commands, cfg.clamp_at_drone};
  LoopState<T, bool> s;
  s.reset(cfg.task.at(T(0)).pos);
  // On the stack: Capacity x (6 or 12) scalars, no allocation.
  DelayBuffer<Sample, Capacity> history;
  long k = 0;
  while (k < iterations) {
    history.push(Sample::fromState(s.model.X));  // H(k + 1) = X_k
    T xc[aurora_sim::kStateSize], X_before[aurora_sim::kStateSize], U[4];
    const long received = link.uplinkIndex(k);
    history.at(received).toState(xc);
    for (int i = 0; i < aurora_sim::kStateSize; ++i) X_before[i] = s.model.X[i];
    LoopStep<T> step;
    step.ref = controllerHalf<Law>(params, cfg.task, clamp, T(k), xc, s, U);
    link.downlink(k, U, U);
    droneHalf(params, clamp, step.ref, U, s, step.U);
    observe(LoopObservation<T>{k, X_before, s, step, xc, received});
    ++k;
    if (stoppedEarly(cfg.early_stop, s.metrics.feasible())) break;
  }
  return runnerResult(s, k);
}

// The run over an ideal link (today's loop: the delay rule, no command
// delay): the CUDA kernel's per-thread body and the sweep's scalar loop.
template <LawType Law, typename T, int Capacity, typename Observer>
AURORA_HD RunnerResult runClosedLoop(const StudyRun<T>& run, const RunnerConfig<T>& cfg, long iterations,
                                     Observer& observe) {
  IdealLink link{run.delay};
  return runClosedLoopOver<Law, T, Capacity>(run, cfg, iterations, observe, link);
}

// The run over cfg.link's model (host only: the channels and the commands
// in flight live on the heap). `combination` keys the link's draws: the
// sweep's combination index, 0 for a single flight (as the node's).
template <LawType Law, typename T, int Capacity, typename Observer>
RunnerResult runOverModelLink(const StudyRun<T>& run, const RunnerConfig<T>& cfg, long iterations,
                              Observer& observe, uint64_t combination) {
  std::unique_ptr<ModelLink<Capacity, T>> link(
      new ModelLink<Capacity, T>(cfg.link, run.delay, combination, double(run.plant.Ts)));
  return runClosedLoopOver<Law, T, Capacity>(run, cfg, iterations, observe, *link);
}

// Refuses a delay the runner's history cannot hold.
inline void checkRunnerDelay(long delay) {
  if (delay < 0 || delay > kMaxRunnerDelay) {
    throw aurora_sim::ConfigError("delay " + std::to_string(delay) + " samples is outside the accepted range: " +
                                  delayRangeText());
  }
}

// Runs `iterations` iterations; `observe(LoopObservation)` is called after
// each (for callers that record the trajectory).
template <typename T, typename Observer = NoObserver>
RunnerResult runLoop(LawType law, const StudyRun<T>& run, const RunnerConfig<T>& cfg, long iterations,
                     Observer observe = Observer()) {
  checkRunnerDelay(run.delay);
  RunnerResult result;
  if (cfg.link.ideal()) {
    withHistoryCapacity(run.delay, [&](auto capacity) {
      withLaw(law, [&](auto law_tag) {
        result = runClosedLoop<decltype(law_tag)::value, T, decltype(capacity)::value>(run, cfg, iterations, observe);
      });
    });
    return result;
  }
  const long history = cfg.link.historyNeeded(run.delay);
  checkRunnerDelay(history);
  withHistoryCapacity(history, [&](auto capacity) {
    withLaw(law, [&](auto law_tag) {
      result = runOverModelLink<decltype(law_tag)::value, T, decltype(capacity)::value>(run, cfg, iterations,
                                                                                        observe, 0);
    });
  });
  return result;
}

// The study's run: its task's iterations (studyIterationCount).
template <typename T, typename Observer = NoObserver>
RunnerResult runStudy(LawType law, const StudyRun<T>& run, const RunnerConfig<T>& cfg,
                      Observer observe = Observer()) {
  const long n = studyIterationCount(double(cfg.task.duration()), double(run.plant.Ts));
  return runLoop(law, run, cfg, n, observe);
}

// The delay study's PD law on drone `p` (the thesis's runs).
template <typename T, typename Observer = NoObserver>
RunnerResult runPositioning(const aurora_sim::ArdroneParams<T>& p, const RunnerConfig<T>& cfg,
                            const PdGains<T>& gains, long delay, Observer observe = Observer()) {
  StudyRun<T> run{p, p, LawGains<T>{gains, UnderactuatedGains<T>::defaults()}, delay};
  return runStudy(LawType::kPdSaturated, run, cfg, observe);
}

}  // namespace aurora_control
