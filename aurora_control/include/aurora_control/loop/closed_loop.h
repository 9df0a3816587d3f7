// The closed loop, written once (docs/architecture.md, "The loop and its
// callers"): iteration k (0-based, task time k Ts) takes the delayed state
// xc the caller picked from its history (the delay rule, delay_buffer.h),
// the task's reference at k Ts, the law's command, the controller's optional
// clamp, the metrics at the loop clock's time, the drone's optional clamp,
// one model step and the checks on the true error. The offline runner
// (positioning_runner.h: the sweep's scalar backend, the flight tool, each
// CUDA thread) and the SIMD engine (on lane batches) run loopIteration;
// the controller node and replay call its controller half
// (controllerCommand, through DelayedController), the sim node the drone's
// (aurora_sim/vehicle/vehicle_half.h, its clamp and step, which droneHalf
// calls).
// Generic in the law and its vehicle (docs/architecture.md, "Laws" and
// "Vehicles": the lists of law/other_laws.h and vehicle_type.h).
#pragma once

#include "aurora_control/law/law_sample.h"
#include "aurora_control/loop/delay_buffer.h"
#include "aurora_control/loop/feasibility.h"
#include "aurora_control/task/task.h"
#include "aurora_sim/vehicle/vehicle_half.h"
#include "aurora_common/scalar_math.h"

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

// What stays fixed during a run of a law with data `Data` (control_law.h:
// its vehicle, gains and memory): the simulated vehicle, the model the law
// inverts (nominal; differs from `plant` in a robustness study), the gains
// and the metric criteria.
template <class Data, typename T>
struct LoopParams {
  using Vehicle = typename Data::Vehicle;
  typename Vehicle::template Params<T> plant;
  typename Vehicle::template Params<T> model;
  typename Data::template Gains<T> gains;
  FeasibilityCriteria<T> criteria;
};

// What the controller's half changes (controllerHalf): the metrics, the
// law's own memory and the loop clock it reads. The controller node keeps
// one (delayed_controller.h); a loop's state (below) has the same members
// beside the vehicle's (kept in one struct, in this order: the kernels'
// registers and spills depend on it).
template <class Data, typename T, typename Mask>
struct ControllerState {
  PositioningMetrics<T, Mask> metrics;
  typename Data::template Memory<T> memory;  // the law's own state (the underactuated law's; empty for others)
  T t;  // the loop clock: metric time of the next iteration
};

// What changes during a run.
template <class Data, typename T, typename Mask>
struct LoopState {
  using Vehicle = typename Data::Vehicle;
  typename Vehicle::template State<T> model;
  PositioningMetrics<T, Mask> metrics;
  typename Data::template Memory<T> memory;  // the law's own state (the underactuated law's; empty for others)
  T t;              // the loop clock: metric time of the next iteration
  T initial_error;  // |Xd(0) - X0|, for check 4

  // A new run: the vehicle's start (at the origin, at rest), towards the
  // task's first reference `desired`.
  AURORA_HD void reset(const typename Vehicle::template Params<T>& plant, const T desired[3]) {
    Vehicle::start(plant, model);
    metrics.reset();
    memory.reset();
    t = T(0);
    T e[3];
    for (int i = 0; i < 3; ++i) e[i] = desired[i] - model.X[Vehicle::kPosition + i];
    initial_error = norm3(e);
  }
};

// The controller's half of an iteration: law `Law` on the state xc it
// received, towards `ref`. U_law: the command as the law computed it; U: as
// sent (clamped to the vehicle's limits when `clamp`); err: ref - xc
// position, the metrics' error.
template <class Law, typename T, class Params, class Gains, class Memory>
AURORA_HD inline void controllerCommand(const Params& model, const Gains& gains, Memory& memory,
                                        const Reference<T>& ref, const T xc[Law::Vehicle::kStates], bool clamp,
                                        T U_law[Law::Vehicle::kInputs], T U[Law::Vehicle::kInputs], T err[3]) {
  using Vehicle = typename Law::Vehicle;
  Law::command(model, gains, memory, ref, xc, U_law, err);
  for (int i = 0; i < Vehicle::kInputs; ++i) U[i] = clamp ? Vehicle::limitInput(model, i, U_law[i]) : U_law[i];
}

