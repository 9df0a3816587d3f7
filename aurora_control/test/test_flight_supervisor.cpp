// Flight sequence and watchdogs.
#include <gtest/gtest.h>

#include <limits>

#include "aurora_control/robot/flight_supervisor.h"
#include "aurora_control/formation/formation_supervisor.h"

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

TEST(FlightSupervisor, AGroundRobotDrivesAtOnceAndStopsWhereADroneLands) {
  SafetyConfig c = realFlight();
  c.ground_robot = true;
  c.box_min[2] = -0.5;
  FlightSupervisor s(c);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(s.update(0.0, inf, X0, 0, 0, 25).mode, "wait for state");
  FlightDecision d = s.update(0.1, 0.0, X0, 3, 0, 25);  // no take-off: it drives from the first fresh state
  EXPECT_FALSE(d.send_takeoff);
  EXPECT_TRUE(d.run_law);
  EXPECT_EQ(d.event, "fly");
  EXPECT_EQ(s.flyStartStep(), 3);
  d = s.update(30.0, 0.0, X0, 260, 25.7, 25);  // the task is over: it stops, it does not land
  EXPECT_FALSE(d.send_land);
  EXPECT_FALSE(d.run_law);
  EXPECT_EQ(d.mode, "stop (task complete)");
  EXPECT_EQ(s.update(30.1, 0.0, X0, 261, 25.8, 25).mode, "stopped");
  EXPECT_FALSE(s.update(30.2, 0.0, X0, 262, 25.9, 25).run_law);  // for good

  FlightSupervisor stale(c), outside(c);
  stale.update(0.0, 0.0, X0, 1, 0, 25);
  // A stale state stands it still, and says so as a robot that does not fly (issue 51: "hover").
  d = stale.update(0.5, 0.3, X0, 1, 0.1, 25);
  EXPECT_EQ(d.mode, "halt (no fresh state for 0.2 s)");
  EXPECT_FALSE(d.run_law);
  d = stale.update(1.0, 1.2, X0, 1, 0.1, 25);
  EXPECT_EQ(d.mode, "stop (no fresh state for 1 s)");
  EXPECT_FALSE(d.send_land);
  double X[12] = {};
  X[1] = -3.2;
  outside.update(0.0, 0.0, X0, 1, 0, 25);
  d = outside.update(0.1, 0.0, X, 2, 0.1, 25);
  EXPECT_EQ(d.mode.rfind("stop (left the safety box", 0), 0u) << d.mode;
  EXPECT_EQ(outside.phase(), FlightPhase::kLanded);
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

namespace {

// Two drones through FormationSupervisor: positions, ages, one cycle.
struct Pair {
  FormationSupervisor<2> s;
  double X[2][12] = {};
  double age[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  long step[2] = {0, 0};
  double now = 0.0;
  // The formation file's starts: drone 2 0.25 m above drone 1 (the lab's scenario).
  double start[2][3] = {{-1.0, 0.0, 0.75}, {1.0, 0.0, 1.0}};
  Pair() {
    const std::string names[2] = {"ardrone1", "ardrone2"};
    s.configure(realFlight(), names, start);
  }
  FormationSupervisor<2>::Decision cycle(double task_time = 0.0, double duration = 40.0) {
    const double* const Xs[2] = {X[0], X[1]};
    now += 1.0 / 30.0;
    ++step[0], ++step[1];
    return s.update(now, age, Xs, step, task_time, duration);
  }
  void hoverAtStart(int d) {  // at its start point, still
    for (int i = 0; i < 3; ++i) X[d][i] = start[d][i];
    X[d][8] = 0.0;
  }
  // Both fresh, both taken off and hovering at their start points: flying.
  void toFormation() {
    age[0] = age[1] = 0.0;
    cycle();
    hoverAtStart(0), hoverAtStart(1);
    cycle();
  }
};

}  // namespace

TEST(FormationSupervisor, DronesTakeOffTogetherAndHoldUntilBothAreUp) {
  Pair p;
  p.X[0][0] = -1.0, p.X[1][0] = 1.0;
  p.age[0] = 0.0;  // drone 2 has no state yet: nobody takes off
  auto c = p.cycle();
  EXPECT_FALSE(c.drone[0].send_takeoff);
  EXPECT_FALSE(c.drone[1].send_takeoff);
  p.age[1] = 0.0;
  c = p.cycle();
  EXPECT_TRUE(c.drone[0].send_takeoff);
  EXPECT_TRUE(c.drone[1].send_takeoff);
  EXPECT_EQ(c.mode, "takeoff");
  p.hoverAtStart(0);  // drone 1 is up at its start point, drone 2 still climbing
  p.X[1][2] = 0.5, p.X[1][8] = 0.4;
  c = p.cycle();
  EXPECT_EQ(c.mode, "hold (waiting for ardrone2)");
  EXPECT_FALSE(c.formation);
  EXPECT_TRUE(c.drone[0].run_law && c.drone[0].hold);
  EXPECT_EQ(c.drone[0].hold_point[0], -1.0);
  EXPECT_EQ(c.drone[0].hold_point[2], 0.75);
  // Drone 2 up at the take-off altitude, level with drone 1 (where the line
  // is singular): not its start point; it climbs on to the file's 1.0 m.
  p.X[1][2] = 0.75, p.X[1][8] = 0.0;
  c = p.cycle();
  EXPECT_EQ(c.mode, "hold (waiting for ardrone2)");
  EXPECT_TRUE(c.drone[1].run_law && c.drone[1].hold);
  EXPECT_EQ(c.drone[1].hold_point[0], 1.0);
  EXPECT_EQ(c.drone[1].hold_point[2], 1.0);
  p.hoverAtStart(1);
  c = p.cycle();
  EXPECT_TRUE(c.started);
  EXPECT_TRUE(c.formation);
  EXPECT_EQ(c.mode, "fly");
  c = p.cycle(1.0 / 30.0);
  EXPECT_FALSE(c.started);
  EXPECT_TRUE(c.formation);
}

TEST(FormationSupervisor, OneStaleDroneMakesBothHoverThenTheFormationGoesOn) {
  Pair p;
  p.toFormation();
  ASSERT_TRUE(p.s.started());
  p.age[1] = 0.3;  // above hover_after (0.2 s), below land_after (1 s)
  auto c = p.cycle(1.0);
  EXPECT_FALSE(c.formation);
  EXPECT_FALSE(c.drone[0].run_law);
  EXPECT_FALSE(c.drone[1].run_law);
  EXPECT_EQ(c.mode, "hover (ardrone2: hover (no fresh state for 0.2 s))");
  EXPECT_EQ(c.event, c.mode);
  p.age[1] = 0.0;
  c = p.cycle(1.0);
  EXPECT_TRUE(c.formation);
  EXPECT_EQ(c.mode, "fly");
}

TEST(FormationSupervisor, OneDroneLandingLandsBoth) {
  Pair p;
  p.toFormation();
  p.X[0][0] = 3.5;  // drone 1 leaves the safety box
  auto c = p.cycle(2.0);
  EXPECT_TRUE(c.drone[0].send_land);
  EXPECT_TRUE(c.drone[1].send_land);
  EXPECT_EQ(c.mode, "land (ardrone1: left the safety box at 3.50, 0.00, 0.75)");
  c = p.cycle(2.0);
  EXPECT_FALSE(c.drone[0].send_land || c.drone[1].send_land);  // told once
  p.X[0][2] = 0.05;
  c = p.cycle(2.0);
  EXPECT_EQ(c.mode, "land (ardrone1: left the safety box at 3.50, 0.00, 0.75)");  // drone 2 is still up
  p.X[1][2] = 0.05;
  c = p.cycle(2.0);
  EXPECT_EQ(c.mode, "landed");
}

TEST(FormationSupervisor, BothLandWhenTheFormationEnds) {
  Pair p;
  p.toFormation();
  auto c = p.cycle(39.9, 40.0);
  EXPECT_TRUE(c.formation);
  c = p.cycle(40.1, 40.0);
  EXPECT_FALSE(c.formation);
  EXPECT_TRUE(c.drone[0].send_land && c.drone[1].send_land);
  EXPECT_EQ(c.mode, "land (task complete)");
}

// A Pioneer (ground robot, its own safety) beside a drone, in a crew sized
// for three: the drone takes off while the Pioneer drives to its start
// point; the formation starts once both are still at their starts; the
// Pioneer is never told to take off or land; at the end its "stop (task
// complete)" lands the drone for the same reason.
TEST(FormationSupervisor, AGroundRobotDrivesToItsStartAndStopsWhereTheDronesLand) {
  FormationSupervisor<3> s;
  SafetyConfig cfg[2] = {realFlight(), realFlight()};
  cfg[0].ground_robot = true;
  const std::string names[2] = {"pioneer1", "ardrone2"};
  const double start[2][3] = {{-1.0, 0.0, 0.0}, {0.0, 0.0, 0.75}};
  s.configure(cfg, names, start, 2);
  double X[3][12] = {}, now = 0.0;
  X[0][0] = -1.25;  // the Pioneer stands 0.25 m behind its start
  const double age[3] = {0.0, 0.0, 0.0};
  long step[3] = {0, 0, 0};
  auto cycle = [&](double task_time = 0.0) {
    const double* const Xs[3] = {X[0], X[1], X[2]};
    now += 1.0 / 30.0, ++step[0], ++step[1];
    return s.update(now, age, Xs, step, task_time, 20.0);
  };
  auto c = cycle();
  EXPECT_EQ(c.mode, "takeoff");
  EXPECT_FALSE(c.drone[0].send_takeoff);
  EXPECT_TRUE(c.drone[1].send_takeoff);
  EXPECT_TRUE(c.drone[0].run_law && c.drone[0].hold) << "the Pioneer drives to its start point";
  EXPECT_EQ(c.drone[0].hold_point[0], -1.0);
  for (int i = 0; i < 3; ++i) X[1][i] = start[1][i];  // the drone hovers at its start
  c = cycle();
  EXPECT_EQ(c.mode, "hold (waiting for pioneer1)");
  EXPECT_FALSE(c.formation);
  X[0][0] = -1.0, X[0][6] = 0.2;  // at its start, still moving
  EXPECT_EQ(cycle().mode, "hold (waiting for pioneer1)");
  X[0][6] = 0.0;
  c = cycle();
  EXPECT_TRUE(c.started && c.formation);
  c = cycle(20.1);  // past the formation's end
  EXPECT_EQ(c.mode, "land (task complete)");
  EXPECT_FALSE(c.drone[0].send_land) << "a ground robot stops";
  EXPECT_FALSE(c.drone[0].run_law);
  EXPECT_TRUE(c.drone[1].send_land);
  X[1][2] = 0.05;
  EXPECT_EQ(cycle(20.1).mode, "landed");
}
