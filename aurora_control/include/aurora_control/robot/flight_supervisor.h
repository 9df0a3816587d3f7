// Flight sequence and safety watchdogs of the controller (ROS-free): wait for
// a fresh state, take off, wait until hovering at the start altitude, fly
// the task, land at the end; hover when the state goes stale, land when it
// stays stale or the drone leaves the safety box. Each safety action is
// reported once (`event`) and named in `mode` for the control message.
// A ground robot (SafetyConfig::ground_robot) neither takes off nor lands:
// it drives from the first fresh state, and where a drone would land it
// stops (zero commands) for good: "stop (...)", then "stopped".
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "aurora_sim/state_index.h"

namespace aurora_control {

struct SafetyConfig {
  bool flight_sequence = false;   // false: fly from the first state (simulation, the study)
  double takeoff_altitude = 0.75; // [m] hover altitude after take-off (the study's start)
  double takeoff_tolerance = 0.05; // [m] "at the start point" within this
  double hover_speed = 0.1;        // [m/s] "hovering" below this speed (above mocap velocity noise)
  double takeoff_climbed = 0.3;    // [m] the driver's take-off is done above this
  double takeoff_timeout = 15.0;  // [s] give up and land after this
  double landed_altitude = 0.1;   // [m] below this while landing: landed
  double hover_after = 0.5;       // [s] state age that commands hover
  double land_after = 0.0;        // [s] state age that commands landing; 0 = never
  // Delivery of take-off and land to the driver (driver_command.h).
  double command_resend_period = 1.0;  // [s] re-send until the state shows the effect
  double land_resend_timeout = 10.0;   // [s] after the first land: stop re-sending, warn
  double takeoff_rise = 0.1;           // [m] climb above the request altitude that shows a take-off
  double descent_speed = 0.1;          // [m/s] sinking faster shows a landing (above mocap noise)
  bool ground_robot = false;      // the vehicle's (kOnGround), not a file's: no take-off, stop instead of landing
  double max_speed = 0.0;         // [m/s] a ground robot's forward speed limit on what is sent (0: none)
  double max_turn_rate = 0.0;     // [rad/s] its turn-rate limit (0: none)
  bool box_enabled = false;       // land when the drone leaves [box_min, box_max]
  double box_min[3] = {0, 0, 0};  // [m] world frame
  double box_max[3] = {0, 0, 0};
};

enum class FlightPhase { kWaitState, kTakeoff, kFly, kLand, kLanded };

struct FlightDecision {
  bool run_law = false;      // true: the control law; false: hover (all zero)
  bool hold = false;         // with run_law: fly to hold_point instead of the task
  double hold_point[3] = {0, 0, 0};
  bool send_takeoff = false;
  bool send_land = false;
  std::string mode;          // for the control message
  std::string event;         // non-empty once, when a safety action or phase change begins
};

class FlightSupervisor {
 public:
  explicit FlightSupervisor(const SafetyConfig& cfg = SafetyConfig()) { configure(cfg); }

  void configure(const SafetyConfig& cfg) {
    cfg_ = cfg;
    phase_ = cfg.flight_sequence ? FlightPhase::kWaitState : FlightPhase::kFly;
    fly_start_step_ = 0;
    last_mode_.clear();
  }

  FlightPhase phase() const { return phase_; }
  const SafetyConfig& config() const { return cfg_; }
  // Step of the state at which the task started (task time = (step - this) Ts).
  long flyStartStep() const { return fly_start_step_; }
  // Where the drone hovers after take-off [m, world frame].
  const double* startPoint() const { return start_point_; }
  // A formation's drone hovers at its formation file's start after take-off
  // (not above its take-off spot at takeoff_altitude: every drone there is
  // level, where the line is singular; line_formation.h).
  void startAt(const double p[3]) {
    fixed_start_ = true;
    for (int i = 0; i < 3; ++i) fixed_start_point_[i] = p[i];
  }

  // At the start point (within takeoff_tolerance) and still (below hover_speed).
  bool atStartPoint(const double X[aurora_sim::kStateSize]) const {
    double e2 = 0.0, v2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      e2 += (X[aurora_sim::kX + i] - start_point_[i]) * (X[aurora_sim::kX + i] - start_point_[i]);
      v2 += X[aurora_sim::kVx + i] * X[aurora_sim::kVx + i];
    }
    return e2 <= cfg_.takeoff_tolerance * cfg_.takeoff_tolerance &&
           v2 <= cfg_.hover_speed * cfg_.hover_speed;
  }

  // Land now, whatever the phase (a formation lands every drone when one
  // of them must: formation_supervisor.h).
  FlightDecision landNow(const std::string& mode) {
    FlightDecision d;
    return land(d, mode);
  }