// What an iteration hands its observer besides the state.
template <typename T, int Inputs>
struct LoopStep {
  Reference<T> ref;  // the reference of iteration k
  T U[Inputs];       // the command the vehicle applied (after its clamp)
};

// The controller's side of iteration k (k as T: a batch of per-lane step
// numbers on SIMD lanes) with xc the state it received: the reference at
// task time k Ts, the law, its clamp and the metrics at the clock's time
// s.t. Writes the command it sends to U, the law's unclamped command to
// U_law and the position error (ref - xc) to err; returns the reference.
// `s`: a ControllerState, or a LoopState (the same members).
// Every loop runs it: the offline runner, the SIMD engine and each CUDA
// thread (through loopIteration), and the controller node and replay
// (through DelayedController, with the node's reference as the task).
template <class Law, class Data, typename T, typename TaskT, class State>
AURORA_HD inline Reference<T> controllerHalf(const LoopParams<Data, T>& p, const TaskT& task, const ClampPolicy& clamp,
                                             const T& k, const T xc[Law::Vehicle::kStates], State& s,
                                             T U_law[Law::Vehicle::kInputs],
                                             T U[Law::Vehicle::kInputs], T err[3]) {
  const Reference<T> ref = task.at(taskTime(k, p.plant.Ts));
  controllerCommand<Law>(p.model, p.gains, s.memory, ref, xc, clamp.at_controller, U_law, U, err);
  s.metrics.template accumulate<Law::Vehicle::kInputs>(p.criteria, err, U, s.t);
  return ref;
}

// The same for a loop that needs the command it sends only.
template <class Law, class Data, typename T, typename TaskT, class State>
AURORA_HD inline Reference<T> controllerHalf(const LoopParams<Data, T>& p, const TaskT& task, const ClampPolicy& clamp,
                                             const T& k, const T xc[Law::Vehicle::kStates], State& s,
                                             T U[Law::Vehicle::kInputs]) {
  T U_law[Law::Vehicle::kInputs], err[3];
  return controllerHalf<Law>(p, task, clamp, k, xc, s, U_law, U, err);
}

// The vehicle's side: the command it received (the sent one over an ideal
// link), its clamp, one model step, the checks on the true error against
// `ref`, the clock. Writes the command applied to `applied`.
template <class Data, typename T, typename Mask>
AURORA_HD inline void droneHalf(const LoopParams<Data, T>& p, const ClampPolicy& clamp, const Reference<T>& ref,
                                const T received[Data::Vehicle::kInputs], LoopState<Data, T, Mask>& s,
                                T applied[Data::Vehicle::kInputs]) {
  using Vehicle = typename Data::Vehicle;
  aurora_sim::vehicleHalf<Vehicle>(p.plant, clamp.at_drone, received, s.model, applied);  // the simulator node's too
  T e[3];
  for (int i = 0; i < 3; ++i) e[i] = ref.pos[i] - s.model.X[Vehicle::kPosition + i];
  s.metrics.check(p.criteria, norm3(e), s.initial_error);
  s.t = nextLoopTime(s.t, p.plant.Ts);
}

// The early stop, written once: with early_stop, a run ends at its first
// failed check (masks of lanes on SIMD batches).
template <typename Mask>
AURORA_HD inline Mask stoppedEarly(bool early_stop, const Mask& feasible) {
  return early_stop ? !feasible : (feasible & !feasible);
}

// Iteration k as a number of the loop's scalar (the SIMD engine overloads
// it for lanes).
template <typename K, typename T>
AURORA_HD inline void iterationNumber(const K& k, T& out) {
  out = T(k);
}

// Steps 1-2 of iteration k (loopIteration below): the history keeps X_k,
// the link picks the step whose state the controller receives, read back
// into xc. Returns that step. A formation runs it for each robot before its
// layer (formation_runner.h).
template <class Data, typename T, typename Mask, typename K, class History, class Link>
AURORA_HD inline K receiveState(const K& k, History& history, Link& link, const LoopState<Data, T, Mask>& s,
                                T xc[Data::Vehicle::kStates]) {
  history.push(s.model.X);  // H(k + 1) = X_k
  const K received = link.uplinkIndex(k);
  history.read(received, xc);
  return received;
}

