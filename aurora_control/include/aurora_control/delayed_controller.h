// The controller node's per-cycle computation, ROS-free: the controller half
// of the closed loop (closed_loop.h) in its incremental form. Received states
// go into the delay buffer; each cycle the chosen law (the delay study's PD
// law with saturation, eq. 3.1, or the underactuated 12-gain law) runs on the
// delayed state (docs/delay-and-study.md) through controllerCommand, the
// command is clamped as the drivers do (optional), and the study's metrics
// accumulate once per state step at the loop clock's time. The node and the
// offline `replay` tool both call this class, so a replay of a bag
// reproduces every command.
#pragma once

#include <cstdint>

#include "aurora_control/closed_loop.h"
#include "aurora_control/delay_buffer.h"
#include "aurora_control/link.h"
#include "aurora_control/feasibility.h"
#include "aurora_control/pd_controller.h"
#include "aurora_control/trajectory_task.h"
#include "aurora_control/underactuated_law.h"
#include "aurora_sim/ardrone_params.h"
#include "aurora_sim/scalar_math.h"
#include "aurora_sim/state_index.h"

namespace aurora_control {

struct StateSample {
  long step = 0;           // the source's sample index (DroneState.step)
  int64_t stamp_ns = 0;    // header stamp [ns]
  double X[aurora_sim::kStateSize] = {};
};

struct ControllerSettings {
  LawType law = LawType::kPdSaturated;
  PdGains<double> gains{0.0, 0.0};
  UnderactuatedGains<double> underactuated = UnderactuatedGains<double>::defaults();
  aurora_sim::ArdroneParams<double> vehicle{};  // the model the underactuated law inverts
  long delay = 0;          // [samples] the uplink's base delay
  LinkParams link;         // the rest of the link (link.h); so far the offline runner's only
  bool clamp_commands = true;
  double Ts = 1.0 / 30.0;  // [s], the vehicle's sample time (the loop clock's step)
};

struct ControlOutput {
  double U[4] = {0, 0, 0, 0};            // as sent (clamped when configured)
  double U_unclamped[4] = {0, 0, 0, 0};  // as the law computed it
  double position_error[3] = {0, 0, 0};  // desired - used position [m]
  const StateSample* used = nullptr;     // the (delayed) state the law used
  long delay_in_force = 0;               // samples between the newest state and `used`
  long delay_pending = 0;                // further states before settings.delay is in force
  double iae = 0, itae = 0, iasc = 0;    // running metrics after this cycle
};

template <int Capacity>
class DelayedController {
 public:
  static constexpr long kMaxDelay = Capacity - 1;

  ControllerSettings settings;

  DelayedController() { reset(); }

  void reset() {
    history_.clear();
    memory_.reset();
    resetMetrics();
  }

  // The metrics start again (e.g. when the task starts after take-off).
  void resetMetrics() {
    metrics_.reset();
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
  ControlOutput compute(const Reference<double>& ref) {
    ControlOutput out;
    const StateSample& used = history_.delayed(settings.delay);
    out.used = &used;
    out.delay_in_force = history_.delayInForce(settings.delay);
    out.delay_pending = history_.pendingUntilInForce(settings.delay);
    const LawGains<double> gains{settings.gains, settings.underactuated};
    withLaw(settings.law, [&](auto law) {
      controllerCommand<decltype(law)::value>(settings.vehicle, gains, memory_, ref, used.X,
                                              settings.clamp_commands, out.U_unclamped, out.U,
                                              out.position_error);
    });
    finish(out);
    return out;
  }

  static Reference<double> restingAt(const double desired[3]) {
    Reference<double> r;
    for (int i = 0; i < 3; ++i) r.pos[i] = desired[i], r.vel[i] = 0.0, r.acc[i] = 0.0;
    r.yaw = r.yaw_rate = r.yaw_acc = 0.0;
    return r;
  }

  // The command while the state is stale: hover (all zero); the metrics
  // gain nothing (zero error, zero command).
  ControlOutput hover() {
    ControlOutput out;
    out.used = &newest();
    finish(out);
    return out;
  }

 private:
  void finish(ControlOutput& out) {
    // Metrics once per state step (a timer cycle without a new state, or a
    // re-sent state, does not count twice), at the loop clock's time.
    const long step = newest().step;
    if (step != metrics_step_) {
      metrics_.accumulate(criteria_, out.position_error, out.U, clock_.at(step, settings.Ts));
      metrics_step_ = step;
    }
    out.iae = metrics_.iae;
    out.itae = metrics_.itae;
    out.iasc = metrics_.iasc;
  }

  DelayBuffer<StateSample, Capacity> history_;
  UnderactuatedMemory<double> memory_;  // the underactuated law's own state
  PositioningMetrics<double, bool> metrics_;
  FeasibilityCriteria<double> criteria_ = FeasibilityCriteria<double>::study();
  long metrics_step_ = -1;
  LoopClock clock_;
};

}  // namespace aurora_control
