// Bit-for-bit equality of the ROS lockstep loop and the offline flight
// (flight_runner.h) for any vehicle, law and task: the test flies the same
// vehicle, controller, task, link and delay files the nodes were given
// through the chooser the `flight` tool uses (withFlight), and compares
// every state component, a Pioneer's u and omega included.
#include <aurora_msgs/DroneState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "aurora_control/loop/flight_setup.h"
#include "lockstep_states.h"

using namespace aurora_control;

namespace {

using Trajectory = std::vector<std::vector<double>>;

// The offline flight's states 0..steps (initial state first) and its vehicle's state size.
template <class Flight>
Trajectory fly(Flight f, long steps, bool ideal_link) {
  using Law = typename Flight::Law;
  using Vehicle = typename Law::Vehicle;
  if (ideal_link) f.cfg.link = LinkParams();
  typename Vehicle::template State<double> s0;
  Vehicle::start(f.run.plant, s0);
  Trajectory out(1, std::vector<double>(s0.X, s0.X + Vehicle::kStates));
  const FlightResult r = flyLaw(f, steps, [&](const auto& o, double) {
    out.emplace_back(o.after.model.X, o.after.model.X + Vehicle::kStates);
  });
  std::printf("flight: %s on %s, %ld steps, delay %ld: RMS tracking error %.4f m, max %.4f m\n", f.law.c_str(),
              Vehicle::name(), r.steps, f.run.delay, r.rms_tracking_error, r.max_tracking_error);
  return out;
}

std::string param(const ros::NodeHandle& pnh, const std::string& key) {
  std::string value;
  pnh.getParam(key, value);
  return value;
}

}  // namespace

TEST(FlightEquivalence, RosLoopEqualsTheFlightRunnerBitForBit) {
  ros::NodeHandle nh, pnh("~");
  const int steps = pnh.param("steps", 900);
  auto flown = aurora_tests::collectStates(nh, steps);
  ASSERT_GE(flown.size(), static_cast<size_t>(steps + 1)) << "ROS loop did not complete in time";

  // The nodes' files (the launch's vehicle:=, controller:=, task:=, link:=, delay:=).
  FlightFiles files{param(pnh, "controller_file"), param(pnh, "task_file"), param(pnh, "vehicle_file"),
                    param(pnh, "link_file"), pnh.param("delay", int(kDelayNotGiven)), false};
  if (files.vehicle.empty()) files.vehicle = param(pnh, "config_dir") + "/vehicles/ardrone2.yaml";
  Trajectory offline, ideal;
  int states = 0;
  withFlight(files, controllerFileName(files.controller), {0.0, "", ""}, [&](const auto& f) {
    states = std::remove_reference<decltype(f)>::type::Law::Vehicle::kStates;
    offline = fly(f, steps, false);
    if (!files.link.empty()) ideal = fly(f, steps, true);
  });
  EXPECT_EQ(aurora_tests::bitMismatches(flown, offline, steps, states), 0);
  if (!files.link.empty()) {
    // Not a vacuous pass: over the ideal link the same flight differs.
    long differ = 0;
    for (size_t k = 0; k < ideal.size() && k < offline.size(); ++k) differ += ideal[k] != offline[k];
    EXPECT_GT(differ, steps / 2) << "the link changed nothing";
  }
  // Guard against a vacuous pass: the robot went at least 0.5 m from its start.
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
