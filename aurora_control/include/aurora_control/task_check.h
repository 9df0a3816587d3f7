// Validation of a waypoint task, shared by the controller node (ROS
// parameters) and the sweep (yaml-cpp): one set of rules, one wording.
#pragma once

#include <cmath>
#include <string>

#include "aurora_control/waypoint_task.h"

namespace aurora_control {

// Empty when the task is usable; otherwise what is wrong, naming the key
// under `prefix` (e.g. "/ardrone1/controller/task/").
template <typename T, int N>
std::string checkTask(const WaypointTask<T, N>& task, const std::string& prefix) {
  if (task.count < 1 || task.count > N) {
    return "'" + prefix + "waypoints' has " + std::to_string(task.count) +
           " entries: accepted 1 to " + std::to_string(N) + " waypoints [x, y, z] in m";
  }
  if (!(std::isfinite(double(task.duration)) && task.duration > 0 && task.duration <= 86400)) {
    return "'" + prefix + "duration' = " + std::to_string(double(task.duration)) +
           " is invalid: accepted range (0, 86400] s";
  }
  for (int i = 0; i < task.count; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (!std::isfinite(double(task.position[i][j]))) {
        return "'" + prefix + "waypoints[" + std::to_string(i) + "]' is not finite";
      }
    }
    const double prev = i == 0 ? 0.0 : double(task.end_time[i - 1]);
    if (!(double(task.end_time[i]) > prev)) {
      return "'" + prefix + "end_times[" + std::to_string(i) + "]' = " +
             std::to_string(double(task.end_time[i])) +
             " is invalid: end times must be positive and strictly increasing";
    }
  }
  return "";
}

}  // namespace aurora_control
