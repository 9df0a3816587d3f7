// Flight sequence of a formation of real robots (docs/formation.md, "Real
// robots"), ROS-free: each drone keeps the single-drone controller's
// FlightSupervisor (take-off, hover on a stale state, land on a long one or
// outside the safety box), and the formation adds its rules above them:
//  - after take-off each drone flies to its start point of the formation
//    file (the drones are not level there: the line is singular where they
//    are) and holds it until every drone has reached its own;
//  - the formation starts (tick 0) in the cycle where every drone flies,
//    from where the drones are then;
//  - while any drone must hover, every drone hovers (the layer would
//    otherwise steer the others by a position it no longer knows);
//  - when any drone must land, every drone lands; at the formation's end,
//    every drone lands.
// A ground robot (its SafetyConfig's ground_robot: a mixed crew's Pioneer)
// neither takes off nor lands: it drives to its start point and holds it
// (the formation starts once it is there too, and still), and stops where
// the drones land. D robots at most; configure() says how many fly.
#pragma once

#include <limits>
#include <string>

#include "aurora_control/robot/flight_supervisor.h"

namespace aurora_control {

template <int D>
class FormationSupervisor {
 public:
  struct Decision {
    FlightDecision drone[D];  // per drone: law, hold point, take-off / land requests
    bool formation = false;   // the formation flies this cycle (the layer and the drones' laws)
    bool started = false;     // ... and this is its first cycle (tick 0)
    std::string mode;         // the formation's, for its message
    std::string event;        // non-empty once, when the mode changes
  };

  // names: the drones' namespaces (for the modes); starts: each drone's
  // start point from the formation file [m], where it hovers after take-off
  // until every drone is at its own (the file refuses level starts).
  void configure(const SafetyConfig& cfg, const std::string (&names)[D], const double (&starts)[D][3]) {
    SafetyConfig cfgs[D];
    for (int d = 0; d < D; ++d) cfgs[d] = cfg;
    configure(cfgs, names, starts, D);
  }
  // n robots (at most D), each with its own safety configuration.
  void configure(const SafetyConfig* cfgs, const std::string* names, const double (*starts)[3], int n) {
    n_ = n;
    for (int d = 0; d < n_; ++d) {
      supervisor_[d].configure(cfgs[d]), names_[d] = names[d];
      supervisor_[d].startAt(starts[d]);
    }
    started_ = false;
    landing_ = false;
    last_mode_.clear();
  }

  bool started() const { return started_; }

  // now [s]; age[d]: time since drone d's last fresh state [s] (infinite if
  // none); X[d], step[d]: its newest state; task_time [s] since the
  // formation started; duration [s]: the formation reference's.
  Decision update(double now, const double (&age)[D], const double* const (&X)[D], const long (&step)[D],
                  double task_time, double duration) {
    Decision c;
    // The drones take off together: none before every one has a fresh state.
    bool all_fresh = true;
    for (int d = 0; d < n_; ++d) all_fresh = all_fresh && age[d] <= freshWithin(d);
    for (int d = 0; d < n_; ++d) {
      const bool held = !all_fresh && supervisor_[d].phase() == FlightPhase::kWaitState;
      c.drone[d] = supervisor_[d].update(now, held ? kNever : age[d], X[d], step[d], started_ ? task_time : 0.0,
                                         duration);
    }
    const int lander = firstLanding(c);
    if (lander >= 0 || landing_) return landAll(c, lander);
    if (!started_) return beforeStart(c, X);
    return flying(c);
  }

 private:
  double freshWithin(int d) const { return supervisor_[d].config().hover_after; }

  // Ready for tick 0: flying; a ground robot also at its start point, still.
  bool readyToStart(int d, const double* X) const {
    return supervisor_[d].phase() == FlightPhase::kFly &&
           (!supervisor_[d].config().ground_robot || supervisor_[d].atStartPoint(X));
  }

