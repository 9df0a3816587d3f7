// Bit-for-bit equality of the ROS lockstep loop and the offline runner.
#include <aurora_msgs/DroneState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cstring>
#include <map>
#include <vector>

#include "aurora_control/loop/ardrone2/ardrone_study.h"
#include "aurora_control/loop/positioning_runner.h"
#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/ros/vehicle_params.h"
#include "lockstep_states.h"

using namespace aurora_control;

namespace {

WaypointTask<double> taskFromParams(const ros::NodeHandle& pnh) {
  std::vector<double> end_times;
  XmlRpc::XmlRpcValue wps;
  EXPECT_TRUE(pnh.getParam("task/waypoints", wps));
  EXPECT_TRUE(pnh.getParam("task/end_times", end_times));
  WaypointTask<double> task;
  task.count = wps.size();
  for (int i = 0; i < wps.size(); ++i) {
    for (int j = 0; j < 3; ++j) task.position[i][j] = static_cast<double>(wps[i][j]);
    task.end_time[i] = end_times[i];
  }
  EXPECT_TRUE(pnh.getParam("task/duration", task.duration));
  return task;
}

}  // namespace

TEST(TrajectoryEquivalence, RosLoopEqualsOfflineRunnerBitForBit) {
  ros::NodeHandle nh, pnh("~");
  const int delay = pnh.param("delay", 0);
  const int steps = pnh.param("steps", 1800);
  ASSERT_GT(delay, 0) << "the test must use a nonzero delay";

  auto flown = aurora_tests::collectStates(nh, steps);
  ASSERT_GE(flown.size(), static_cast<size_t>(steps + 1)) << "ROS loop did not complete in time";

  // The offline runner with the same vehicle file, task, gains and delay.
  const auto params = aurora_sim::loadVehicleParams<aurora_sim::Ardrone2>(nh, "vehicle");
  RunnerConfig<double> cfg;
  cfg.task.waypoints = taskFromParams(pnh);
  cfg.clamp_commands = true;
  double kp = 0, kd = 0;
  ASSERT_TRUE(pnh.getParam("controller/kp", kp));
  ASSERT_TRUE(pnh.getParam("controller/kd", kd));
  std::vector<std::vector<double>> offline(1, std::vector<double>(12));
  {
    aurora_sim::ArdroneState<double> s0;
    s0.reset();
    offline[0].assign(s0.X, s0.X + 12);
  }
  runPositioning(params, cfg, PdGains<double>{kp, kd}, delay,
                 [&](const FlightObservation& o) {
                   offline.emplace_back(o.after.model.X, o.after.model.X + 12);
                 });
  ASSERT_GE(offline.size(), static_cast<size_t>(steps + 1));

  const long mismatches = aurora_tests::bitMismatches(flown, offline, steps);
  EXPECT_EQ(mismatches, 0);
  // Guard against a vacuous pass: the drone actually flew the mission.
  EXPECT_GT(std::fabs(flown[steps].position.x - flown[0].position.x) +
                std::fabs(flown[450].position.z - flown[0].position.z),
            0.5);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "trajectory_equivalence");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
