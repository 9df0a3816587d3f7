// The offline runner: one whole run of the closed loop (closed_loop.h), one
// simulation at a time. The sweep's `scalar` backend and each CUDA thread
// run it as the study does (no clamp); the flight tool (flight_runner.h) as
// the lockstep ROS loop does (the drone clamps). The rostests compare the ROS
// loop with it.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "aurora_control/loop/delay_buffer.h"
#include "aurora_control/params/limits.h"
#include "aurora_control/loop/closed_loop.h"
#include "aurora_control/loop/loop_link.h"
#include "aurora_common/refusal_text.h"

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

// One simulation's own parameters: the simulated vehicle, the gains of a
// law with data `Data` (control_law.h) and the delay. `model` is what the
// law inverts (the vehicle file's nominal values; `plant` differs from it in
// a robustness study).
template <class Data, typename T>
struct StudyRun {
  typename Data::Vehicle::template Params<T> plant;
  typename Data::Vehicle::template Params<T> model;
  typename Data::template Gains<T> gains;
  long delay;  // [samples]
};

struct RunnerResult {
  bool ok[kPositioningChecks];
  bool feasible;
  double iae, itae, iasc;
  long steps;           // model steps run
  double final_pos[3];  // [m], world frame
};

// Largest delay (samples) the runner's history holds: the same limit as the
// node's (limits.h).
constexpr long kMaxRunnerDelay = kMaxDelaySamples;

// The vehicle's state after an iteration, as an observer sees it.
template <class Vehicle, typename T>
struct LoopView {
  const typename Vehicle::template State<T>& model;  // X_(k+1)
  const PositioningMetrics<T, bool>& metrics;
};

// What an observer sees after each iteration.
template <class Vehicle, typename T>
struct LoopObservation {
  long k;                                     // the iteration (0-based): task time k Ts
  const T* X_before;                          // the state it started from (X_k)
  LoopView<Vehicle, T> after;                 // after the model step (X_(k+1), metrics)
  const LoopStep<T, Vehicle::kInputs>& step;  // its reference and the command applied
  const T* xc;                                // the delayed state the law received
  long received;                              // its step: the delay in force is k - received
};

struct NoObserver {
  template <typename... Args>
  AURORA_HD void operator()(const Args&...) const {}
};

// A finished run's result (the SIMD engine builds one lane's sim and calls it).
template <class Data, typename T>
AURORA_HD inline RunnerResult runnerResult(const LoopState<Data, T, bool>& sim, long steps) {
  RunnerResult r;
  for (int i = 0; i < kPositioningChecks; ++i) r.ok[i] = sim.metrics.ok[i];
  r.feasible = sim.metrics.feasible();
  r.iae = double(sim.metrics.iae);
  r.itae = double(sim.metrics.itae);
  r.iasc = double(sim.metrics.iasc);
  r.steps = steps;
  for (int i = 0; i < 3; ++i) r.final_pos[i] = double(sim.model.X[Data::Vehicle::kPosition + i]);
  return r;
}

// The runner's observation of one iteration, from loopIteration's step.
template <class Law, typename T, class Observer>
struct RunnerObserver {
  using Vehicle = typename Law::Vehicle;
  Observer& observe;
  const LoopState<typename Law::Data, T, bool>& s;
  long k;
  T X_before[Vehicle::kStates];
  AURORA_HD void operator()(const LoopStep<T, Vehicle::kInputs>& step, const T* xc, long received) const {
    observe(LoopObservation<Vehicle, T>{k, X_before, LoopView<Vehicle, T>{s.model, s.metrics}, step, xc, received});
  }
};

// The observer of iteration k, holding the state it starts from; none for
// NoObserver (the sweep's and the kernel's runs keep no copy).
template <class Law, typename T, class Observer>
struct ObserverAt {
  AURORA_HD static RunnerObserver<Law, T, Observer> at(Observer& observe,
                                                      const LoopState<typename Law::Data, T, bool>& s, long k) {
    RunnerObserver<Law, T, Observer> at_k{observe, s, k, {}};
    for (int i = 0; i < Law::Vehicle::kStates; ++i) at_k.X_before[i] = s.model.X[i];
    return at_k;
  }
};
template <class Law, typename T>
struct ObserverAt<Law, T, NoObserver> {
  AURORA_HD static NoObserver at(NoObserver&, const LoopState<typename Law::Data, T, bool>&, long) {
    return NoObserver();
  }
};

