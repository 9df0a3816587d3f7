// One whole flight offline, with either law and any task, computed exactly
// as the lockstep ROS loop computes it: iteration k (0-based) hands state k
// to the controller core the node uses (DelayedController: delay buffer,
// law, clamp, metrics), asks for the reference at task time k Ts, and steps
// the model with the command clamped to [-1, 1] as the sim (and the drivers)
// do. A rostest checks the ROS loop equals it to the last bit.
#pragma once

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "aurora_control/delayed_controller.h"
#include "aurora_control/limits.h"
#include "aurora_control/task.h"
#include "aurora_control/tracking.h"
#include "aurora_control/waypoint_task.h"
#include "aurora_sim/ardrone_model.h"

namespace aurora_control {

struct FlightResult {
  long steps = 0;                     // model steps run
  double iae = 0, itae = 0, iasc = 0; // the controller's running metrics at the end
  double rms_tracking_error = 0;      // [m] trackingError over the steps run (state k, reference k)
  double max_tracking_error = 0;      // [m]
  double final_pos[3] = {0, 0, 0};    // [m]
};

constexpr int kFlightHistory = kDelayHistory;  // the node's history (limits.h)

// observe(k, state after step k, reference of iteration k - 1, command of
// iteration k - 1) after each model step (k 1-based). Iteration k hands
// state k (the state at task time k Ts) to the controller with the
// reference of that time: `iterations` = taskStepCount() flies a task's
// steps 0..N.
template <typename Observer>
FlightResult runFlight(const aurora_sim::ArdroneParams<double>& p, const ControllerSettings& settings,
                       const Task<double>& task, long iterations, Observer observe) {
  if (settings.delay < 0 || settings.delay >= kFlightHistory) {
    throw std::invalid_argument("delay " + std::to_string(settings.delay) +
                                " samples is outside the accepted range [0, " +
                                std::to_string(kFlightHistory - 1) + "]");
  }
  std::unique_ptr<DelayedController<kFlightHistory>> core(new DelayedController<kFlightHistory>());
  core->settings = settings;
  aurora_sim::ArdroneState<double> model;
  model.reset();
  FlightResult r;
  double sum_sq = 0.0;
  for (long k = 0; k < iterations; ++k) {
    StateSample sample;
    sample.step = k;
    for (int i = 0; i < aurora_sim::kStateSize; ++i) sample.X[i] = model.X[i];
    core->push(sample);
    const Reference<double> ref = task.at(WaypointTask<double>::timeOfStep(k, p.Ts));
    const double e = trackingError(ref, sample.X);  // state k against reference k
    sum_sq += e * e;
    r.max_tracking_error = std::max(r.max_tracking_error, e);
    const ControlOutput out = core->compute(ref);
    double U[4];
    for (int i = 0; i < 4; ++i) U[i] = aurora_sim::clampUnit(out.U[i]);  // the sim's clamp
    aurora_sim::ardroneStep(p, model, U, aurora_sim::Disturbance<double>::zero());
    r.iae = out.iae, r.itae = out.itae, r.iasc = out.iasc;
    r.steps = k + 1;
    observe(k + 1, model, ref, U);
  }
  r.rms_tracking_error = r.steps > 0 ? std::sqrt(sum_sq / double(r.steps)) : 0.0;
  for (int i = 0; i < 3; ++i) r.final_pos[i] = model.X[i];
  return r;
}

}  // namespace aurora_control
