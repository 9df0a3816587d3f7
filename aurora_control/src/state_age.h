// How old a robot's newest state is for the watchdogs (the flight sequence
// and safety of docs/real-drones.md), not counting the time this process
// itself stood still.
#pragma once

#include <ros/time.h>
#include <ros/timer.h>

#include <algorithm>
#include <deque>

namespace aurora_control {

// A loaded machine can hold a node's process up for a while. The states that
// came meanwhile then wait in the callback queue behind the timer callbacks
// due in that time, and a watchdog judging on those callbacks would hover
// for a stall of its own, fresh states at hand. A timer callback that runs
// more than a period after it was due marks such a stall; a state's age
// leaves out every stall since the state came. The watchdog still fires
// when the states really stop, late by at most the stalls (the process
// could not have acted sooner).
class ProcessStall {
 public:
  // Called first in each timer callback of the node's loop (period [s]).
  void timerRan(const ros::TimerEvent& event, double period) {
    if ((event.current_real - event.current_expected).toSec() <= period) return;
    const Stall stall{event.current_expected, event.current_real};
    if (!stalls_.empty() && stall.from <= stalls_.back().to) {  // late callbacks of one stall: one span
      stalls_.back().to = std::max(stalls_.back().to, stall.to);
      return;
    }
    stalls_.push_back(stall);
    if (stalls_.size() > kKept) stalls_.pop_front();
  }

  // [s] from `received` (the newest state's arrival) to `now`, less every
  // stall within that span (the last kKept); never negative.
  double stateAge(const ros::Time& now, const ros::Time& received) const {
    double age = (now - received).toSec();
    for (const Stall& s : stalls_) {
      const ros::Time a = std::max(received, s.from), b = std::min(now, s.to);
      if (b > a) age -= (b - a).toSec();
    }
    return std::max(0.0, age);
  }

 private:
  struct Stall {
    ros::Time from, to;
  };
  // More than a watchdog's span needs: its timeouts are seconds, a stall a
  // period at least.
  static constexpr size_t kKept = 64;
  std::deque<Stall> stalls_;  // oldest first, apart
};

}  // namespace aurora_control
