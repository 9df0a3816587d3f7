// real.launch against the driver-compatible fake: the mission completes (take
// off, fly, land) and the flown position stays within ~tolerance of the
// simulated run (the offline runner: same task, gains, delay, clamping).
#include <aurora_msgs/Control.h>
#include <aurora_msgs/DroneState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cmath>
#include <map>
#include <vector>

#include <yaml-cpp/yaml.h>

#include <string>
#include <type_traits>

#include "aurora_control/loop/flight_setup.h"
#include "truth_track.h"

using namespace aurora_control;

using aurora_tests::positionAt;
using Sample = aurora_tests::TruthSample;

namespace {

std::string param(const ros::NodeHandle& pnh, const std::string& key) {
  std::string value;
  pnh.getParam(key, value);
  return value;
}

}  // namespace

TEST(RealLaunch, MissionCompletesCloseToTheSimulatedRun) {
  ros::NodeHandle nh, pnh("~");
  const std::string fake = pnh.param<std::string>("fake_ns", "/fake_driver");
  const double tolerance = pnh.param("tolerance", 0.2);
  std::vector<Sample> truth;
  std::vector<aurora_msgs::Control> controls;
  bool done = false;
  ros::Subscriber s1 = nh.subscribe<aurora_msgs::DroneState>(
      fake + "/true_state", 1000, [&](const aurora_msgs::DroneState::ConstPtr& m) {
        truth.push_back(Sample{m->header.stamp.toSec(), {m->position.x, m->position.y, m->position.z}});
      });
  // A drone lands at the end; a ground robot stops (flight_supervisor.h).
  const bool ground = pnh.param("ground_robot", false);
  const std::string end = ground ? "stopped" : "landed";
  ros::Subscriber s2 = nh.subscribe<aurora_msgs::Control>(
      "control", 1000, [&](const aurora_msgs::Control::ConstPtr& m) {
        controls.push_back(*m);
        if (m->mode == end) done = true;
      });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(pnh.param("timeout", 110.0));
  while (ros::ok() && !done && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_TRUE(done) << "the flight did not end with '" << end << "' in time (" << controls.size()
                    << " control messages, last mode '"
                    << (controls.empty() ? std::string("none") : controls.back().mode) << "')";
  bool saw_takeoff = false, saw_complete = false;
  long s0 = -1;
  for (const auto& c : controls) {
    saw_takeoff |= c.mode == "takeoff";
    saw_complete |= c.mode == (ground ? "stop (task complete)" : "land (task complete)");
    if (s0 < 0 && c.mode == "fly") s0 = static_cast<long>(c.step);
  }
  EXPECT_EQ(saw_takeoff, !ground);  // a ground robot never takes off
  EXPECT_TRUE(saw_complete);
  ASSERT_GE(s0, 0) << "never flew";

  // The simulated run: the offline flight of the launch's vehicle,
  // controller and task files (any law, through the flight tool's chooser),
  // delay and clamping.
  FlightFiles files{param(pnh, "controller_file"), param(pnh, "task_file"), param(pnh, "vehicle_file"), "",
                    pnh.param("delay", 0), false};
  std::vector<std::vector<double>> sim;
  double Ts = 0.0;
  std::string law;
  withFlight(files, controllerFileName(files.controller), {0.0, "", ""}, [&](const auto& f) {
    using Law = typename std::remove_reference<decltype(f)>::type::Law;
    typename Law::Vehicle::template State<double> s0;
    Law::Vehicle::start(f.run.plant, s0);
    sim.assign(1, std::vector<double>(s0.X, s0.X + 3));
    Ts = f.run.plant.Ts, law = f.law;
    flyLaw(f, studyIterationCount(f.cfg.task.duration(), Ts), [&](const auto& o, double) {
      sim.push_back(std::vector<double>(o.after.model.X, o.after.model.X + 3));
    });
  });

  double worst = 0.0, worst_t = 0.0;
  long compared = 0;
  for (const auto& c : controls) {
    if (c.mode != "fly") continue;
    const long k = static_cast<long>(c.step) - s0;
    if (k < 0 || k >= static_cast<long>(sim.size())) continue;
    double real[3];
    // The truth when the pose the law used was taken (sim state k is what the
    // law saw at iteration k).
    if (!positionAt(truth, c.state_used.header.stamp.toSec(), real)) continue;
    double e = 0.0;
    for (int i = 0; i < 3; ++i) e += (real[i] - sim[k][i]) * (real[i] - sim[k][i]);
    e = std::sqrt(e);
    if (e > worst) worst = e, worst_t = k * Ts;
    ++compared;
  }
  std::printf("real.launch (%s) vs simulated run: %ld cycles compared, largest position difference "
              "%.3f m at task time %.2f s\n", law.c_str(), compared, worst, worst_t);
  EXPECT_GT(compared, static_cast<long>(0.95 * double(sim.size() - 1)));  // nearly every step of the task
  EXPECT_LE(worst, tolerance);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "real_mission");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
