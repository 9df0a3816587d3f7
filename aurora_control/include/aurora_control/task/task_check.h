// Validation of a waypoint task, shared by the controller node (ROS
// parameters) and the sweep (yaml-cpp): one set of rules, one wording.
#pragma once

#include <cmath>
#include <string>

#include "aurora_control/task/waypoint_task.h"
#include "aurora_common/refusal_text.h"

namespace aurora_control {

// Heights a task may ask for [m]: a waypoint or a trajectory below 0.2 m is
// at (or under) the ground the drone takes off from (docs/controllers.md,
// "Tasks").
constexpr double kMinTaskHeight = 0.2, kMaxTaskHeight = 100.0;

// The heights a vehicle's task may ask for: a drone's between the bounds
// above, a ground robot's on the floor (z = 0; docs/pioneer3dx.md).
struct TaskHeights {
  double min, max;
  const char* why;  // said after the accepted range in a refusal

  static TaskHeights flying() { return {kMinTaskHeight, kMaxTaskHeight, "z is up; the ground is z = 0"}; }
  static TaskHeights onFloor() { return {0.0, 0.0, "a ground robot's task lies on the floor"}; }
  template <class Vehicle>
  static TaskHeights of() {
    return Vehicle::kOnGround ? onFloor() : flying();
  }
  bool accepts(double z) const { return z >= min && z <= max; }
  // "[0.2, 100] m (why)": the accepted range, as every refusal says it.
  std::string rangeText() const {
    return "[" + aurora_common::numberText(min) + ", " + aurora_common::numberText(max) + "] m (" + why + ")";
  }
  std::string refusal(double z) const {
    return "has z = " + aurora_common::numberText(z) + " m: accepted heights " + rangeText();
  }
};

// Empty when the task is usable; otherwise what is wrong, naming the key
// under `prefix` (e.g. "/ardrone1/controller/task/").
template <typename T, int N>
std::string checkTask(const WaypointTask<T, N>& task, const std::string& prefix,
                      const TaskHeights& heights = TaskHeights::flying()) {
  if (task.count < 1 || task.count > N) {
    return "'" + prefix + "waypoints' has " + std::to_string(task.count) +
           " entries: accepted 1 to " + std::to_string(N) + " waypoints [x, y, z] in m";
  }
  if (!(std::isfinite(double(task.duration)) && task.duration > 0 && task.duration <= 86400)) {
    return "'" + prefix + "duration' = " + std::to_string(double(task.duration)) +
           " is invalid: accepted range (0, 86400] s";
  }
  for (int i = 0; i < task.count; ++i) {
    const std::string wp = "'" + prefix + "waypoints[" + std::to_string(i) + "]'";
    for (int j = 0; j < 3; ++j) {
      if (!std::isfinite(double(task.position[i][j]))) return wp + " is not finite";
    }
    const double z = double(task.position[i][2]);
    if (!heights.accepts(z)) return wp + " " + heights.refusal(z);
    const double prev = i == 0 ? 0.0 : double(task.end_time[i - 1]);
    if (!(double(task.end_time[i]) > prev)) {
      return "'" + prefix + "end_times[" + std::to_string(i) + "]' = " +
             std::to_string(double(task.end_time[i])) +
             " is invalid: end times must be positive and strictly increasing";
    }
    if (double(task.end_time[i]) > double(task.duration)) {
      return "'" + prefix + "end_times[" + std::to_string(i) + "]' = " + aurora_common::numberText(task.end_time[i]) +
             " is after the task's duration (" + aurora_common::numberText(task.duration) +
             " s): accepted end times up to the duration (the last waypoint is held after its end time)";
    }
  }
  return "";
}

}  // namespace aurora_control
