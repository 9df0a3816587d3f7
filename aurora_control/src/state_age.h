// How old a robot's newest state is for the watchdogs (the flight sequence
// and safety of docs/real-drones.md), not counting the time this process
// itself stood still.
#pragma once

#include <ros/time.h>
#include <ros/timer.h>

#include <algorithm>

namespace aurora_control {

// A loaded machine can hold a node's process up for a while. The states that
// came meanwhile then wait in the callback queue behind the timer callbacks
// due in that time, and a watchdog judging on those callbacks would hover
// for a stall of its own, fresh states at hand. A timer callback that runs
// more than a period after it was due marks such a stall; a state's age
// leaves it out. The watchdog still fires when the states really stop, late
// by at most the stall (the process could not have acted sooner).
class ProcessStall {
 public:
  // Called first in each timer callback of the node's loop (period [s]).
  void timerRan(const ros::TimerEvent& event, double period) {
    if ((event.current_real - event.current_expected).toSec() > period) {
      from_ = event.current_expected;
      to_ = event.current_real;
    }
  }

  // [s] from `received` (the newest state's arrival) to `now`, less the
  // last stall within that span; never negative.
  double stateAge(const ros::Time& now, const ros::Time& received) const {
    double age = (now - received).toSec();
    const ros::Time a = std::max(received, from_), b = std::min(now, to_);
    if (b > a) age -= (b - a).toSec();
    return std::max(0.0, age);
  }

 private:
  ros::Time from_, to_;  // the last stall (none: both 0)
};

}  // namespace aurora_control
