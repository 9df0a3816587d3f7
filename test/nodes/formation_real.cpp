// formation.launch driver:=ardrone against two fake drivers (formation_real.test):
// both take off and land through their namespaced driver topics; the
// formation starts once both hover and, until a mocap dropout, stays within
// ~tolerance of the offline runner started where the drones were then; the
// dropout on drone 2 makes both hover (zero commands), then the formation
// goes on; the formation controller's process held up for 0.4 s (a loaded
// machine) does not make them hover; both land at the formation's end.
#include <aurora_msgs/DroneState.h>
#include <aurora_msgs/Formation.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <ros/master.h>
#include <ros/network.h>
#include <signal.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <cmath>
#include <string>
#include <vector>

#include "aurora_control/formation/line/line_yaml.h"
#include "aurora_sim/ros/vehicle_params.h"
#include "truth_track.h"

using namespace aurora_control;
using Line = LineFormation<double>;

namespace {

constexpr int kDrones = 2;

struct Recording {
  std::vector<aurora_tests::TruthSample> truth[kDrones];
  std::vector<aurora_msgs::Formation> ticks;
  std::string received[kDrones];  // the fakes' "takeoff=N land=N reset=N"
  long pause_tick = -1;           // the formation tick at which drone 2's mocap paused
  long stall_tick = -1;           // the tick at which the formation controller was held up
};

// The process id of a running node (its XML-RPC API's getPid); -1 if unknown.
int nodePid(const std::string& node) {
  XmlRpc::XmlRpcValue args, result, uri;
  args[0] = ros::this_node::getName();
  args[1] = node;
  if (!ros::master::execute("lookupNode", args, result, uri, true)) return -1;
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(static_cast<std::string>(uri), host, port)) return -1;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue caller;
  caller[0] = ros::this_node::getName();
  if (!client.execute("getPid", caller, result) || result.size() != 3) return -1;
  return static_cast<int>(result[2]);
}

// Stops a process for `seconds` (SIGSTOP, then SIGCONT), as a loaded
// machine's scheduler may: its threads and timers all stand still.
void holdUp(int pid, double seconds) {
  kill(pid, SIGSTOP);
  ros::WallDuration(seconds).sleep();
  kill(pid, SIGCONT);
}

// Records until both drones landed; pauses drone 2's mocap for 0.5 s once the
// formation reached pause_at [s].
void fly(Recording& r, double pause_at, double timeout) {
  ros::NodeHandle nh;
  std::vector<ros::Subscriber> subs;
  for (int d = 0; d < kDrones; ++d) {
    const std::string fake = "/ardrone" + std::to_string(d + 1) + "/fake_driver/";
    subs.push_back(nh.subscribe<aurora_msgs::DroneState>(fake + "true_state", 1000,
        [&r, d](const aurora_msgs::DroneState::ConstPtr& m) {
          r.truth[d].push_back({m->header.stamp.toSec(), {m->position.x, m->position.y, m->position.z}});
        }));
    subs.push_back(nh.subscribe<std_msgs::String>(fake + "received", 10,
        [&r, d](const std_msgs::String::ConstPtr& m) { r.received[d] = m->data; }));
  }
  subs.push_back(nh.subscribe<aurora_msgs::Formation>("/formation/formation", 1000,
      [&r](const aurora_msgs::Formation::ConstPtr& m) { r.ticks.push_back(*m); }));
  ros::Publisher pause = nh.advertise<std_msgs::Float64>("/ardrone2/fake_driver/pause_mocap", 1, true);
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && ros::WallTime::now() < deadline && (r.ticks.empty() || r.ticks.back().mode != "landed")) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
    if (r.pause_tick < 0 && !r.ticks.empty() && r.ticks.back().mode == "fly" &&
        r.ticks.back().step * r.ticks.back().sample_time >= pause_at) {
      std_msgs::Float64 seconds;
      seconds.data = 0.5;  // above the safety file's hover_after (0.2 s), below land_after (1 s)
      pause.publish(seconds);
      r.pause_tick = static_cast<long>(r.ticks.back().step);
    }
    // 5 s after the dropout, with both drones' states fresh again.
    if (r.pause_tick >= 0 && r.stall_tick < 0 && r.ticks.back().mode == "fly" &&
        r.ticks.back().step * r.ticks.back().sample_time >= pause_at + 5.0) {
      const int pid = nodePid("/formation/formation_controller");
      ASSERT_GT(pid, 0) << "no pid of /formation/formation_controller";
      r.stall_tick = static_cast<long>(r.ticks.back().step);
      holdUp(pid, 0.4);
    }
  }
}

bool sawMode(const Recording& r, const std::string& prefix) {
  for (const auto& m : r.ticks) {
    if (m.mode.compare(0, prefix.size(), prefix) == 0) return true;
  }
  return false;
}

// The first mode published once the node took states ("wait for state"
// before).
std::string firstModeAfterStates(const Recording& r) {
  for (const auto& m : r.ticks) {
    if (m.mode != "wait for state") return m.mode;
  }
  return "";
}