// Steps 3-5 of iteration k on the state xc received: the controller's half
// towards task's reference, the command through the link's downlink, the
// vehicle's half. Returns the reference and the command applied.
template <class Law, class Data, typename T, typename Mask, typename TaskT, typename K, class Link>
AURORA_HD inline LoopStep<T, Data::Vehicle::kInputs> actOn(const LoopParams<Data, T>& p, const TaskT& task,
                                                           const ClampPolicy& clamp, const K& k,
                                                           const T xc[Data::Vehicle::kStates], Link& link,
                                                           LoopState<Data, T, Mask>& s) {
  T U[Data::Vehicle::kInputs], kt;
  iterationNumber(k, kt);
  LoopStep<T, Data::Vehicle::kInputs> step;
  step.ref = controllerHalf<Law>(p, task, clamp, kt, xc, s, U);
  link.downlink(k, U, U);
  droneHalf(p, clamp, step.ref, U, s, step.U);
  return step;
}

// One iteration k of the closed loop, written once for every loop that runs
// one (docs/architecture.md, "One iteration"): the offline runner (the
// sweep's scalar backend, the flight tool, each CUDA thread) and the SIMD
// engine on lanes; a formation runs its two parts around its layer. In order:
//  1. history.push(X_k): the history keeps the state (what the law reads);
//  2. link.uplinkIndex(k): the step whose state the controller receives
//     (the delay rule over an ideal link), read back from the history;
//  3. the controller's half (reference at k Ts, law, its clamp, metrics);
//  4. link.downlink(k, U, U): the command the vehicle receives;
//  5. the vehicle's half (its clamp, one model step, checks, clock);
//  6. observe(step, xc, received);
//  7. the early stop: returns whether the run ends here.
// `k` counts as the history and the link count (long; integer lanes on the
// SIMD engine; iterationNumber gives it in T for the task's time). History and
// link are policies with this interface for scalars (StateHistory,
// IdealLink, ModelLink) and for lanes (the SIMD engine's).
template <class Law, class Data, typename T, typename Mask, typename TaskT, typename K, class History, class Link,
          class Observer>
AURORA_HD inline Mask loopIteration(const LoopParams<Data, T>& p, const TaskT& task, const ClampPolicy& clamp,
                                    bool early_stop, const K& k, History& history, Link& link,
                                    LoopState<Data, T, Mask>& s, Observer&& observe) {
  T xc[Data::Vehicle::kStates];
  const K received = receiveState(k, history, link, s, xc);
  const LoopStep<T, Data::Vehicle::kInputs> step = actOn<Law>(p, task, clamp, k, xc, link, s);
  observe(step, xc, received);
  return stoppedEarly(early_stop, s.metrics.feasible());
}

// The history of one run (scalars): the last Capacity states as law `Law`
// reads them (delay_buffer.h); read(j) gives back the state of step j.
// The controller holds the newest state it received: a link's loss burst
// may leave it on a step older than the ring holds (it arrived, young, long
// ago), so read() latches what it read and reads the ring again only for
// another step. A new arrival is at most the link's latency old
// (LinkParams::historyNeeded, below Capacity), so the run does not depend
// on the ring's size.
template <class Law, typename T, int Capacity>
class StateHistory {
 public:
  using Sample = LawSample<T, Law>;
  AURORA_HD void push(const T X[Law::Vehicle::kStates]) { ring_.push(Sample::fromState(X)); }
  AURORA_HD void read(long step, T X[Law::Vehicle::kStates]) {
    if (step != held_step_) held_ = ring_.at(step), held_step_ = step;
    held_.toState(X);
  }

 private:
  DelayBuffer<Sample, Capacity> ring_;  // on the stack: Capacity x the law's width, no allocation
  Sample held_;
  long held_step_ = -1;  // the step of held_ (none yet)
};

// Number of loop iterations of `while t < duration: ...; t += Ts` with t
// accumulated in double (1801 for 60 s at 1/30 s). Every precision runs this
// many, so float and double sweeps cover the same time.
inline long studyIterationCount(double duration, double Ts) {
  long n = 0;
  for (double t = 0.0; t < duration; t += Ts) ++n;
  return n;
}

}  // namespace aurora_control
