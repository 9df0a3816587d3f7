// Bit-for-bit equality of the ROS lockstep loop and the offline runner.
#include <aurora_msgs/DroneState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cstring>
#include <map>
#include <vector>

#include "aurora_control/positioning_runner.h"
#include "aurora_sim/ros_conversions.h"
#include "aurora_sim/ros_params.h"

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

bool bitEqual(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

}  // namespace

TEST(TrajectoryEquivalence, RosLoopEqualsOfflineRunnerBitForBit) {
  ros::NodeHandle nh, pnh("~");
  const int delay = pnh.param("delay", 0);
  const int steps = pnh.param("steps", 1800);
  ASSERT_GT(delay, 0) << "the test must use a nonzero delay";

  std::map<unsigned long, aurora_msgs::DroneState> flown;
  ros::Subscriber sub = nh.subscribe<aurora_msgs::DroneState>(
      "state", 4000, [&](const aurora_msgs::DroneState::ConstPtr& m) { flown[m->step] = *m; });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(90.0);
  while (ros::ok() && ros::WallTime::now() < deadline &&
         (flown.empty() || flown.rbegin()->first < static_cast<unsigned long>(steps))) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  ASSERT_GE(flown.size(), static_cast<size_t>(steps + 1)) << "ROS loop did not complete in time";

  // The offline runner with the same vehicle file, task, gains and delay.
  const auto params = aurora_sim::loadVehicleParams(nh, "vehicle");
  RunnerConfig<double> cfg;
  cfg.task = taskFromParams(pnh);
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
                 [&](long, const PositioningSim<double, bool>& sim, const double*,
                     const PosVel<double>&) {
                   offline.emplace_back(sim.model.X, sim.model.X + 12);
                 });
  ASSERT_GE(offline.size(), static_cast<size_t>(steps + 1));

  long mismatches = 0;
  double max_diff = 0.0;
  for (int k = 0; k <= steps; ++k) {
    ASSERT_TRUE(flown.count(k)) << "state of step " << k << " missing";
    double X[12];
    aurora_sim::stateFromMsg(flown[k], X);
    for (int i = 0; i < 12; ++i) {
      if (!bitEqual(X[i], offline[k][i])) {
        if (mismatches < 5) {
          ADD_FAILURE() << "step " << k << " state " << i << ": ROS " << X[i] << " offline "
                        << offline[k][i];
        }
        ++mismatches;
        max_diff = std::max(max_diff, std::fabs(X[i] - offline[k][i]));
      }
    }
  }
  EXPECT_EQ(mismatches, 0) << "max |diff| " << max_diff;
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
