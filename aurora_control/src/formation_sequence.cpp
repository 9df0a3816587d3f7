// The formation node's flight sequence for real robots (docs/formation.md,
// "Real robots"): each drone's take-off and land requests through its
// driver's topics (a ground robot has none: it drives to its start point
// and stops where the drones land), the formation started from where the
// robots are, and the formation's watchdog rules (formation_supervisor.h)
// every cycle.
#include <limits>

#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "controller_params.h"
#include "formation_node.h"

namespace aurora_control {

// ~safety (a safety file, as real.launch loads): flight_sequence true turns
// the sequence on; realtime only (a lockstep sim has no take-off). A ground
// robot's safety file is under ~ground (formation.launch ground_safety).
void FormationNode::configureSequence() {
  const SafetyConfig drones = loadSafetyConfig(pnh_);
  sequence_ = drones.flight_sequence;
  if (!sequence_) return;
  if (lockstep_) {
    throw aurora_common::ConfigError("parameter '" + aurora_common::fullKey(pnh_, "safety/flight_sequence") +
                                  "' = true needs '" + aurora_common::fullKey(pnh_, "mode") +
                                  "' = 'realtime': real robots fly in real time");
  }
  const int n = crew_->robots();
  std::string names[kMaxCrew];
  double starts[kMaxCrew][3];
  for (int d = 0; d < n; ++d) {
    names[d] = drones_[d];
    for (int i = 0; i < 3; ++i) starts[d][i] = crew_->robot(d).start[i];
    safety_[d] = robotSafety(d, drones);
  }
  supervisor_.configure(safety_, names, starts, n);
  mode_ = "wait for state";
  // /NS/takeoff and /NS/land: the launch remaps them to each driver's names.
  for (int d = 0; d < n; ++d) {
    if (crew_->robot(d).ground) continue;
    const std::string ns = "/" + drones_[d];
    takeoff_land_[d] = TakeoffLand(nh_, ns + "/takeoff", ns + "/land", drones_[d], safety_[d]);
  }
}

// A drone's safety is ~safety; a ground robot's ~ground/safety, which must
// turn its sequence on too (real_ground.yaml: its watchdogs, speed limits).
SafetyConfig FormationNode::robotSafety(int d, const SafetyConfig& drones) const {
  if (!crew_->robot(d).ground) return drones;
  const ros::NodeHandle ground(pnh_, "ground");
  SafetyConfig c = loadSafetyConfig(ground);
  if (!c.flight_sequence) {
    throw aurora_common::ConfigError("parameter '" + aurora_common::fullKey(ground, "safety/flight_sequence") +
                                  "' is not true: " + drones_[d] + " is a ground robot among real robots; load "
                                  "its safety file there (formation.launch ground_safety:=real_ground)");
  }
  c.ground_robot = true;
  return c;
}

void FormationNode::flightCycle(const ros::Time& now) {
  const Supervisor::Decision c = superviseDrones(now);
  mode_ = c.mode;
  if (!c.event.empty()) {
    const bool safety = c.event.rfind("hover", 0) == 0 || c.event.rfind("halt (", 0) == 0 ||
                        (c.event.rfind("land (", 0) == 0 && c.event != "land (task complete)");
    if (safety) ROS_WARN("formation_controller: %s", c.event.c_str());
    else ROS_INFO("formation_controller: %s", c.event.c_str());
  }
  serviceDriverCommands(c, now);
  if (c.started) {  // tick 0 from where the robots are now
    double X0[3 * kMaxCrew];
    crew_->newestPositions(X0);
    crew_->startFrom(X0);
    formation_k_ = 0;
  }
  const CrewTick t = c.formation ? crew_->tick(formation_k_++) : holdOrHover(c);
  send(t, now);  // realtime: no stamped answer
  publish(t, now);
}

// Each robot's supervisor on its newest state and that state's age.
FormationNode::Supervisor::Decision FormationNode::superviseDrones(const ros::Time& now) {
  static const double kNoState[aurora_sim::kMaxStates] = {};
  double age[kMaxCrew] = {};
  const double* X[kMaxCrew] = {kNoState, kNoState, kNoState};
  long step[kMaxCrew] = {};
  for (int d = 0; d < crew_->robots(); ++d) {
    const bool have = crew_->ready(d);
    age[d] = have ? stall_.stateAge(now, last_state_[d]) : std::numeric_limits<double>::infinity();
    X[d] = have ? crew_->newest(d).X : kNoState;
    step[d] = have ? crew_->newest(d).step : 0;
  }
  const double Ts = crew_->sampleTime();
  // Ticks 0 .. n - 1 fly (as the offline runner's); tick n lands them.
  const double duration = double(crew_->ticks() - 1) * Ts;
  return supervisor_.update(now.toSec(), age, X, step, taskTime(double(formation_k_), Ts), duration);
}

void FormationNode::serviceDriverCommands(const Supervisor::Decision& c, const ros::Time& now) {
  for (int d = 0; d < crew_->robots(); ++d) {
    if (crew_->robot(d).ground) continue;  // no take-off or landing
    const bool have = crew_->ready(d);
    takeoff_land_[d].apply(c.drone[d], now.toSec(), have ? crew_->newest(d).X[aurora_sim::kZ] : 0.0);
    const bool fresh = have && stall_.stateAge(now, last_state_[d]) <= safety_[d].hover_after;
    takeoff_land_[d].service(now.toSec(), fresh ? crew_->newest(d).X : nullptr);
  }
}

// Outside the formation: a robot holds its start point (its law) or hovers
// (a zero command: a ground robot stands; drivers expect a steady stream,
// with or without a state).
CrewTick FormationNode::holdOrHover(const Supervisor::Decision& c) {
  CrewTick t;
  t.k = formation_k_;
  for (int d = 0; d < crew_->robots(); ++d) {
    const FlightDecision& f = c.drone[d];
    if (!crew_->ready(d)) continue;  // zero command, reference at the origin
    if (f.run_law && f.hold) {
      t.out[d] = crew_->hold(d, f.hold_point);
      t.ref[d] = restingAt(f.hold_point);
    } else {
      t.out[d] = crew_->hover(d);
    }
  }
  return t;
}

}  // namespace aurora_control
