// Tasks: where the drone should be at a given time. A positioning task is a
// single point; the thesis's mission is four waypoints, one per quarter of a
// 60 s run (thesis, Simulation #1; docs/delay-and-study.md "The positioning delay
// study" for the single point).
#pragma once

#include "aurora_common/host_device.h"

namespace aurora_control {

template <typename T, int MaxWaypoints = 16>
struct WaypointTask {
  int count = 0;
  T position[MaxWaypoints][3];  // world frame [m]
  T yaw[MaxWaypoints] = {};     // [rad] in [-pi, pi] (0 unless the task file gives it)
  T end_time[MaxWaypoints];     // the waypoint is desired while t <= end_time [s]
  T duration;                   // the task ends at this time [s]

  AURORA_HD static WaypointTask singlePoint(T x, T y, T z, T duration) {
    WaypointTask t;
    t.count = 1;
    t.position[0][0] = x; t.position[0][1] = y; t.position[0][2] = z;
    t.end_time[0] = duration;
    t.duration = duration;
    return t;
  }

  // Index of the waypoint desired at time t (the last one after its end).
  AURORA_HD int activeIndex(T t) const {
    for (int i = 0; i < count; ++i) {
      if (t <= end_time[i]) return i;
    }
    return count - 1;
  }
};

}  // namespace aurora_control