// The offline runner from where the drones were at tick 0; states[d][k]:
// drone d after k steps.
std::vector<std::vector<double>> offlineRun(const Recording& r, const aurora_msgs::Formation& first, int d,
                                            long ticks) {
  ros::NodeHandle pnh("~");
  const FormationFile f = readFormationFile(pnh.param<std::string>("formation_file", ""),
                                            pnh.param<std::string>("config_dir", ""));
  LineRun run = formationRun(f, aurora_sim::loadVehicleParams<aurora_sim::Ardrone2>(ros::NodeHandle("/ardrone1"), "vehicle"));
  for (int j = 0; j < kDrones; ++j) {
    double p[3];
    EXPECT_TRUE(aurora_tests::positionAt(r.truth[j], first.header.stamp.toSec(), p));
    for (int i = 0; i < 3; ++i) run.drone[j].start[i] = p[i];
  }
  std::vector<std::vector<double>> states(1, std::vector<double>(run.drone[d].start, run.drone[d].start + 3));
  auto observe = [&](const LineObservation& o) {
    states.emplace_back(o.drones[d].model.X, o.drones[d].model.X + 3);
  };
  f.drones[0].controller.withLawType([&](auto law) {
    runFormation<decltype(law), double, Line, 64>(run, ticks, observe);
  });
  return states;
}

// Largest distance of drone d's true position at each fly tick before the
// pause from the offline run's state of that tick; counts the ticks compared.
double largestDifference(const Recording& r, int d, long& compared, long& worst_tick) {
  const aurora_msgs::Formation* first = nullptr;
  for (const auto& m : r.ticks) {
    if (m.mode == "fly" && m.step == 0) first = &m;
  }
  if (!first) return INFINITY;
  const auto offline = offlineRun(r, *first, d, r.pause_tick);
  double worst = 0.0;
  compared = 0;
  for (const auto& m : r.ticks) {
    const long k = static_cast<long>(m.step);
    double p[3];
    if (m.mode != "fly" || k >= r.pause_tick || !aurora_tests::positionAt(r.truth[d], m.header.stamp.toSec(), p)) continue;
    const double e = std::sqrt(std::pow(p[0] - offline[k][0], 2) + std::pow(p[1] - offline[k][1], 2) +
                               std::pow(p[2] - offline[k][2], 2));
    if (e > worst) worst = e, worst_tick = k;
    ++compared;
  }
  return worst;
}

}  // namespace

TEST(FormationReal, TwoDriversTakeOffFlyTheFormationAndLand) {
  ros::NodeHandle pnh("~");
  Recording r;
  fly(r, pnh.param("pause_at", 20.0), pnh.param("timeout", 130.0));
  ASSERT_FALSE(r.ticks.empty()) << "no formation message";
  ASSERT_EQ(r.ticks.back().mode, "landed") << "the flight did not end with both drones landed";
  // The formation node takes no state before this checker listens
  // (extra_formation_subscribers): it sees the flight from its take-off.
  EXPECT_EQ(firstModeAfterStates(r), "takeoff");
  EXPECT_TRUE(sawMode(r, "hold (waiting for"));
  EXPECT_TRUE(sawMode(r, "land (task complete)"));
  ASSERT_GE(r.pause_tick, 0) << "the formation never reached the pause";
  for (int d = 0; d < kDrones; ++d) {
    EXPECT_NE(r.received[d].find("takeoff="), std::string::npos);
    EXPECT_EQ(r.received[d].find("takeoff=0"), std::string::npos) << "drone " << d + 1 << ": " << r.received[d];
    EXPECT_EQ(r.received[d].find("land=0"), std::string::npos) << "drone " << d + 1 << ": " << r.received[d];
  }
  // Drone 2's dropout: both drones hover (zero commands), then fly again.
  long hovering = 0, flew_after = 0;
  for (const auto& m : r.ticks) {
    if (m.mode.rfind("hover (ardrone2", 0) == 0) {
      ++hovering;
      for (double u : m.command) EXPECT_EQ(u, 0.0) << "a drone flew on while ardrone2's state was stale";
    }
    flew_after += m.mode == "fly" && static_cast<long>(m.step) > r.pause_tick + 3;
  }
  EXPECT_GT(hovering, 3) << "the dropout did not make the formation hover";
  // Held up 0.4 s, the controller found the states that came meanwhile in its
  // queue: its own stall is no missing state (aurora_control/src/state_age.h).
  ASSERT_GE(r.stall_tick, 0) << "the formation never reached the stall";
  for (const auto& m : r.ticks) {
    if (static_cast<long>(m.step) > r.stall_tick && m.mode != "fly") {
      EXPECT_EQ(m.mode.rfind("hover", 0), std::string::npos) << "tick " << m.step << ": " << m.mode;
    }
  }
  EXPECT_GT(flew_after, 30) << "the formation did not fly on after the dropout";
  // Ticks 0 .. n - 1 flew (the offline runner's n), then both landed.
  const FormationFile f = readFormationFile(pnh.param<std::string>("formation_file", ""),
                                            pnh.param<std::string>("config_dir", ""));
  long last_fly = -1;
  for (const auto& m : r.ticks) {
    if (m.mode == "fly") last_fly = static_cast<long>(m.step);
  }
  EXPECT_EQ(last_fly, formationTicks(f.reference.duration, r.ticks.back().sample_time) - 1);
  for (int d = 0; d < kDrones; ++d) {
    long compared = 0, worst_tick = -1;
    const double worst = largestDifference(r, d, compared, worst_tick);
    std::printf("formation.launch driver:=ardrone, drone %d vs the offline runner: %ld ticks compared, largest "
                "position difference %.3f m (tick %ld)\n", d + 1, compared, worst, worst_tick);
    EXPECT_GT(compared, static_cast<long>(0.9 * r.pause_tick));
    EXPECT_LE(worst, pnh.param("tolerance", 0.3)) << "drone " << d + 1;
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "formation_real");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
