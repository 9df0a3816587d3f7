// rviz views of a task: numbered waypoint spheres, and the desired path
// (the waypoint polyline, or the whole trajectory sampled at 10 Hz, so the
// path ahead of the drone is visible).
#pragma once

#include <nav_msgs/Path.h>
#include <visualization_msgs/MarkerArray.h>

#include "aurora_control/task/task.h"

namespace aurora_control {

visualization_msgs::MarkerArray waypointMarkers(const Task<double>& task);
nav_msgs::Path desiredPath(const Task<double>& task);

}  // namespace aurora_control
