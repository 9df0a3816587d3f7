// The closed loop, written once (docs/architecture.md, "The loop and its
// callers"): iteration k (0-based, task time k Ts) takes the delayed state
// xc the caller picked from its history (the delay rule, delay_buffer.h),
// the task's reference at k Ts, the law's command, the controller's optional
// clamp, the metrics at the loop clock's time, the drone's optional clamp,
// one model step and the checks on the true error. The offline runner
// (positioning_runner.h: the sweep's scalar backend, the flight tool, each
// CUDA thread) and the SIMD engine (on lane batches) call closedLoopStep;
// the controller node and replay call its controller half
// (controllerCommand, through DelayedController), the sim node the drone's.
#pragma once

#include "aurora_control/control_law.h"
#include "aurora_control/feasibility.h"
#include "aurora_control/task.h"
#include "aurora_sim/ardrone_model.h"
#include "aurora_sim/scalar_math.h"

namespace aurora_control {

// The loop clock, the metric time (docs/architecture.md, same section):
// t_0 = 0, t_(k+1) = t_k + Ts, repeated addition in the run's precision (the
// original study's `t += Ts`). Offline loops advance it once per iteration.
template <typename T>
AURORA_HD inline T nextLoopTime(const T& t, const T& Ts) {
  return t + Ts;
}

// The same clock for a caller that sees states by their step numbers (the
// controller node, replay): t of step k by the same additions, kept
// incrementally (one addition per new step; a step going back restarts it).
class LoopClock {
 public:
  double at(long step, double Ts) {
    if (step < step_) step_ = 0, t_ = 0.0;
    for (; step_ < step; ++step_) t_ = nextLoopTime(t_, Ts);
    return t_;
  }

 private:
  long step_ = 0;
  double t_ = 0.0;
};

// Where a command is clamped to [-1, 1]. The study clamps nowhere; the
// AR.Drone and Bebop drivers (and the sim node, as they do) clamp what they
// receive; the controller node may clamp what it sends (clamp_commands).
struct ClampPolicy {
  bool at_controller = false;
  bool at_drone = false;
};

// What stays fixed during a run: the simulated drone, the model the
// underactuated law inverts (nominal; differs from `plant` in a robustness
// study), the gains and the metric criteria.
template <typename T>
struct LoopParams {
  aurora_sim::ArdroneParams<T> plant;
  aurora_sim::ArdroneParams<T> model;
  LawGains<T> gains;
  FeasibilityCriteria<T> criteria;
};

// What changes during a run.
template <typename T, typename Mask>
struct LoopState {
  aurora_sim::ArdroneState<T> model;
  PositioningMetrics<T, Mask> metrics;
  UnderactuatedMemory<T> memory;  // the underactuated law's own state (unused by the PD law)
  T t;              // the loop clock: metric time of the next iteration
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

// The controller's half of an iteration: law `Law` on the state xc it
// received, towards `ref`. U_law: the command as the law computed it; U: as
// sent (clamped when `clamp`); err: ref - xc position, the metrics' error.
template <LawType Law, typename T>
AURORA_HD inline void controllerCommand(const aurora_sim::ArdroneParams<T>& model, const LawGains<T>& gains,
                                        UnderactuatedMemory<T>& memory, const Reference<T>& ref,
                                        const T xc[aurora_sim::kStateSize], bool clamp, T U_law[4], T U[4],
                                        T err[3]) {
  lawCommand<Law>(model, gains, memory, ref, xc, U_law, err);
  for (int i = 0; i < 4; ++i) U[i] = clamp ? aurora_sim::clampUnit(U_law[i]) : U_law[i];
}

// What an iteration hands its observer besides the state.
template <typename T>
struct LoopStep {
  Reference<T> ref;  // the reference of iteration k
  T U[4];            // the command the drone applied (after its clamp)
};

// The controller's side of iteration k (k as T: a batch of per-lane step
// numbers on SIMD lanes) with xc the state it received: the reference at
// task time k Ts, the law, its clamp and the metrics. Writes the command it
// sends to U; returns the reference.
template <LawType Law, typename T, typename Mask, typename TaskT>
AURORA_HD inline Reference<T> controllerHalf(const LoopParams<T>& p, const TaskT& task, const ClampPolicy& clamp,
                                             const T& k, const T xc[aurora_sim::kStateSize], LoopState<T, Mask>& s,
                                             T U[4]) {
  const Reference<T> ref = task.at(taskTime(k, p.plant.Ts));
  T U_law[4], err[3];
  controllerCommand<Law>(p.model, p.gains, s.memory, ref, xc, clamp.at_controller, U_law, U, err);
  s.metrics.accumulate(p.criteria, err, U, s.t);
  return ref;
}

// The drone's side: the command it received (the sent one over an ideal
// link), its clamp, one model step, the checks on the true error against
// `ref`, the clock. Writes the command applied to `applied`.
template <typename T, typename Mask>
AURORA_HD inline void droneHalf(const LoopParams<T>& p, const ClampPolicy& clamp, const Reference<T>& ref,
                                const T received[4], LoopState<T, Mask>& s, T applied[4]) {
  for (int i = 0; i < 4; ++i) applied[i] = clamp.at_drone ? aurora_sim::clampUnit(received[i]) : received[i];
  aurora_sim::ardroneStep(p.plant, s.model, applied, aurora_sim::Disturbance<T>::zero());
  T e[3];
  for (int i = 0; i < 3; ++i) e[i] = ref.pos[i] - s.model.X[aurora_sim::kX + i];
  s.metrics.check(p.criteria, norm3(e), s.initial_error);
  s.t = nextLoopTime(s.t, p.plant.Ts);
}

// Iteration k of the closed loop over an ideal command path: both halves,
// the sent command applied at once. Advances `s` by one model step.
template <LawType Law, typename T, typename Mask, typename TaskT>
AURORA_HD inline LoopStep<T> closedLoopStep(const LoopParams<T>& p, const TaskT& task, const ClampPolicy& clamp,
                                            const T& k, const T xc[aurora_sim::kStateSize],
                                            LoopState<T, Mask>& s) {
  LoopStep<T> step;
  T U[4];
  step.ref = controllerHalf<Law>(p, task, clamp, k, xc, s, U);
  droneHalf(p, clamp, step.ref, U, s, step.U);
  return step;
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
