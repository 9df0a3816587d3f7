// A task: what the drone should do at each time. Either waypoints (one point
// per time slot: the thesis's mission, the study's single point) or a
// trajectory (circle, lemniscate: trajectory_task.h). One type for the node,
// replay, the offline runner and the sweep; loaded from one YAML schema
// (task_yaml.h).
#pragma once

#include "aurora_control/task/trajectory_task.h"
#include "aurora_control/task/waypoint_task.h"
#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"

namespace aurora_control {

// Task time of iteration k: k Ts, from the integer step, so the ROS loop
// and the offline runner switch waypoints at the same step
// (docs/architecture.md, "Step index and metric time"). T is a scalar or a
// batch of per-lane step numbers.
template <typename T>
AURORA_HD inline T taskTime(const T& k, const T& Ts) {
  return k * Ts;
}
inline double taskTime(long k, double Ts) { return taskTime(double(k), Ts); }

enum class TaskType : int { kWaypoints = 0, kCircle = 1, kLemniscate = 2 };

template <typename T>
struct Task {
  TaskType type = TaskType::kWaypoints;
  WaypointTask<T> waypoints;    // kWaypoints
  TrajectoryTask<T> trajectory; // kCircle, kLemniscate

  AURORA_HD bool isTrajectory() const { return type != TaskType::kWaypoints; }
  AURORA_HD T duration() const { return isTrajectory() ? trajectory.duration() : waypoints.duration; }

  // The reference at task time t [s]. Waypoints: the active point and its
  // yaw, at rest; chosen by selects, so lanes at different times work.
  template <typename Time>
  AURORA_HD Reference<Time> at(const Time& t) const {
    if (isTrajectory()) return trajectory.at(t);
    using aurora_common::select;
    Reference<Time> r;
    for (int j = 0; j < 3; ++j) r.pos[j] = Time(waypoints.position[0][j]);
    r.yaw = Time(waypoints.yaw[0]);
    for (int i = 1; i < waypoints.count; ++i) {
      const auto later = t > Time(waypoints.end_time[i - 1]);
      for (int j = 0; j < 3; ++j) r.pos[j] = select(later, Time(waypoints.position[i][j]), r.pos[j]);
      r.yaw = select(later, Time(waypoints.yaw[i]), r.yaw);
    }
    for (int j = 0; j < 3; ++j) r.vel[j] = r.acc[j] = Time(0);
    r.yaw_rate = r.yaw_acc = Time(0);
    return r;
  }

  // Index of the active waypoint, or of the lap of a trajectory (0-based;
  // the last one after the end): the segments the report measures.
  int activeIndex(T t) const {
    if (!isTrajectory()) return waypoints.activeIndex(t);
    const int lap = t > T(0) ? static_cast<int>(t / trajectory.period) : 0;
    return lap < trajectory.laps ? lap : trajectory.laps - 1;
  }

  // The same task in another precision (the float sweep converts once).
  template <typename U>
  AURORA_HD Task<U> cast() const {
    Task<U> c;
    c.type = type;
    c.waypoints.count = waypoints.count;
    for (int i = 0; i < waypoints.count; ++i) {
      for (int j = 0; j < 3; ++j) c.waypoints.position[i][j] = U(waypoints.position[i][j]);
      c.waypoints.yaw[i] = U(waypoints.yaw[i]);
      c.waypoints.end_time[i] = U(waypoints.end_time[i]);
    }
    c.waypoints.duration = U(waypoints.duration);
    if (!isTrajectory()) return c;  // (a waypoint task leaves the trajectory unset)
    const TrajectoryTask<T>& a = trajectory;
    TrajectoryTask<U>& b = c.trajectory;
    b.kind = a.kind;
    for (int j = 0; j < 3; ++j) b.centre[j] = U(a.centre[j]);
    b.size[0] = U(a.size[0]), b.size[1] = U(a.size[1]), b.fast_x = a.fast_x;
    b.period = U(a.period), b.laps = a.laps, b.yaw_along_path = a.yaw_along_path, b.yaw = U(a.yaw);
    return c;
  }
};

// A positioning task: one point for the whole run (the delay study's).
template <typename T>
AURORA_HD inline Task<T> positioningTask(T x, T y, T z, T duration) {
  Task<T> t;
  t.type = TaskType::kWaypoints;
  t.waypoints = WaypointTask<T>::singlePoint(x, y, z, duration);
  return t;
}

}  // namespace aurora_control
