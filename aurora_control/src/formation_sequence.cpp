// The formation node's flight sequence for real drones (docs/formation.md,
// "Real drones"): each drone's take-off and land requests through its
// driver's topics, the formation started from where the drones hover, and
// the formation's watchdog rules (formation_supervisor.h) every 30 Hz cycle.
#include <limits>

#include "aurora_sim/ros/conversions.h"
#include "controller_params.h"
#include "formation_node.h"

namespace aurora_control {

// ~safety (a safety file, as real.launch loads): flight_sequence true turns
// the sequence on; realtime only (a lockstep sim has no take-off).
void FormationNode::configureSequence() {
  safety_ = loadSafetyConfig(pnh_);
  sequence_ = safety_.flight_sequence;
  if (!sequence_) return;
  if (crew_->shape() != "line") {
    throw aurora_common::ConfigError("parameter '" + aurora_common::fullKey(pnh_, "safety/flight_sequence") +
                                  "' = true (real robots) flies the two-drone line only for now: a " + crew_->shape() +
                                  " formation flies simulated robots (formation.launch driver:=sim)");
  }
  if (lockstep_) {
    throw aurora_common::ConfigError("parameter '" + aurora_common::fullKey(pnh_, "safety/flight_sequence") +
                                  "' = true needs '" + aurora_common::fullKey(pnh_, "mode") +
                                  "' = 'realtime': real drones fly in real time");
  }
  std::string names[kDrones];
  double starts[kDrones][3];
  for (int d = 0; d < kDrones; ++d) {
    names[d] = drones_[d];
    for (int i = 0; i < 3; ++i) starts[d][i] = crew_->robot(d).start[i];
  }
  supervisor_.configure(safety_, names, starts);
  mode_ = "wait for state";
  // /NS/takeoff and /NS/land: the launch remaps them to each driver's names.
  for (int d = 0; d < kDrones; ++d) {
    const std::string ns = "/" + drones_[d];
    takeoff_land_[d] = TakeoffLand(nh_, ns + "/takeoff", ns + "/land", drones_[d], safety_);
  }
}

void FormationNode::flightCycle(const ros::Time& now) {
  const FormationSupervisor<kDrones>::Decision c = superviseDrones(now);
  mode_ = c.mode;
  if (!c.event.empty()) {
    const bool safety = c.event.rfind("hover", 0) == 0 || (c.event.rfind("land (", 0) == 0 && c.event != "land (task complete)");
    if (safety) ROS_WARN("formation_controller: %s", c.event.c_str());
    else ROS_INFO("formation_controller: %s", c.event.c_str());
  }
  serviceDriverCommands(c, now);
  if (c.started) {  // tick 0 from where the drones hover now
    double X0[3 * kDrones];
    crew_->newestPositions(X0);
    crew_->startFrom(X0);
    formation_k_ = 0;
  }
  const CrewTick t = c.formation ? crew_->tick(formation_k_++) : holdOrHover(c);
  send(t);
  publish(t, now);
}

// Each drone's supervisor on its newest state and that state's age.
FormationSupervisor<FormationNode::kDrones>::Decision FormationNode::superviseDrones(const ros::Time& now) {
  static const double kNoState[aurora_sim::kStateSize] = {};
  double age[kDrones];
  const double* X[kDrones];
  long step[kDrones];
  for (int d = 0; d < kDrones; ++d) {
    const bool have = crew_->ready(d);
    age[d] = have ? (now - last_state_[d]).toSec() : std::numeric_limits<double>::infinity();
    X[d] = have ? crew_->newest(d).X : kNoState;
    step[d] = have ? crew_->newest(d).step : 0;
  }
  const double Ts = crew_->sampleTime();
  // Ticks 0 .. n - 1 fly (as the offline runner's); tick n lands them.
  const double duration = double(crew_->ticks() - 1) * Ts;
  return supervisor_.update(now.toSec(), age, X, step, taskTime(double(formation_k_), Ts), duration);
}

void FormationNode::serviceDriverCommands(const FormationSupervisor<kDrones>::Decision& c, const ros::Time& now) {
  for (int d = 0; d < kDrones; ++d) {
    const bool have = crew_->ready(d);
    takeoff_land_[d].apply(c.drone[d], now.toSec(), have ? crew_->newest(d).X[aurora_sim::kZ] : 0.0);
    const bool fresh = have && (now - last_state_[d]).toSec() <= safety_.hover_after;
    takeoff_land_[d].service(now.toSec(), fresh ? crew_->newest(d).X : nullptr);
  }
}

// Outside the formation: a drone holds its start point (its law) or hovers
// (a zero command; drivers expect a steady stream, with or without a state).
CrewTick FormationNode::holdOrHover(const FormationSupervisor<kDrones>::Decision& c) {
  CrewTick t;
  t.k = formation_k_;
  for (int d = 0; d < kDrones; ++d) {
    const FlightDecision& f = c.drone[d];
    if (!crew_->ready(d)) continue;  // zero command, reference at the origin
    if (f.run_law && f.hold) {
      t.out[d] = crew_->hold(d, f.hold_point);
      t.ref[d] = DelayedController<kDelayHistory>::restingAt(f.hold_point);
    } else {
      t.out[d] = crew_->hover(d);
    }
  }
  return t;
}

}  // namespace aurora_control