  // now [s]; state_age: time since the last fresh state [s] (infinite if
  // none); X and step: the newest state; task_time [s] since the task
  // started; task_duration [s].
  FlightDecision update(double now, double state_age, const double X[aurora_sim::kStateSize],
                        long step, double task_time, double task_duration) {
    FlightDecision d;
    const bool have_state = std::isfinite(state_age);
    switch (phase_) {
      case FlightPhase::kWaitState:
        if (have_state && state_age <= cfg_.hover_after && cfg_.ground_robot) {  // it drives from here
          phase_ = FlightPhase::kFly;
          fly_start_step_ = step;
          // A formation's ground robot drives to its start point first.
          for (int i = 0; i < 3; ++i) start_point_[i] = fixed_start_ ? fixed_start_point_[i] : X[aurora_sim::kX + i];
          d.run_law = true;
          return finish(d, "fly");
        }
        if (have_state && state_age <= cfg_.hover_after) {
          d.send_takeoff = true;
          phase_ = FlightPhase::kTakeoff;
          takeoff_started_ = now;
          // Hover above the take-off spot at the start altitude: the task
          // starts from rest there, as the simulation starts at z = 0.75 m.
          start_point_[0] = fixed_start_ ? fixed_start_point_[0] : X[aurora_sim::kX];
          start_point_[1] = fixed_start_ ? fixed_start_point_[1] : X[aurora_sim::kY];
          start_point_[2] = fixed_start_ ? fixed_start_point_[2] : cfg_.takeoff_altitude;
          return finish(d, "takeoff");
        }
        return finish(d, "wait for state");
      case FlightPhase::kTakeoff:
        if (staleLand(d, state_age)) return d;
        if (atStartPoint(X)) {
          phase_ = FlightPhase::kFly;
          fly_start_step_ = step;
          d.run_law = true;
          return finish(d, "fly");
        }
        if (now - takeoff_started_ > cfg_.takeoff_timeout) {
          return land(d, "land (take-off did not reach the start point)");
        }
        if (X[aurora_sim::kZ] > cfg_.takeoff_climbed) {  // the driver's take-off is done: hold
          d.run_law = true;
          d.hold = true;
          for (int i = 0; i < 3; ++i) d.hold_point[i] = start_point_[i];
        }
        return finish(d, "takeoff");
      case FlightPhase::kFly:
        // No state yet: nothing has gone stale (a warning here would come
        // before the first state could arrive).
        if (!have_state) return finish(d, "wait for state");
        if (staleLand(d, state_age)) return d;
        if (state_age > cfg_.hover_after) {
          // All-zero commands: a drone hovers, a ground robot stands still (it does not fly).
          return finish(d, std::string(cfg_.ground_robot ? "halt" : "hover") + " (no fresh state for " +
                               seconds(cfg_.hover_after) + ")");
        }
        if (cfg_.box_enabled && outsideBox(X)) {
          char buf[96];
          std::snprintf(buf, sizeof buf, "land (left the safety box at %.2f, %.2f, %.2f)",
                        X[aurora_sim::kX], X[aurora_sim::kY], X[aurora_sim::kZ]);
          return land(d, buf);
        }
        if (cfg_.flight_sequence && task_time > task_duration) return land(d, "land (task complete)");
        d.run_law = true;
        return finish(d, "fly");
      case FlightPhase::kLand:
        if (have_state && X[aurora_sim::kZ] < cfg_.landed_altitude) {
          phase_ = FlightPhase::kLanded;
          return finish(d, "landed");
        }
        return finish(d, last_mode_);
      case FlightPhase::kLanded:
        return finish(d, cfg_.ground_robot ? "stopped" : "landed");
    }
    return d;
  }

 private:
  static std::string seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g s", s);
    return buf;
  }

  bool outsideBox(const double X[aurora_sim::kStateSize]) const {
    for (int i = 0; i < 3; ++i) {
      if (X[aurora_sim::kX + i] < cfg_.box_min[i] || X[aurora_sim::kX + i] > cfg_.box_max[i]) return true;
    }
    return false;
  }

  bool staleLand(FlightDecision& d, double state_age) {
    if (cfg_.land_after > 0.0 && state_age > cfg_.land_after) {
      land(d, "land (no fresh state for " + seconds(cfg_.land_after) + ")");
      return true;
    }
    return false;
  }

  // A drone lands; a ground robot stops at once ("land (why)" becomes "stop (why)").
  FlightDecision& land(FlightDecision& d, const std::string& mode) {
    if (cfg_.ground_robot) {
      phase_ = FlightPhase::kLanded;
      return finish(d, "stop" + mode.substr(mode.rfind("land", 0) == 0 ? 4 : 0));
    }
    phase_ = FlightPhase::kLand;
    d.send_land = true;
    return finish(d, mode);
  }

  FlightDecision& finish(FlightDecision& d, const std::string& mode) {
    d.mode = mode;
    if (mode != last_mode_) d.event = mode;
    last_mode_ = mode;
    return d;
  }

  SafetyConfig cfg_;
  FlightPhase phase_ = FlightPhase::kFly;
  long fly_start_step_ = 0;
  double takeoff_started_ = 0.0;
  double start_point_[3] = {0, 0, 0};
  bool fixed_start_ = false;  // startAt: a formation's start point
  double fixed_start_point_[3] = {0, 0, 0};
  std::string last_mode_;
};

}  // namespace aurora_control
