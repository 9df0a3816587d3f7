// One iteration of the positioning delay study (docs/delay-and-study.md, "The
// positioning delay study", loop steps 2-5), shared by the scalar runner,
// the SIMD sweep engine and the CUDA kernel so the physics and the law exist
// once. History handling (step 1 and 6) is the caller's: a scalar DelayBuffer
// here, per-lane gathers in the batch engines.
#pragma once

#include "aurora_control/feasibility.h"
#include "aurora_control/control_law.h"
#include "aurora_control/task.h"
#include "aurora_sim/ardrone_model.h"
#include "aurora_sim/scalar_math.h"

namespace aurora_control {

template <typename T, typename Mask>
struct PositioningSim {
  aurora_sim::ArdroneState<T> model;
  PositioningMetrics<T, Mask> metrics;
  UnderactuatedMemory<T> memory;  // the underactuated law's own state (unused by the PD law)
  T t;              // study time, by repeated addition of Ts as the reference does
  T initial_error;  // |Xd(0) - X0|, for check 4

  AURORA_HD void reset(const T desired[3]) {
    model.reset();
    metrics.reset();
    memory.reset();
    t = T(0);
    T e[3];
    for (int i = 0; i < 3; ++i) e[i] = desired[i] - model.X[aurora_sim::kX + i];
    initial_error = norm3(e);
  }
};

// Loop steps 2-5 with the delayed state xc already picked and the task's
// reference of this iteration: law `Law` (control_law.h) inverting `model`,
// the optional clamp, metrics on the controller's error, one model step of
// the simulated drone `plant`, the checks on the true error (the tracking
// error for a trajectory). Writes the command applied to the model to U.
template <LawType Law, typename T, typename Mask>
AURORA_HD inline void positioningIteration(const aurora_sim::ArdroneParams<T>& plant,
                                           const aurora_sim::ArdroneParams<T>& model,
                                           const FeasibilityCriteria<T>& criteria, const LawGains<T>& gains,
                                           const Reference<T>& ref, bool clamp_commands,
                                           const T xc[aurora_sim::kStateSize], PositioningSim<T, Mask>& s,
                                           T U[4]) {
  T err[3];
  lawCommand<Law>(model, gains, s.memory, ref, xc, U, err);
  if (clamp_commands) {
    for (int i = 0; i < 4; ++i) U[i] = aurora_sim::clampUnit(U[i]);
  }
  s.metrics.accumulate(criteria, err, U, s.t);
  aurora_sim::ardroneStep(plant, s.model, U, aurora_sim::Disturbance<T>::zero());
  T e[3];
  for (int i = 0; i < 3; ++i) e[i] = ref.pos[i] - s.model.X[aurora_sim::kX + i];
  s.metrics.check(criteria, norm3(e), s.initial_error);
  s.t = s.t + plant.Ts;
}

// Number of loop iterations of `while t < duration: ...; t += Ts` with t
// accumulated in double (1801 for 60 s at 1/30 s). Every precision runs this
// many, so float and double sweeps cover the same time.
inline long studyIterationCount(double duration, double Ts) {
  long n = 0;
  for (double t = 0.0; t < duration; t += Ts) ++n;
  return n;
}

}  // namespace aurora_control
