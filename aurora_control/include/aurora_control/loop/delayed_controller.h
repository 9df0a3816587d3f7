// The controller node's per-cycle computation, ROS-free: the controller's
// side of the one iteration (closed_loop.h) in its incremental form.
// Received states go into the delay buffer (and through the node's link);
// each cycle runs the iteration's controller half, controllerHalf, with the
// node's reference: the chosen law (the delay study's PD law with
// saturation, eq. 3.1, or the underactuated 12-gain law) on the delivered
// state (docs/delay-and-study.md), the optional clamp (as the drivers
// clamp), the study's metrics at the loop clock's time, once per state
// step; then the link's downlink. The node and the offline `replay` tool
// both call this class, so a replay of a bag reproduces every command.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>

#include "aurora_control/loop/closed_loop.h"
#include "aurora_control/loop/delay_buffer.h"
#include "aurora_control/link/link.h"
#include "aurora_control/loop/node_link.h"
#include "aurora_control/loop/feasibility.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/task/trajectory_task.h"
#include "aurora_control/loop/predicted_loop.h"
#include "aurora_common/scalar_math.h"
#include "aurora_sim/state_index.h"
#include "aurora_sim/vehicle/vehicle_type.h"  // kMaxStates: the list's largest state

namespace aurora_control {

struct StateSample {
  long step = 0;           // the source's sample index (DroneState.step)
  int64_t stamp_ns = 0;    // header stamp [ns]
  double X[aurora_sim::kMaxStates] = {};  // the vehicle's state (its kStates first; the rest 0)
};

// What the controller core is given for any law: the uplink's base delay,
// the rest of the link, the clamp and the vehicle's sample time.
struct LoopSettings {
  long delay = 0;          // [samples] the uplink's base delay
  LinkParams link;         // the rest of the link (link.h, docs/links.md); apply with configureLink()
  bool clamp_commands = true;
  double Ts = 1.0 / 30.0;  // [s], the vehicle's sample time (the loop clock's step)
  PredictorForm predictor = PredictorForm::kOff;  // the state predictor's form (apply with configurePredictor)
};

namespace settings_detail {
template <class Gains>
Gains preset(decltype(Gains::defaults())*) {
  return Gains::defaults();
}
template <class Gains>
Gains preset(...) {
  return Gains{};
}
}  // namespace settings_detail

// The gains a law's loop starts with before its controller file's (its
// Gains' defaults(), where it has one).
template <class Data>
typename Data::template Gains<double> presetGains() {
  return settings_detail::preset<typename Data::template Gains<double>>(nullptr);
}

// The settings of a loop of laws of one Data (other_laws.h, "family"): the
// law that flies (its index in the family, chosen by name at start-up:
// the AR.Drone's PD or underactuated law; any other law alone), its gains
// and the model it inverts (its vehicle file).
template <class D>
struct LawSettings : LoopSettings {
  using Data = D;
  int law = 0;  // the law that flies: withLawOf<Data>'s index
  typename Data::template Gains<double> gains = presetGains<Data>();
  typename Data::Vehicle::template Params<double> vehicle{};

  // Settings flying Law (a law of Data's family).
  template <class Law>
  static LawSettings flying() {
    static_assert(std::is_same<typename Law::Data, Data>::value, "a law of this loop's family");
    LawSettings s;
    s.law = std::max(familyIndex<Law>(), 0);
    return s;
  }
  LoopParams<Data, double> loopParams(const FeasibilityCriteria<double>& criteria) const {
    return LoopParams<Data, double>{vehicle, vehicle, gains, criteria};
  }
  // Calls f(the law in force as a type).
  template <class F>
  void withLawType(F&& f) const {
    withLawOf<Data>(law, f);
  }
};

// The name of the law the settings fly.
template <class Data>
const char* lawNameOf(const LawSettings<Data>& set) {
  const char* name = "";
  set.withLawType([&](auto law) { name = law.name(); });
  return name;
}

// The commands of any vehicle: its kInputs first (at most 4), the rest 0.
constexpr int kMaxInputs = aurora_sim::kCommandSize;

struct ControlOutput {
  double U[kMaxInputs] = {0, 0, 0, 0};            // as the vehicle applies it (over an ideal link: as sent)
  double U_sent[kMaxInputs] = {0, 0, 0, 0};       // as the controller sent it (clamped when configured)
  double U_unclamped[kMaxInputs] = {0, 0, 0, 0};  // as the law computed it
  double position_error[3] = {0, 0, 0};  // desired - used position [m]
  const StateSample* used = nullptr;     // the (delayed) state the law used
  long delay_in_force = 0;               // samples between the newest state and `used`
  long delay_pending = 0;                // further states before settings.delay is in force
  bool state_arrived = true;             // the newest state step brought a newer state to the law
  long command_age = 0;                  // steps since the command the drone applies was sent (-1: none yet)
  bool drone_hovers = false;             // the drone hovers: no command arrived yet, or none for cmd_timeout
  long uplink_losses = 0, downlink_losses = 0;  // packets lost so far
  double iae = 0, itae = 0, iasc = 0;    // running metrics after this cycle
  // The state predictor (docs/predictor.md): whether the law flew on its
  // prediction, the step predicted, how many steps it stepped, the state.
  bool predicted = false;
  long prediction_step = 0, prediction_horizon = 0;
  double X_predicted[aurora_sim::kMaxStates] = {};
};

// The node's reference as controllerHalf's task: the node computes it from
// its own task clock (which starts after take-off), so it holds at any time.
struct GivenReference {
  Reference<double> ref;
  Reference<double> at(double) const { return ref; }
};

// A reference at rest at point `desired` (positioning, a hold).
inline Reference<double> restingAt(const double desired[3]) {
  Reference<double> r;
  for (int i = 0; i < 3; ++i) r.pos[i] = desired[i], r.vel[i] = 0.0, r.acc[i] = 0.0;
  r.yaw = r.yaw_rate = r.yaw_acc = 0.0;
  return r;
}

// Settings: LawSettings<Data> (any law of Data's family).
template <int Capacity, class Settings>
class DelayedController {
 public:
  static constexpr long kMaxDelay = Capacity - 1;
  using Data = typename Settings::Data;
  using Vehicle = typename Data::Vehicle;
  static_assert(Vehicle::kStates <= aurora_sim::kMaxStates, "a state sample holds the vehicle's state");
  static_assert(Vehicle::kInputs <= kMaxInputs, "a control output holds the vehicle's command");

