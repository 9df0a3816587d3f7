// Flight sequence and watchdogs.
#include <gtest/gtest.h>

#include <limits>

#include "aurora_control/flight_supervisor.h"

using namespace aurora_control;

namespace {
SafetyConfig realFlight() {
  SafetyConfig c;
  c.flight_sequence = true;
  c.hover_after = 0.2;
  c.land_after = 1.0;
  c.box_enabled = true;
  c.box_min[0] = c.box_min[1] = -3;
  c.box_min[2] = 0;
  c.box_max[0] = c.box_max[1] = 3;
  c.box_max[2] = 3;
  return c;
}
double X0[12] = {};
}  // namespace

TEST(FlightSupervisor, SequenceWaitTakeoffFlyLand) {
  FlightSupervisor s(realFlight());
  const double inf = std::numeric_limits<double>::infinity();
  FlightDecision d = s.update(0.0, inf, X0, 0, 0, 60);
  EXPECT_EQ(d.mode, "wait for state");
  EXPECT_FALSE(d.run_law);
  d = s.update(0.1, 0.0, X0, 1, 0, 60);
  EXPECT_TRUE(d.send_takeoff);
  EXPECT_EQ(s.phase(), FlightPhase::kTakeoff);
  double X[12] = {};
  X[2] = 0.2;
  d = s.update(0.5, 0.0, X, 15, 0, 60);
  EXPECT_FALSE(d.run_law);  // the driver's own take-off is still climbing
  X[2] = 0.5;
  X[8] = 0.4;
  d = s.update(1.0, 0.0, X, 30, 0, 60);
  EXPECT_EQ(d.mode, "takeoff");
  EXPECT_FALSE(d.send_takeoff);  // once
  EXPECT_TRUE(d.run_law && d.hold);  // holds the start point
  EXPECT_EQ(d.hold_point[2], 0.75);
  X[2] = 0.74;
  d = s.update(1.5, 0.0, X, 45, 0, 60);
  EXPECT_EQ(s.phase(), FlightPhase::kTakeoff);  // still climbing at 0.4 m/s: not hovering
  X[8] = 0.01;
  d = s.update(2.0, 0.0, X, 60, 0, 60);
  EXPECT_TRUE(d.run_law);
  EXPECT_EQ(s.flyStartStep(), 60);
  EXPECT_EQ(d.event, "fly");
  d = s.update(3.0, 0.0, X, 90, 1.0, 60);
  EXPECT_TRUE(d.event.empty());  // events once
  d = s.update(70.0, 0.0, X, 1900, 60.1, 60);
  EXPECT_TRUE(d.send_land);
  EXPECT_EQ(d.mode, "land (task complete)");
  X[2] = 0.05;
  d = s.update(75.0, 0.0, X, 2000, 65, 60);
  EXPECT_EQ(s.phase(), FlightPhase::kLanded);
}

TEST(FlightSupervisor, StaleStateHoversThenLands) {
  SafetyConfig c = realFlight();
  c.flight_sequence = false;
  FlightSupervisor s(c);
  double X[12] = {};
  X[2] = 1.0;
  EXPECT_TRUE(s.update(0, 0.1, X, 1, 0, 60).run_law);
  FlightDecision d = s.update(0, 0.3, X, 1, 0, 60);
  EXPECT_FALSE(d.run_law);
  EXPECT_EQ(d.mode, "hover (no fresh state for 0.2 s)");
  EXPECT_EQ(d.event, d.mode);
  EXPECT_TRUE(s.update(0, 0.05, X, 2, 0, 60).run_law);  // fresh again: fly
  d = s.update(0, 1.2, X, 2, 0, 60);
  EXPECT_TRUE(d.send_land);
  EXPECT_EQ(d.mode, "land (no fresh state for 1 s)");
}

TEST(FlightSupervisor, LeavingTheBoxLands) {
  FlightSupervisor s([] {
    SafetyConfig c = realFlight();
    c.flight_sequence = false;
    return c;
  }());
  double X[12] = {};
  X[0] = 3.5;
  X[2] = 1.0;
  const FlightDecision d = s.update(0, 0.0, X, 1, 0, 60);
  EXPECT_TRUE(d.send_land);
  EXPECT_EQ(d.mode.rfind("land (left the safety box", 0), 0u) << d.mode;
}

TEST(FlightSupervisor, SimulationDefaultsFlyAtOnceAndNeverLand) {
  FlightSupervisor s;  // flight_sequence false, land_after 0
  const FlightDecision d = s.update(0, 0.0, X0, 0, 100, 60);
  EXPECT_TRUE(d.run_law);
  EXPECT_FALSE(d.send_land);
  EXPECT_EQ(s.update(0, 100.0, X0, 0, 100, 60).send_land, false);
}

TEST(FlightSupervisor, NoHoverWarningBeforeTheFirstState) {
  // Without a flight sequence the supervisor starts in "fly": before the
  // first state arrives that is a wait, not a stale state (no hover event).
  for (const double land_after : {0.0, 1.0}) {
    SafetyConfig c = realFlight();
    c.flight_sequence = false;
    c.land_after = land_after;
    FlightSupervisor s(c);
    const double inf = std::numeric_limits<double>::infinity();
    FlightDecision d = s.update(0.0, inf, X0, 0, 0, 60);
    EXPECT_EQ(d.mode, "wait for state");
    EXPECT_FALSE(d.send_land);
    d = s.update(0.9, inf, X0, 0, 0, 60);
    EXPECT_EQ(d.mode, "wait for state");
    EXPECT_TRUE(d.event.empty());
    d = s.update(1.0, 0.0, X0, 1, 0, 60);
    EXPECT_EQ(d.mode, "fly");
    EXPECT_TRUE(d.run_law);
  }
}
