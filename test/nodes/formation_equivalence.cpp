// Bit-for-bit equality of the formation in the ROS loop (formation.launch,
// lockstep) and the offline formation runner (formation_runner.h, what
// `flight --formation` flies): every drone's state at every step, and the
// formation topic's Q and Qd at every tick, with a different delay (or
// link) on each drone.
#include <aurora_msgs/DroneState.h>
#include <aurora_msgs/Formation.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cmath>
#include <cstring>
#include <map>
#include <vector>

#include "aurora_control/formation/formation_yaml.h"
#include "aurora_sim/ros/vehicle_params.h"
#include "lockstep_states.h"

using namespace aurora_control;
using Line = LineFormation<double>;

TEST(FormationEquivalence, RosLoopEqualsTheFormationRunnerBitForBit) {
  ros::NodeHandle pnh("~"), d1("/ardrone1"), d2("/ardrone2");
  const int steps = pnh.param("steps", 600);
  std::map<unsigned long, aurora_msgs::Formation> layer;
  ros::Subscriber sub = d1.subscribe<aurora_msgs::Formation>(
      "/formation/formation", 4000, [&](const aurora_msgs::Formation::ConstPtr& m) { layer[m->step] = *m; });
  std::map<unsigned long, aurora_msgs::DroneState> flown2;
  ros::Subscriber sub2 = d2.subscribe<aurora_msgs::DroneState>(
      "state", 4000, [&](const aurora_msgs::DroneState::ConstPtr& m) { flown2[m->step] = *m; });
  auto flown1 = aurora_tests::collectStates(d1, steps);
  for (int i = 0; i < 100 && (flown2.size() < flown1.size() || layer.size() < static_cast<size_t>(steps)); ++i) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_GE(flown1.size(), static_cast<size_t>(steps + 1)) << "ROS loop did not complete in time";

  std::string file;
  ASSERT_TRUE(pnh.getParam("formation_file", file));
  const auto vehicle = aurora_sim::loadVehicleParams(d1, "vehicle");
  const FormationFile f = readFormationFile(file, pnh.param<std::string>("config_dir", ""));
  FormationRun<double, Line> run = formationRun(f, vehicle);
  run.drone[0].delay = pnh.param("delay_1", 0), run.drone[1].delay = pnh.param("delay_2", 0);
  std::vector<std::vector<double>> offline[2];
  std::vector<std::vector<double>> Q, Qd;
  for (int d = 0; d < 2; ++d) {
    aurora_sim::ArdroneState<double> s0;
    s0.reset();
    for (int i = 0; i < 3; ++i) s0.X[i] = run.drone[d].start[i];
    offline[d].emplace_back(s0.X, s0.X + 12);
  }
  auto observe = [&](const FormationObservation<double, Line>& o) {
    for (int d = 0; d < 2; ++d) offline[d].emplace_back(o.drones[d].model.X, o.drones[d].model.X + 12);
    Q.emplace_back(o.layer.Q(), o.layer.Q() + 6);
    Qd.emplace_back(o.layer.Qd(), o.layer.Qd() + 6);
  };
  withLaw(f.drones[0].controller.law, [&](auto law) {
    runFormation<decltype(law), double, Line, 64>(run, steps, observe);
  });
  EXPECT_EQ(aurora_tests::bitMismatches(flown1, offline[0], steps), 0) << "drone 1";
  EXPECT_EQ(aurora_tests::bitMismatches(flown2, offline[1], steps), 0) << "drone 2";
  long layer_mismatches = 0, ran = 0;
  for (int k = 0; k < steps; ++k) {
    ASSERT_TRUE(layer.count(k)) << "formation topic of tick " << k << " missing";
    ran += layer[k].layer_ran;
    for (int i = 0; i < 6; ++i) {
      layer_mismatches += std::memcmp(&layer[k].Q[i], &Q[k][i], sizeof(double)) != 0;
      layer_mismatches += std::memcmp(&layer[k].Qd[i], &Qd[k][i], sizeof(double)) != 0;
    }
  }
  EXPECT_EQ(layer_mismatches, 0);
  EXPECT_EQ(ran, (steps + run.schedule.period_ticks - 1) / run.schedule.period_ticks);
  // Not a vacuous pass: drone 2 moved, and the two delays differ.
  double far = 0.0;
  for (const auto& kv : flown2) far = std::max(far, std::hypot(kv.second.position.x - flown2[0].position.x,
                                                               kv.second.position.y - flown2[0].position.y));
  EXPECT_GT(far, 0.3);
  EXPECT_NE(run.drone[0].delay, run.drone[1].delay);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "formation_equivalence");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