  Settings settings;

  DelayedController() { reset(); }

  void reset() {
    history_.clear();
    held_valid_ = false;
    side_.memory.reset();
    link_.reset();
    resetMetrics();
    startPredictor();
  }

  // The state predictor (docs/predictor.md; off by default): the law flies
  // on its prediction of the state its command acts on.
  void configurePredictor(const PredictorRun<Vehicle, double>& p) {
    predictor_run_ = p;
    startPredictor();
  }
  const PredictorRun<Vehicle, double>& predictor() const { return predictor_run_; }

  // Applies settings.link (and settings.delay as its uplink delay); the
  // channels start afresh. An ideal link keeps the delay rule.
  // `key`: the draws' key besides the seed (a formation's drone index).
  void configureLink(uint64_t key = 0) { link_.configure(settings.link, settings.delay, settings.Ts, key); }

  // The metrics start again (e.g. when the task starts after take-off).
  void resetMetrics() {
    side_.metrics.reset();
    metrics_step_ = -1;
  }

  // Adds a received state. A state whose step equals the newest one is a
  // re-send (lockstep) and is not added (returns false); a step going back
  // means the source was reset: the history and metrics start again.
  bool push(const StateSample& s) {
    if (history_.size() > 0) {
      const long newest = history_.delayed(0).step;
      if (s.step == newest) return false;
      if (s.step < newest) reset();
    }
    history_.push(s);
    if (link_.active()) {
      link_.setDelay(settings.delay);
      used_step_ = link_.stateReceived(s.step);
      holdUsedState();
    }
    return true;
  }

  bool empty() const { return history_.size() == 0; }
  // Further states before a delay of d samples is in force (0 once it is).
  long delayPending(long d) const { return history_.pendingUntilInForce(d); }
  const StateSample& newest() const { return history_.delayed(0); }

  // One cycle of the law towards a point at rest (positioning). Requires !empty().
  ControlOutput compute(const double desired[3]) { return compute(restingAt(desired)); }

  // One cycle of the law on the delayed state towards `ref`. The PD law uses
  // position, velocity and acceleration; the underactuated law also the yaw
  // and its rates (feed-forward). Requires !empty().
  // The state the law uses this cycle: the delay rule's, or the newest its
  // link delivered. Requires !empty().
  const StateSample& delivered() const {
    if (!link_.active()) return history_.delayed(settings.delay);
    return held_valid_ ? held_ : newest();  // newest: before the link delivered any state
  }

  // The state the law flies on this cycle: the predictor's from the
  // delivered state, or that state. A formation's layer reads it before the
  // law runs (formation_controller.h); predicting again for the same cycle
  // gives the same state (StatePredictor::predict). Requires !empty().
  StateSample flownState() {
    StateSample predicted;
    ControlOutput unused;
    return predictedFrom(delivered(), predicted, unused);
  }

