// Bit-for-bit equality of the ROS lockstep loop and the offline flight
// runner (flight_runner.h) for any law and task: the controller and task
// come from the same parameters the node was given.
#include <aurora_msgs/DroneState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <vector>

#include "aurora_control/loop/flight_runner.h"
#include "aurora_control/law/law_yaml.h"
#include "aurora_control/link/link_yaml.h"
#include "aurora_control/task/task_yaml.h"
#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/ros/vehicle_params.h"
#include "lockstep_states.h"

using namespace aurora_control;

namespace {

// The test's private parameters hold the same controller and task files as
// the node's; read them with the node's loaders (through their YAML text).
YAML::Node fileParam(const ros::NodeHandle& pnh, const std::string& key) {
  std::string path;
  EXPECT_TRUE(pnh.getParam(key, path)) << key;
  return YAML::LoadFile(path);
}

}  // namespace

TEST(FlightEquivalence, RosLoopEqualsTheFlightRunnerBitForBit) {
  ros::NodeHandle nh, pnh("~");
  const int steps = pnh.param("steps", 900);
  auto flown = aurora_tests::collectStates(nh, steps);
  ASSERT_GE(flown.size(), static_cast<size_t>(steps + 1)) << "ROS loop did not complete in time";

  const auto params = aurora_sim::loadVehicleParams(nh, "vehicle");
  std::string controller_file;
  ASSERT_TRUE(pnh.getParam("controller_file", controller_file));
  const ControllerFile controller = readControllerFile(controller_file);
  ControllerSettings set = controller.settings;
  set.vehicle = params;
  set.Ts = params.Ts;
  const long given_delay = pnh.param("delay", int(kDelayNotGiven));
  set.clamp_commands = controller.has_clamp ? controller.clamp : true;
  std::string link_file;
  if (pnh.getParam("link_file", link_file)) {  // the node's link:=NAME
    set.link = readLinkFile(link_file);
  }
  set.delay = delayInForce(given_delay, set.link);
  const Task<double> task = readTask(YamlReader(), fileParam(pnh, "task_file")["task"], "task");
  std::vector<std::vector<double>> offline(1);
  aurora_sim::ArdroneState<double> s0;
  s0.reset();
  offline[0].assign(s0.X, s0.X + 12);
  const FlightResult r = runFlight(params, set, task, steps,
                                   [&](const FlightObservation& o, double) {
                                     offline.emplace_back(o.after.model.X, o.after.model.X + 12);
                                   });
  std::printf("flight runner: %s on a %g s task, delay %ld: RMS tracking error %.4f m, max %.4f m\n",
              lawName(set.law), task.duration(), set.delay, r.rms_tracking_error, r.max_tracking_error);

  const long mismatches = aurora_tests::bitMismatches(flown, offline, steps);
  EXPECT_EQ(mismatches, 0);
  if (!link_file.empty()) {
    // Not a vacuous pass: over the ideal link the same flight differs.
    set.link = LinkParams();
    std::vector<std::vector<double>> ideal(1, offline[0]);
    runFlight(params, set, task, steps, [&](const FlightObservation& o, double) {
      ideal.emplace_back(o.after.model.X, o.after.model.X + 12);
    });
    long differ = 0;
    for (size_t k = 0; k < ideal.size() && k < offline.size(); ++k) differ += ideal[k] != offline[k];
    EXPECT_GT(differ, steps / 2) << "the link changed nothing";
  }
  // Guard against a vacuous pass: the drone went at least 0.5 m from its start.
  double farthest = 0.0;
  for (const auto& kv : flown) {
    const double dx = kv.second.position.x - flown[0].position.x;
    const double dy = kv.second.position.y - flown[0].position.y;
    farthest = std::max(farthest, std::sqrt(dx * dx + dy * dy));
  }
  EXPECT_GT(farthest, 0.5);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "flight_equivalence");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
