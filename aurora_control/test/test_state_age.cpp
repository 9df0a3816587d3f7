// A state's age for the nodes' watchdogs leaves out the time the node's own
// process stood still (src/state_age.h): every stall since the state came,
// not the last one only.
#include <gtest/gtest.h>

#include "state_age.h"

using aurora_control::ProcessStall;

namespace {

constexpr double kPeriod = 1.0 / 30.0;

ros::Time at(double s) { return ros::Time(s); }

// A timer callback due at `expected` that ran at `real` [s].
ros::TimerEvent callback(double expected, double real) {
  ros::TimerEvent e;
  e.current_expected = at(expected);
  e.current_real = at(real);
  return e;
}

}  // namespace

TEST(ProcessStall, WithoutStallsAStatesAgeIsTheTimeSinceItCame) {
  ProcessStall stall;
  stall.timerRan(callback(100.0, 100.01), kPeriod);  // late by less than a period: no stall
  EXPECT_DOUBLE_EQ(stall.stateAge(at(102.0), at(100.5)), 1.5);
  EXPECT_DOUBLE_EQ(stall.stateAge(at(100.0), at(100.5)), 0.0);  // never negative
}

TEST(ProcessStall, EveryStallSinceTheStateCameIsLeftOut) {
  ProcessStall stall;
  stall.timerRan(callback(100.0, 100.4), kPeriod);  // 0.4 s
  stall.timerRan(callback(101.0, 101.3), kPeriod);  // 0.3 s
  // A state at 99.9, judged at 102: 2.1 s, of which 0.7 s the process stood still.
  EXPECT_NEAR(stall.stateAge(at(102.0), at(99.9)), 1.4, 1e-9);
  // A state that came during the first stall: that stall's part after it only.
  EXPECT_NEAR(stall.stateAge(at(102.0), at(100.2)), 1.8 - 0.2 - 0.3, 1e-9);
  // A state after both: neither.
  EXPECT_NEAR(stall.stateAge(at(102.0), at(101.5)), 0.5, 1e-9);
}

TEST(ProcessStall, LateCallbacksOfOneStallCountItOnce) {
  ProcessStall stall;
  // Callbacks due at 100.0 and 100.033 both ran at 100.5: one stall, 100.0 to 100.5.
  stall.timerRan(callback(100.0, 100.5), kPeriod);
  stall.timerRan(callback(100.0 + kPeriod, 100.5), kPeriod);
  EXPECT_NEAR(stall.stateAge(at(101.0), at(99.8)), 1.2 - 0.5, 1e-9);
}