  ControlOutput compute(const Reference<double>& ref) {
    ControlOutput out;
    const StateSample& used = delivered();
    out.used = &used;
    out.delay_in_force = link_.active() ? newest().step - used.step : history_.delayInForce(settings.delay);
    out.delay_pending = link_.active() ? 0 : history_.pendingUntilInForce(settings.delay);
    StateSample predicted;
    controllerSide(ref, predictedFrom(used, predicted, out), out);
    metricsOut(out);
    overLink(out);
    if (predictor_) predictor_->sent(newest().step, out.U_sent);
    return out;
  }

  // The command while the state is stale: hover (all zero); the metrics
  // gain nothing (zero error, zero command).
  ControlOutput hover() {
    ControlOutput out;
    out.used = &newest();
    const long step = newest().step;
    if (step != metrics_step_) {
      side_.metrics.template accumulate<Vehicle::kInputs>(criteria_, out.position_error, out.U,
                                                             clock_.at(step, settings.Ts));
      metrics_step_ = step;
    }
    metricsOut(out);
    if (predictor_) predictor_->sent(step, out.U_sent);
    return out;
  }

 private:
  void startPredictor() {
    predictor_.reset();
    if (!predictor_run_.on()) return;
    predictor_.reset(new HostPredictor<Vehicle, double>(predictor_run_.form, predictor_run_.model,
                                                        predictor_run_.path));
  }

  // The state the law flies on: the predictor's from `used`, or `used`.
  const StateSample& predictedFrom(const StateSample& used, StateSample& predicted, ControlOutput& out) {
    if (!predictor_) return used;
    predicted = used;
    predictor_->predict(newest().step, used.step, used.X, predicted.X);
    out.predicted = true;
    out.prediction_step = predictor_->target();
    out.prediction_horizon = predictor_->target() - predictor_->anchor();
    for (int i = 0; i < Vehicle::kStates; ++i) out.X_predicted[i] = predicted.X[i];
    return predicted;
  }

  // The link's choice, held from when it was chosen (it arrived, so it is
  // in the history then): through a loss burst longer than the history the
  // law keeps the last state delivered, as the sweep's StateHistory does,
  // not a state the link lost.
  void holdUsedState() {
    if (held_valid_ && held_.step == used_step_) return;
    for (long i = 0; i < history_.size() && i < Capacity; ++i) {
      if (history_.delayed(i).step == used_step_) {
        held_ = history_.delayed(i);
        held_valid_ = true;
        return;
      }
    }
  }

  // The drone's side of the command over the link (after the metrics, which
  // are the controller's: its error, its sent command).
  void overLink(ControlOutput& out) {
    for (int i = 0; i < kMaxInputs; ++i) out.U_sent[i] = out.U[i];
    if (!link_.active()) return;
    const long k = newest().step;
    link_.commandSent(k, out.U_sent, out.U);
    out.state_arrived = link_.stateArrived();
    out.command_age = link_.commandAge(k);
    out.drone_hovers = link_.droneHovers();
    out.uplink_losses = link_.uplinkLosses();
    out.downlink_losses = link_.downlinkLosses();
  }

  // The iteration's controller half (controllerHalf) on the delivered state,
  // its metrics at the loop clock's time of the newest step. The metrics
  // count once per state step: a timer cycle without a new state, or a
  // re-sent state, runs the law again (its memory moves on, as the node's
  // law always did) but its metrics do not count twice.
  void controllerSide(const Reference<double>& ref, const StateSample& used, ControlOutput& out) {
    const long step = newest().step;
    const bool counted = step == metrics_step_;
    const PositioningMetrics<double, bool> before = side_.metrics;
    side_.t = clock_.at(step, settings.Ts);
    const LoopParams<Data, double> params = settings.loopParams(criteria_);
    const ClampPolicy clamp{settings.clamp_commands, false};
    settings.withLawType([&](auto law) {
      controllerHalf<decltype(law)>(params, GivenReference{ref}, clamp, double(step), used.X, side_,
                                    out.U_unclamped, out.U, out.position_error);
    });
    if (counted) side_.metrics = before;
    metrics_step_ = step;
  }

  void metricsOut(ControlOutput& out) const {
    out.iae = side_.metrics.iae;
    out.itae = side_.metrics.itae;
    out.iasc = side_.metrics.iasc;
  }

  DelayBuffer<StateSample, Capacity> history_;
  // What the controller's half changes: the metrics, the underactuated
  // law's memory, the clock's time (set from clock_ each cycle).
  ControllerState<Data, double, bool> side_;
  FeasibilityCriteria<double> criteria_ = FeasibilityCriteria<double>::study();
  long metrics_step_ = -1;
  LoopClock clock_;
  NodeLink<Capacity> link_;
  long used_step_ = -1;  // over a link: the step of the state the law uses
  StateSample held_;     // ... and that state (held_valid_: the link has delivered one)
  bool held_valid_ = false;
  PredictorRun<Vehicle, double> predictor_run_;
  std::unique_ptr<HostPredictor<Vehicle, double>> predictor_;
};

}  // namespace aurora_control
