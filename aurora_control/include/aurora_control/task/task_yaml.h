// The one task schema (config/tasks/*.yaml, a sweep's task), read strictly:
//
//   task:
//     name: mission4                    # optional label
//     type: waypoints                   # waypoints (default) | circle | lemniscate
//     # waypoints:
//     duration: 60.0                    # s
//     waypoints: [[x, y, z], ...]       # m, world frame, 1 to 16; [x, y, z, yaw] with a yaw in rad
//     end_times: [15.0, ...]            # s; waypoint i is desired while t <= end_times[i]
//     # circle / lemniscate:
//     centre: [x, y]                    # m, world frame
//     height: 1.5                       # m
//     radius: 1.0                       # m (circle)
//     amplitudes: [ax, ay]              # m (lemniscate: x = ax sin wt, y = ay sin 2wt)
//     fast_axis: y                      # lemniscate: the axis going twice per lap (x: x = ax sin 2wt, y = ay sin wt)
//     period: 20.0                      # s per lap
//     laps: 2                           # the task lasts laps * period
//     yaw: along_path                   # or a fixed yaw in rad
//
// Unknown keys are refused naming the accepted ones for the type.
#pragma once

#include <string>
#include <vector>

#include "aurora_control/task/task.h"
#include "aurora_control/task/task_check.h"
#include "aurora_control/params/yaml_reader.h"

