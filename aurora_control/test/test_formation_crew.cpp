// The formation node's crews (formation_crew.h): each shape's tick, fed the
// offline runner's states, answers with the runner's commands and layer bit
// for bit (what `flight --formation` flies), for the UAV-UGV line's
// Pioneer and drone and the triangle's three AR.Drones, each robot its own
// delay; and the files the ROS loop cannot fly are refused naming the key.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "aurora_common/refusal_text.h"
#include "aurora_control/formation/formation_crew.h"
#include "aurora_control/formation/triangle/triangle_yaml.h"
#include "aurora_control/formation/uav_ugv/uav_ugv_yaml.h"
#include "aurora_sim/vehicle/vehicle_yaml.h"
#include "config_dir.h"

using namespace aurora_control;

namespace {

using aurora_tests::kConfig;

// One tick of the runner: each robot's state at its start, its command.
struct RunnerTick {
  std::vector<std::vector<double>> X, U;
  std::vector<double> Q, Qd;
};

template <class Law, class Shape, class Run>
std::vector<RunnerTick> runnerTicks(const Run& run, long ticks) {
  using Vehicle = typename Law::Vehicle;
  std::vector<RunnerTick> out;
  auto observe = [&](const FormationObservation<double, Shape, typename Law::Data>& o) {
    RunnerTick t;
    for (int d = 0; d < Shape::kDrones; ++d) {
      t.X.emplace_back(o.X_before[d], o.X_before[d] + Vehicle::kStates);
      t.U.emplace_back(o.steps[d].U, o.steps[d].U + Vehicle::kInputs);
    }
    t.Q.assign(o.layer.Q(), o.layer.Q() + Shape::kVariables);
    t.Qd.assign(o.layer.Qd(), o.layer.Qd() + Shape::kVariables);
    out.push_back(t);
  };
  runFormation<Law, double, Shape, kDelayHistory>(run, ticks, observe);
  return out;
}

// Mismatching commands and layer values when the crew gets the runner's states.
long crewMismatches(FormationCrew& crew, const std::vector<RunnerTick>& runner, long& layer_runs) {
  long mismatches = 0;
  layer_runs = 0;
  for (size_t k = 0; k < runner.size(); ++k) {
    for (int d = 0; d < crew.robots(); ++d) {
      StateSample s;
      s.step = static_cast<long>(k);
      std::copy(runner[k].X[d].begin(), runner[k].X[d].end(), s.X);
      EXPECT_TRUE(crew.push(d, s));
    }
    EXPECT_EQ(crew.commonStep(), static_cast<long>(k));
    const CrewTick t = crew.tick(static_cast<long>(k));
    layer_runs += t.layer_ran;
    for (int d = 0; d < crew.robots(); ++d) {
      mismatches += std::memcmp(t.out[d].U, runner[k].U[d].data(), runner[k].U[d].size() * sizeof(double)) != 0;
    }
    mismatches += std::memcmp(crew.Q(), runner[k].Q.data(), runner[k].Q.size() * sizeof(double)) != 0;
    mismatches += std::memcmp(crew.Qd(), runner[k].Qd.data(), runner[k].Qd.size() * sizeof(double)) != 0;
  }
  return mismatches;
}

CrewRequest request(const std::string& name, const std::vector<long>& delays) {
  CrewRequest q;
  q.file = kConfig + "/formations/" + name + ".yaml";
  q.config_dir = kConfig;
  q.delays = delays;
  for (size_t r = 0; r < delays.size(); ++r) q.delay_keys.push_back("/formation/delay_" + std::to_string(r + 1));
  return q;
}

std::string refusal(const CrewRequest& q) {
  try {
    loadFormationCrew(q);
  } catch (const aurora_common::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(FormationCrew, TheUavUgvLinesTickIsTheRunners) {
  const auto q = request("line_pioneer_ardrone", {2, 5, -1});
  auto crew = loadFormationCrew(q);
  ASSERT_EQ(crew->robots(), 2);
  EXPECT_EQ(crew->shape(), "uav_ugv_line");
  EXPECT_EQ(crew->robot(0).vehicle, "pioneer3dx");
  EXPECT_TRUE(crew->robot(0).ground);
  EXPECT_EQ(crew->robot(0).name_space, "pioneer1");
  EXPECT_EQ(crew->robot(1).vehicle, "ardrone2");
  EXPECT_FALSE(crew->robot(1).ground);
  EXPECT_EQ(std::string(crew->variableName(0)), "xf");
  UavUgvLineSetup setup = readUavUgvLineFile(q.file, q.config_dir);
  setup.delay[0] = 2, setup.delay[1] = 5;
  EXPECT_EQ(crew->ticks(), setup.ticks());
  EXPECT_EQ(crew->sampleTime(), setup.tick);
  const auto runner = runnerTicks<UavUgvRobots, UavUgvShape>(uavUgvRun(setup), 600);
  long runs = 0;
  EXPECT_EQ(crewMismatches(*crew, runner, runs), 0);
  EXPECT_EQ(runs, 600);  // the layer runs every tick
  // Not a vacuous pass: the Pioneer drove and turned, the drone flew.
  EXPECT_NE(runner[599].U[0][1], 0.0);
  EXPECT_GT(std::fabs(runner[599].X[0][0] - runner[0].X[0][0]) + std::fabs(runner[599].X[0][1] - runner[0].X[0][1]), 0.1);
  // A Pioneer's command reaches RosAria as linear.x and angular.z.
  const double U[4] = {0.3, -0.2, 0.0, 0.0};
  const aurora_sim::TwistCommand c = crew->toDriver(0, U);
  EXPECT_EQ(c.linear_x, 0.3);
  EXPECT_EQ(c.angular_z, -0.2);
  // A real ground robot's safety limits bind its command; a drone has none.
  double pioneer[4] = {0.8, -1.5, 0.0, 0.0}, drone[4] = {0.8, -1.5, 0.9, 1.0};
  crew->limitSpeed(0, pioneer, 0.5, 1.0);
  crew->limitSpeed(1, drone, 0.5, 1.0);
  EXPECT_EQ(pioneer[0], 0.5);
  EXPECT_EQ(pioneer[1], -1.0);
  EXPECT_EQ(drone[0], 0.8);
  EXPECT_EQ(drone[1], -1.5);
}

TEST(FormationCrew, TheTrianglesTickIsTheRunners) {
  const auto q = request("triangle_ardrones", {0, 4, 9});
  auto crew = loadFormationCrew(q);
  ASSERT_EQ(crew->robots(), 3);
  EXPECT_EQ(crew->shape(), "triangle");
  EXPECT_EQ(crew->robot(2).name_space, "ardrone3");
  EXPECT_EQ(crew->variables(), 9);
  TriangleSetup setup = readTriangleFile(q.file, q.config_dir);
  setup.delay[1] = 4, setup.delay[2] = 9;
  EXPECT_EQ(crew->ticks(), triangleSteps(setup));
  const auto runner = runnerTicks<TriangleDroneLaw, Triangle>(triangleRun<TriangleDroneLaw>(setup), 450);
  long runs = 0;
  EXPECT_EQ(crewMismatches(*crew, runner, runs), 0);
  // The layer every 0.05 s on the drones' 1/30 s: 3 periods every 2 steps... (its own clock).
  EXPECT_GT(runs, 200);
  EXPECT_LT(runs, 450);
  EXPECT_NE(runner[449].U[2][0], 0.0);
}

// Issue 51: the UAV-UGV line and the triangle fly in the namespaces their files name (a lab whose
// drivers run as bebop1 .. bebop3), the shipped files' defaults otherwise.
TEST(FormationCrew, TheRobotsFlyInTheirFilesNamespaces) {
  CrewRequest q = request("triangle_ardrones", {});
  q.file = std::string(AURORA_TEST_CONFIG_DIR) + "/triangle_bebops.yaml";
  auto crew = loadFormationCrew(q);
  EXPECT_EQ(crew->robot(0).name_space, "bebop1");
  EXPECT_EQ(crew->robot(2).name_space, "bebop3");
  q.file = std::string(AURORA_TEST_CONFIG_DIR) + "/uav_ugv_named.yaml";
  crew = loadFormationCrew(q);
  EXPECT_EQ(crew->robot(0).name_space, "p3dx");
  EXPECT_EQ(crew->robot(1).name_space, "drone7");
  // Files that name none: each robot's vehicle's namespace stem and its number (robot_namespace.h).
  crew = loadFormationCrew(request("line_pioneer_ardrone", {}));
  EXPECT_EQ(crew->robot(0).name_space, "pioneer1");
  EXPECT_EQ(crew->robot(1).name_space, "ardrone2");
  crew = loadFormationCrew(request("triangle_ardrones", {}));
  EXPECT_EQ(crew->robot(0).name_space, "ardrone1");
  EXPECT_EQ(crew->robot(1).name_space, "ardrone2");
  EXPECT_EQ(crew->robot(2).name_space, "ardrone3");
}

TEST(FormationCrew, WhatTheRosLoopCannotFlyIsRefusedNamingTheKey) {
  const std::string kinematic = refusal(request("triangle_kinematic", {}));
  EXPECT_NE(kinematic.find("its robots are kinematic"), std::string::npos) << kinematic;
  EXPECT_NE(kinematic.find("give formation.robots.vehicle: vehicles/ardrone2.yaml, formation.robots.controller: "
                           "controllers/underactuated.yaml"),
            std::string::npos) << kinematic;
  const std::string three = refusal(request("line_pioneer_ardrone", {-1, -1, 4}));
  EXPECT_NE(three.find("'/formation/delay_3' = 4 is refused: this formation has 2 robots"), std::string::npos) << three;
  const std::string long_delay = refusal(request("triangle_ardrones", {-1, 2000, -1}));
  EXPECT_NE(long_delay.find("'/formation/delay_2' = 2000"), std::string::npos) << long_delay;
  // Issue 51: the node and flight share one rule: the triangle flies 1,499 steps (triangleSteps), so
  // delay 1498 is flown and 1499 refused by both, by the delay's own text (no link was given).
  EXPECT_EQ(refusal(request("triangle_ardrones", {-1, -1, 1498})), "");
  const std::string at_end = refusal(request("triangle_ardrones", {-1, -1, 1499}));
  EXPECT_NE(at_end.find("'/formation/delay_3' = 1499: 1499 samples is not shorter than the run's 1499 steps"),
            std::string::npos) << at_end;
  EXPECT_EQ(at_end.find("link"), std::string::npos) << at_end;
}

// The two-drone line's file names no vehicle: its drones fly the one the
// node (~vehicle) or formation_robot (--vehicle) was given, read as its
// entry's UnnamedVehicle; none, or another vehicle's, is refused by name.
TEST(FormationCrew, TheLinesDronesFlyTheVehicleGivenToTheNode) {
  CrewRequest q = request("line_lemniscate", {});
  const std::string none = refusal(q);
  EXPECT_NE(none.find("the line formation's file names no vehicle: its robots fly the ardrone2 vehicle file given to "
                      "the formation node (~vehicle) or to formation_robot (--vehicle), and none was given"),
            std::string::npos) << none;
  using aurora_sim::Pioneer3dx;
  q.vehicle.set<Pioneer3dx>(aurora_sim::loadVehicleFile<Pioneer3dx>(kConfig + "/vehicles/pioneer3dx.yaml"));
  const std::string other = refusal(q);
  EXPECT_NE(other.find("and a pioneer3dx's was given"), std::string::npos) << other;
  const std::string file = kConfig + "/vehicles/ardrone2.yaml";
  q.vehicle.set<aurora_sim::Ardrone2>(aurora_sim::loadVehicleFile<aurora_sim::Ardrone2>(file), file);
  const auto crew = loadFormationCrew(q);
  ASSERT_EQ(crew->robots(), 2);
  for (int d = 0; d < 2; ++d) {
    EXPECT_EQ(crew->robot(d).vehicle, "ardrone2");
    EXPECT_EQ(crew->robot(d).vehicle_file, file);
  }
}