// One whole run of law `Law` with `history` (its read(j) gives the state
// the law flies on; delay < its capacity, checked by the caller). No
// exceptions, no allocation: this is also the CUDA kernel's per-thread
// body. `iterations`: studyIterationCount() for the study, taskStepCount()
// for a flight. Iteration k (0-based) is loopIteration (closed_loop.h)
// over `link`.
template <class Law, typename T, typename Observer, typename History, typename Link>
AURORA_HD RunnerResult runClosedLoopWith(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg,
                                         long iterations, Observer& observe, History& history, Link& link) {
  const LoopParams<typename Law::Data, T> params{run.plant, run.model, run.gains, cfg.criteria};
  const ClampPolicy clamp{cfg.clamp_commands, cfg.clamp_at_drone};
  LoopState<typename Law::Data, T, bool> s;
  s.reset(run.plant, cfg.task.at(T(0)).pos);
  long k = 0;
  while (k < iterations) {
    const bool stop = loopIteration<Law>(params, cfg.task, clamp, cfg.early_stop, k, history, link, s,
                                         ObserverAt<Law, T, Observer>::at(observe, s, k));
    ++k;
    if (stop) break;
  }
  return runnerResult(s, k);
}

// The same with the law's own history of `Capacity` samples.
template <class Law, typename T, int Capacity, typename Observer, typename Link>
AURORA_HD RunnerResult runClosedLoopOver(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg,
                                         long iterations, Observer& observe, Link& link) {
  StateHistory<Law, T, Capacity> history;
  return runClosedLoopWith<Law>(run, cfg, iterations, observe, history, link);
}

// The run over an ideal link (today's loop: the delay rule, no command
// delay): the CUDA kernel's per-thread body and the sweep's scalar loop.
template <class Law, typename T, int Capacity, typename Observer>
AURORA_HD RunnerResult runClosedLoop(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg, long iterations,
                                     Observer& observe) {
  IdealLink link{run.delay};
  return runClosedLoopOver<Law, T, Capacity>(run, cfg, iterations, observe, link);
}

// The run over cfg.link's model (host only: the channels and the commands
// in flight live on the heap). `combination` keys the link's draws: the
// sweep's combination index, 0 for a single flight (as the node's).
template <class Law, typename T, int Capacity, typename Observer>
RunnerResult runOverModelLink(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg, long iterations,
                              Observer& observe, uint64_t combination) {
  using Link = ModelLink<Capacity, T, Law::Vehicle::kInputs>;
  std::unique_ptr<Link> link(new Link(cfg.link, run.delay, combination, double(run.plant.Ts)));
  return runClosedLoopOver<Law, T, Capacity>(run, cfg, iterations, observe, *link);
}

// Refuses a delay the runner's history cannot hold.
inline void checkRunnerDelay(long delay) {
  if (delay < 0 || delay > kMaxRunnerDelay) {
    throw aurora_common::ConfigError("delay " + std::to_string(delay) + " samples is outside the accepted range: " +
                                  delayRangeText());
  }
}

// Calls run(capacity, link) with the history capacity (an
// std::integral_constant) and the link of a run of law `Law` with cfg's
// link: the delay rule over an ideal one, else its model (combination 0, as
// a single flight's and the node's). Refuses a delay the history cannot hold.
// One flight takes the full history (a run does not depend on its size:
// StateHistory), so each caller compiles one loop, not one per tier.
template <class Law, typename T, typename Run>
void withLoopLink(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg, Run&& fly) {
  checkRunnerDelay(run.delay);
  const long history = cfg.link.ideal() ? run.delay : cfg.link.historyNeeded(run.delay);
  checkRunnerDelay(history);
  const std::integral_constant<int, kDelayHistory> capacity;
  if (cfg.link.ideal()) {
    IdealLink link{run.delay};
    return fly(capacity, link);
  }
  using Link = ModelLink<kDelayHistory, T, Law::Vehicle::kInputs>;
  std::unique_ptr<Link> link(new Link(cfg.link, run.delay, 0, double(run.plant.Ts)));
  fly(capacity, *link);
}

// Runs `iterations` iterations of law `Law`; `observe(LoopObservation)` is
// called after each (for callers that record the trajectory).
template <class Law, typename T, typename Observer = NoObserver>
RunnerResult runLoop(const StudyRun<typename Law::Data, T>& run, const RunnerConfig<T>& cfg, long iterations,
                     Observer observe = Observer()) {
  RunnerResult result;
  withLoopLink<Law>(run, cfg, [&](auto capacity, auto& link) {
    result = runClosedLoopOver<Law, T, decltype(capacity)::value>(run, cfg, iterations, observe, link);
  });
  return result;
}

}  // namespace aurora_control