namespace aurora_control {

namespace task_yaml_detail {

inline void readWaypoints(const YamlReader& r, const YAML::Node& n, const std::string& key,
                          const TaskHeights& heights, Task<double>& task) {
  r.onlyKeys(n, key, {"name", "type", "duration", "waypoints", "end_times"});
  const YAML::Node wps = r.require(n, key, "waypoints", "a list of [x, y, z] in m (or [x, y, z, yaw], yaw in rad)");
  const YAML::Node ends = r.require(n, key, "end_times", "one time [s] per waypoint");
  const std::string wkey = r.key(key, "waypoints"), ekey = r.key(key, "end_times");
  if (!wps.IsSequence()) r.fail(wkey, "must be a list of [x, y, z] in m");
  if (!ends.IsSequence() || ends.size() != wps.size()) r.fail(ekey, "must be a list with one time [s] per waypoint");
  WaypointTask<double>& w = task.waypoints;
  w.count = static_cast<int>(wps.size());
  if (w.count > 16) w.count = 17;  // refused by checkTask with the accepted range
  for (int i = 0; i < static_cast<int>(wps.size()) && i < 16; ++i) {
    const std::string k = wkey + "[" + std::to_string(i) + "]";
    const size_t size = wps[i].IsSequence() && wps[i].size() == 4 ? 4 : 3;
    const std::vector<double> p = r.numbers(wps[i], k, size, "[x, y, z] in m (or [x, y, z, yaw], yaw in rad)");
    for (int j = 0; j < 3; ++j) w.position[i][j] = p[j];
    w.yaw[i] = size == 4 ? p[3] : 0.0;
    if (std::fabs(w.yaw[i]) > aurora_common::kPi) r.fail(k, "has yaw " + YamlReader::fmt(w.yaw[i]) + ": accepted [-pi, pi] rad");
    w.end_time[i] = r.number(ends[i], ekey + "[" + std::to_string(i) + "]");
  }
  w.duration = r.number(r.require(n, key, "duration", "a time in (0, 86400] s"), r.key(key, "duration"));
  const std::string problem = checkTask(w, key + r.separator(), heights);
  if (!problem.empty()) r.failWith(problem);
}

inline void readTrajectory(const YamlReader& r, const YAML::Node& n, const std::string& key,
                           bool circle, const TaskHeights& heights, Task<double>& task) {
  const char* size_key = circle ? "radius" : "amplitudes";
  std::vector<std::string> keys{"name", "type", "centre", "height", size_key, "period", "laps", "yaw"};
  if (!circle) keys.push_back("fast_axis");
  r.onlyKeys(n, key, keys);
  TrajectoryTask<double>& t = task.trajectory;
  t.kind = circle ? TrajectoryKind::kCircle : TrajectoryKind::kLemniscate;
  const std::vector<double> c =
      r.numbers(r.require(n, key, "centre", "[x, y] in m"), r.key(key, "centre"), 2, "[x, y] in m");
  for (int i = 0; i < 2; ++i) {
    if (std::fabs(c[i]) > 1000.0) r.fail(r.key(key, "centre"), "is outside the accepted range [-1000, 1000] m");
    t.centre[i] = c[i];
  }
  const std::string hkey = r.key(key, "height");
  t.centre[2] = r.number(r.require(n, key, "height", "a height in m"), hkey);
  if (!heights.accepts(t.centre[2])) {
    r.fail(hkey, "= " + YamlReader::fmt(t.centre[2]) + " is outside the accepted range " + heights.rangeText());
  }
  const std::string skey = r.key(key, size_key);
  if (circle) {
    t.size[0] = r.numberIn(r.require(n, key, "radius", "a radius in m"), skey, 0.0, 100.0, "m", false);
    t.size[1] = 0.0;
  } else {
    const std::vector<double> a = r.numbers(r.require(n, key, "amplitudes", "[ax, ay] in m"), skey, 2, "[ax, ay] in m");
    for (int i = 0; i < 2; ++i) {
      if (!(a[i] > 0.0 && a[i] <= 100.0)) r.fail(skey, "is outside the accepted range (0, 100] m per axis");
      t.size[i] = a[i];
    }
  }
  t.fast_x = false;
  if (n["fast_axis"]) {
    const std::string axis = r.text(n["fast_axis"], r.key(key, "fast_axis"));
    if (axis != "x" && axis != "y") r.fail(r.key(key, "fast_axis"), "= '" + axis + "' is not accepted: x or y");
    t.fast_x = axis == "x";
  }
  t.period = r.numberIn(r.require(n, key, "period", "a time in [1, 3600] s"), r.key(key, "period"), 1.0, 3600.0, "s");
  t.laps = static_cast<int>(n["laps"] ? r.integer(n["laps"], r.key(key, "laps")) : 1);
  if (t.laps < 1 || t.laps > 1000) r.fail(r.key(key, "laps"), "is outside the accepted range [1, 1000]");
  if (t.duration() > 86400.0) r.fail(key, "lasts laps * period = " + YamlReader::fmt(t.duration()) + " s: accepted up to 86400 s");
  t.yaw_along_path = false;
  t.yaw = 0.0;
  if (n["yaw"]) {
    const std::string ykey = r.key(key, "yaw");
    if (n["yaw"].IsScalar() && n["yaw"].as<std::string>() == "along_path") {
      t.yaw_along_path = true;
    } else {
      t.yaw = r.numberIn(n["yaw"], ykey, -aurora_common::kPi, aurora_common::kPi, "rad (or 'along_path')");
    }
  }
}

}  // namespace task_yaml_detail

// Reads the mapping under `key` (the task's own keys, not 'task:' itself),
// its heights those a vehicle accepts (TaskHeights::of<Vehicle>()).
inline Task<double> readTask(const YamlReader& r, const YAML::Node& node, const std::string& key,
                             const TaskHeights& heights = TaskHeights::flying()) {
  if (!node || !node.IsMap()) r.fail(key, "must be a mapping (a task file's 'task:')");
  Task<double> task;
  const std::string type = node["type"] ? r.text(node["type"], r.key(key, "type")) : "waypoints";
  if (type == "waypoints") {
    task.type = TaskType::kWaypoints;
    task_yaml_detail::readWaypoints(r, node, key, heights, task);
  } else if (type == "circle" || type == "lemniscate") {
    task.type = type == "circle" ? TaskType::kCircle : TaskType::kLemniscate;
    task_yaml_detail::readTrajectory(r, node, key, type == "circle", heights, task);
  } else {
    r.fail(r.key(key, "type"), "= '" + type + "' is not accepted: waypoints, circle or lemniscate");
  }
  return task;
}

}  // namespace aurora_control
