// Delivery of the driver's one-shot commands: take-off, land and reset, each a
// std_msgs/Empty on the driver's topic (ROS-free; the node publishes).
//
// Why: a ROS message published before the receiving subscription is
// connected is dropped without a trace, and a driver started by the same
// launch file often connects after the controller's first fresh state. One
// lost take-off used to leave the drone on the ground until the supervisor
// gave up and landed. So a command is held until the driver listens, and
// take-off and land are re-sent at a modest period until the state shows
// their effect (land: or until a timeout, since a drone whose pose stopped
// cannot show anything).
//
// Re-sending is safe for take-off and land because both drivers treat them
// as levels, not toggles: ardrone_autonomy's take-off and land callbacks set
// or clear the SDK's "flying" request (a repeated take-off while flying, or a
// repeated land while landing, changes nothing); bebop_autonomy forwards them
// to the Bebop's piloting TakeOff / Landing commands, which the autopilot
// ignores outside the landed state (take-off) and the flying states (land).
// Reset is never re-sent: ardrone_autonomy's reset *toggles* the emergency
// state, so a second reset would undo the first (and on the Bebop it cuts
// the motors). It is sent once, as soon as the driver listens.
#pragma once

#include "aurora_sim/state_index.h"

namespace aurora_control {

struct DeliveryPolicy {
  double resend_period = 0.0;  // [s] between attempts until shown; 0: one attempt only
  double timeout = 0.0;        // [s] after the first attempt: stop re-sending; 0: never
};

enum class Delivery {
  kIdle,              // nothing requested
  kWaitingForDriver,  // requested; the driver's subscription is not connected yet
  kSending,           // sent at least once; not shown by the state yet
  kShown,             // the state shows the command's effect: done
  kSent,              // a one-attempt command was sent: done
  kTimedOut,          // re-sent until the timeout without being shown: given up
};

class DriverCommand {
 public:
  explicit DriverCommand(const DeliveryPolicy& policy = DeliveryPolicy()) : policy_(policy) {}

  // Starts delivering (again); `reference` is kept for the caller's
  // evidence test (e.g. the altitude at the take-off request).
  void request(double now, double reference = 0.0) {
    state_ = Delivery::kWaitingForDriver;
    attempts_ = 0;
    requested_at_ = now;
    reference_ = reference;
  }

  // A newer command supersedes this one (a land cancels a take-off).
  void cancel() {
    if (pending()) state_ = Delivery::kIdle;
  }

  // now [s]; driver_listening: the driver's subscription is connected;
  // shown: the state shows the command's effect. True when the caller must
  // publish the command now (one attempt, counted).
  bool update(double now, bool driver_listening, bool shown) {
    if (!pending()) return false;
    if (shown && attempts_ > 0) {
      state_ = Delivery::kShown;
      return false;
    }
    if (attempts_ == 0) {
      if (!driver_listening) return false;  // held: a publish now would be lost
      return attempt(now);
    }
    if (policy_.resend_period <= 0.0) {
      state_ = Delivery::kSent;
      return false;
    }
    if (policy_.timeout > 0.0 && now - first_attempt_ >= policy_.timeout) {
      state_ = Delivery::kTimedOut;
      return false;
    }
    return now - last_attempt_ >= policy_.resend_period ? attempt(now) : false;
  }

  Delivery state() const { return state_; }
  bool pending() const { return state_ == Delivery::kWaitingForDriver || state_ == Delivery::kSending; }
  int attempts() const { return attempts_; }
  double requestedAt() const { return requested_at_; }
  double firstAttemptAt() const { return first_attempt_; }
  double reference() const { return reference_; }
  const DeliveryPolicy& policy() const { return policy_; }

 private:
  bool attempt(double now) {
    if (attempts_ == 0) first_attempt_ = now;
    ++attempts_;
    last_attempt_ = now;
    state_ = Delivery::kSending;
    return true;
  }

  DeliveryPolicy policy_;
  Delivery state_ = Delivery::kIdle;
  int attempts_ = 0;
  double requested_at_ = 0.0, first_attempt_ = 0.0, last_attempt_ = 0.0, reference_ = 0.0;
};

// Evidence in a fresh state that the driver acted (state indices of
// docs/model.md). Take-off: the drone rose `rise` [m] above the altitude
// at the request. Land: it descends faster than `speed` [m/s], or is below
// `landed_altitude` [m].
inline bool climbShown(const double X[aurora_sim::kStateSize], double z_at_request, double rise) {
  return X[aurora_sim::kZ] >= z_at_request + rise;
}

inline bool descentShown(const double X[aurora_sim::kStateSize], double speed, double landed_altitude) {
  return X[aurora_sim::kVz] <= -speed || X[aurora_sim::kZ] < landed_altitude;
}

}  // namespace aurora_control
