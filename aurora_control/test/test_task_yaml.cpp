// The one task schema: the shipped task files load; bad keys, types and
// ranges are refused naming the full key and what is accepted.
#include <gtest/gtest.h>

#include <string>

#include "aurora_control/task/task_yaml.h"

using namespace aurora_control;

namespace {

Task<double> load(const std::string& yaml) {
  const YamlReader r("task file 't.yaml': ");
  return readTask(r, YAML::Load(yaml)["task"], "task");
}

// The refusal message for a task, or "" when it loads.
std::string refusal(const std::string& yaml) {
  try {
    load(yaml);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(TaskYaml, ShippedTaskFilesLoad) {
  for (const char* name : {"mission4", "positioning", "circle", "lemniscate", "bebop2_waypoints", "bebop2_lemniscate"}) {
    const std::string path = std::string(AURORA_CONFIG_DIR) + "/tasks/" + name + ".yaml";
    const YamlReader r("task file '" + path + "': ");
    const Task<double> t = readTask(r, YAML::LoadFile(path)["task"], "task");
    EXPECT_GT(t.duration(), 0.0) << name;
  }
  // A ground robot's task lies on the floor; a drone's may not.
  const std::string path = std::string(AURORA_CONFIG_DIR) + "/tasks/pioneer_lemniscate.yaml";
  const YAML::Node floor = YAML::LoadFile(path)["task"];
  EXPECT_EQ(readTask(YamlReader(), floor, "task", TaskHeights::onFloor()).trajectory.centre[2], 0.0);
  EXPECT_THROW(readTask(YamlReader(), floor, "task"), ConfigError);
}

TEST(TaskYaml, WaypointsAndTrajectories) {
  const Task<double> w = load("task: {duration: 20, waypoints: [[1, 2, 3], [0, 0, 1]], end_times: [10, 20]}");
  EXPECT_EQ(w.type, TaskType::kWaypoints);
  EXPECT_EQ(w.at(12.0).pos[0], 0.0);
  EXPECT_EQ(w.at(10.0).pos[2], 3.0);
  const Task<double> c = load("task: {type: circle, centre: [1, 0], height: 1.5, radius: 0.5, period: 10, laps: 3, yaw: along_path}");
  EXPECT_EQ(c.type, TaskType::kCircle);
  EXPECT_DOUBLE_EQ(c.duration(), 30.0);
  EXPECT_TRUE(c.trajectory.yaw_along_path);
  const Task<double> l = load("task: {type: lemniscate, centre: [0, 0], height: 1, amplitudes: [1.5, 0.5], period: 20, yaw: 0.2}");
  EXPECT_EQ(l.type, TaskType::kLemniscate);
  EXPECT_EQ(l.trajectory.laps, 1);
  EXPECT_EQ(l.trajectory.yaw, 0.2);
}

TEST(TaskYaml, RefusalsNameTheKey) {
  EXPECT_NE(refusal("task: {duration: 20, waypoints: [[1, 2, 3]], end_times: [20], radius: 1}")
                .find("'task.radius' is not a known key: accepted name, type, duration, waypoints, end_times"),
            std::string::npos);
  EXPECT_NE(refusal("task: {type: circle, centre: [0, 0], height: 1, radius: 1, period: 10, amplitudes: [1, 1]}")
                .find("'task.amplitudes' is not a known key"),
            std::string::npos);
  EXPECT_NE(refusal("task: {type: spiral}").find("'task.type' = 'spiral' is not accepted: waypoints, circle or lemniscate"),
            std::string::npos);
  EXPECT_NE(refusal("task: {type: circle, centre: [0, 0], height: 1, radius: one, period: 10}")
                .find("'task.radius' = 'one' has the wrong type: expected a number"),
            std::string::npos);
  EXPECT_NE(refusal("task: {type: circle, centre: [0, 0], height: 1, radius: 0, period: 10}")
                .find("'task.radius' = 0 is outside the accepted range (0, 100] m"),
            std::string::npos);
  EXPECT_NE(refusal("task: {type: circle, centre: [0, 0], height: 1, radius: 1}").find("'task.period' is missing"),
            std::string::npos);
  EXPECT_NE(refusal("task: {type: circle, centre: [0, 0], height: 1, radius: 1, period: 10, laps: 1.5}")
                .find("'task.laps' must be a whole number"),
            std::string::npos);
  EXPECT_NE(refusal("task: {duration: 20, waypoints: [[1, 2, 3]], end_times: [30, 40]}")
                .find("'task.end_times' must be a list with one time [s] per waypoint"),
            std::string::npos);
  EXPECT_NE(refusal("task: {duration: 20, waypoints: [[1, 2]], end_times: [20]}").find("'task.waypoints[0]' must be [x, y, z] in m"),
            std::string::npos);
  EXPECT_EQ(refusal("task: {duration: 20, waypoints: [[1, 2, 3]], end_times: [20]}"), "");
  // Every message says where the value came from.
  EXPECT_EQ(refusal("task: {type: spiral}").rfind("task file 't.yaml': ", 0), 0u);
}

// YAML 1.1 readers (rosparam) take 6e1 as text: the refusal says how to
// write it so that both readers see a number.
// A waypoint may carry a yaw (the Bebop 2's scenario); a lemniscate may
// have x go twice per lap. Neither changes a task that does not say so.
TEST(TaskYaml, WaypointYawAndTheLemniscatesFastAxis) {
  const Task<double> w = load("task: {duration: 20, waypoints: [[1, 2, 3, 1.5], [0, 0, 1]], end_times: [10, 20]}");
  EXPECT_EQ(w.at(5.0).yaw, 1.5);
  EXPECT_EQ(w.at(15.0).yaw, 0.0);
  EXPECT_NE(refusal("task: {duration: 20, waypoints: [[1, 2, 3, 4]], end_times: [20]}")
                .find("'task.waypoints[0]' has yaw 4: accepted [-pi, pi] rad"), std::string::npos);
  EXPECT_NE(refusal("task: {duration: 20, waypoints: [[1, 2, 3, 0, 5]], end_times: [20]}")
                .find("'task.waypoints[0]' must be [x, y, z] in m (or [x, y, z, yaw], yaw in rad)"), std::string::npos);
  const std::string fig = "task: {type: lemniscate, centre: [0, 0], height: 1.5, amplitudes: [0.75, 1.25], period: 30";
  EXPECT_FALSE(load(fig + "}").trajectory.fast_x);
  EXPECT_TRUE(load(fig + ", fast_axis: x}").trajectory.fast_x);
  EXPECT_NE(refusal(fig + ", fast_axis: z}").find("'task.fast_axis' = 'z' is not accepted: x or y"), std::string::npos);
  EXPECT_NE(refusal("task: {type: circle, centre: [0, 0], height: 1.5, radius: 1, period: 30, fast_axis: x}")
                .find("'task.fast_axis' is not a known key"), std::string::npos);
}

TEST(TaskYaml, AnExponentReadAsTextSaysHowToWriteIt) {
  const std::string msg = refusal("task: {duration: '6e1', waypoints: [[1, 2, 3]], end_times: [20]}");
  EXPECT_NE(msg.find("not a string (YAML 1.1, which rosparam reads, takes '6e1' as text: write 6.0e+1)"),
            std::string::npos) << msg;
  EXPECT_EQ(refusal("task: {duration: '60', waypoints: [[1, 2, 3]], end_times: [20]}").find("YAML 1.1"),
            std::string::npos);
}