  // The first drone whose supervisor lands it now or did before, -1: none.
  int firstLanding(const Decision& c) const {
    for (int d = 0; d < n_; ++d) {
      const FlightPhase p = supervisor_[d].phase();
      if (c.drone[d].send_land || p == FlightPhase::kLand || p == FlightPhase::kLanded) return d;
    }
    return -1;
  }

  // One drone lands: every drone lands, each told once.
  Decision& landAll(Decision& c, int lander) {
    if (!landing_) {
      landing_ = true;
      land_mode_ = landMode(lander, c.drone[lander].mode);
      for (int d = 0; d < n_; ++d) {
        const FlightPhase p = supervisor_[d].phase();
        if (d != lander && p != FlightPhase::kLand && p != FlightPhase::kLanded) {
          c.drone[d] = supervisor_[d].landNow(land_mode_);
        }
      }
    }
    bool all_landed = true;
    for (int d = 0; d < n_; ++d) all_landed = all_landed && supervisor_[d].phase() == FlightPhase::kLanded;
    return finish(c, all_landed ? "landed" : land_mode_);
  }

  // "land (task complete)" as every drone's; another reason names the drone:
  // "land (ardrone2: no fresh state for 1 s)".
  std::string landMode(int lander, const std::string& given) const {
    static const std::string kComplete = "land (task complete)", kOpen = "land (";
    // A ground robot's "stop (why)" lands the drones for the same reason.
    const std::string mode = given.compare(0, 6, "stop (") == 0 ? "land" + given.substr(4) : given;
    if (mode == kComplete) return mode;
    const bool why = mode.compare(0, kOpen.size(), kOpen) == 0;
    return kOpen + names_[lander] + (why ? ": " + mode.substr(kOpen.size()) : ")");
  }

  // Take-off: a drone at its start point holds it until every drone is
  // there; a ground robot drives to its start point and holds it.
  Decision& beforeStart(Decision& c, const double* const (&X)[D]) {
    int at_start = 0;
    for (int d = 0; d < n_; ++d) at_start += readyToStart(d, X[d]);
    if (at_start == n_) {
      started_ = true;
      c.started = true;
      return flying(c);
    }
    std::string waiting;
    for (int d = 0; d < n_; ++d) {
      if (!readyToStart(d, X[d])) waiting += (waiting.empty() ? "" : ", ") + names_[d];
      if (supervisor_[d].phase() != FlightPhase::kFly) continue;
      FlightDecision& f = c.drone[d];
      if (!f.run_law) continue;  // its own watchdog: hover
      f.hold = true;
      for (int i = 0; i < 3; ++i) f.hold_point[i] = supervisor_[d].startPoint()[i];
    }
    return finish(c, at_start == 0 ? c.drone[firstInSequence()].mode : "hold (waiting for " + waiting + ")");
  }

  // The first robot still in its own sequence (waiting for a state, taking
  // off; a ground robot drives from its first state), else robot 1.
  int firstInSequence() const {
    for (int d = 0; d < n_; ++d) {
      if (supervisor_[d].phase() == FlightPhase::kWaitState || supervisor_[d].phase() == FlightPhase::kTakeoff) return d;
    }
    return 0;
  }

  // The formation flies when every drone's law may run; else all hover.
  Decision& flying(Decision& c) {
    for (int d = 0; d < n_; ++d) {
      if (c.drone[d].run_law) continue;
      for (int o = 0; o < n_; ++o) c.drone[o].run_law = false, c.drone[o].hold = false;
      return finish(c, "hover (" + names_[d] + ": " + c.drone[d].mode + ")");
    }
    c.formation = true;
    return finish(c, "fly");
  }

  Decision& finish(Decision& c, const std::string& mode) {
    c.mode = mode;
    if (mode != last_mode_) c.event = mode;
    last_mode_ = mode;
    return c;
  }

  static constexpr double kNever = std::numeric_limits<double>::infinity();  // no state yet
  int n_ = D;
  FlightSupervisor supervisor_[D];
  std::string names_[D];
  bool started_ = false;
  bool landing_ = false;
  std::string land_mode_;
  std::string last_mode_;
};

}  // namespace aurora_control
