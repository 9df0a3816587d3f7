// One whole flight offline, with either law and any task, computed exactly
// as the lockstep ROS loop computes it: the offline runner's closed loop
// (positioning_runner.h) with the node's settings (its law, gains, delay and
// clamp), the task's steps 0..N, and the command clamped to [-1, 1] by the
// drone as the sim (and the drivers) do. A rostest checks the ROS loop
// equals it to the last bit.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "aurora_control/loop/delayed_controller.h"
#include "aurora_control/loop/predicted_loop.h"
#include "aurora_control/task/tracking.h"

namespace aurora_control {

struct FlightResult {
  long steps = 0;                     // model steps run
  double iae = 0, itae = 0, iasc = 0; // the controller's running metrics at the end
  double rms_tracking_error = 0;      // [m] trackingError over the steps run (state k, reference k)
  double max_tracking_error = 0;      // [m]
  double final_pos[3] = {0, 0, 0};    // [m]
};

// A flight of law `Law` (on its vehicle): `iterations` iterations of the
// runner, with the predictor `predictor` when it is on, observe(
// LoopObservation, tracking error of step k [m]) after each. Iteration k
// hands state k (the state at task time k Ts) to the controller with the
// reference of that time: `iterations` = taskStepCount() flies a task's
// steps 0..N.
template <class Law, typename Observer>
FlightResult flyLaw(const StudyRun<typename Law::Data, double>& run, const RunnerConfig<double>& cfg,
                    const PredictorRun<typename Law::Vehicle, double>& predictor, long iterations,
                    Observer&& observe) {
  FlightResult r;
  double sum_sq = 0.0;
  const RunnerResult done =
      runLoop<Law>(run, cfg, predictor, iterations, [&](const LoopObservation<typename Law::Vehicle, double>& o) {
        const double e = trackingError(o.step.ref, o.X_before);  // state k against reference k
        sum_sq += e * e;
        r.max_tracking_error = std::max(r.max_tracking_error, e);
        observe(o, e);
      });
  r.steps = done.steps;
  r.iae = done.iae, r.itae = done.itae, r.iasc = done.iasc;
  r.rms_tracking_error = r.steps > 0 ? std::sqrt(sum_sq / double(r.steps)) : 0.0;
  for (int i = 0; i < 3; ++i) r.final_pos[i] = done.final_pos[i];
  return r;
}

// The same without a predictor.
template <class Law, typename Observer>
FlightResult flyLaw(const StudyRun<typename Law::Data, double>& run, const RunnerConfig<double>& cfg, long iterations,
                    Observer&& observe) {
  return flyLaw<Law>(run, cfg, PredictorRun<typename Law::Vehicle, double>{}, iterations, observe);
}

// A flight of law `Law` on its vehicle, ready to fly (flyLaw): its run,
// the runner's settings, its predictor (off unless its controller file
// has one), its steps 0..N, the law's name and its rate [Hz] where it has
// one of its own (0: the vehicle's).
template <class L>
struct LawFlight {
  using Law = L;
  StudyRun<typename Law::Data, double> run;
  RunnerConfig<double> cfg;
  PredictorRun<typename Law::Vehicle, double> predictor;
  long steps = 0;
  std::string law = Law::name();
  double rate = 0.0;
};

// The flight f, its `iterations` iterations (its steps by default).
template <class L, typename Observer>
FlightResult flyLaw(const LawFlight<L>& f, long iterations, Observer&& observe) {
  return flyLaw<L>(f.run, f.cfg, f.predictor, iterations, observe);
}
template <class L, typename Observer>
FlightResult flyLaw(const LawFlight<L>& f, Observer&& observe) {
  return flyLaw(f, f.steps, observe);
}

// A flight of `Law` with a loop's settings (its gains, the model it
// inverts, clamp, link, delay) on plant `p`, which clamps what it receives
// (the sim's clamp).
template <class Law>
LawFlight<Law> settingsFlight(const typename Law::Vehicle::template Params<double>& p,
                              const LawSettings<typename Law::Data>& settings, const Task<double>& task, long iterations) {
  LawFlight<Law> f;
  f.run = StudyRun<typename Law::Data, double>{p, settings.vehicle, settings.gains, settings.delay};
  f.cfg.task = task;
  f.cfg.clamp_commands = settings.clamp_commands;
  f.cfg.clamp_at_drone = true;  // the sim's clamp
  f.cfg.link = settings.link;
  f.steps = iterations;
  return f;
}

// The same with the settings' law (chosen at run time).
template <class Data, typename Observer>
FlightResult runFlight(const typename Data::Vehicle::template Params<double>& p, const LawSettings<Data>& settings,
                       const Task<double>& task, long iterations, Observer observe) {
  FlightResult r;
  settings.withLawType([&](auto law) {
    using Law = decltype(law);
    const LawFlight<Law> f = settingsFlight<Law>(p, settings, task, iterations);
    r = flyLaw(f, observe);
  });
  return r;
}

}  // namespace aurora_control
