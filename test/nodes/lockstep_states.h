// Shared by the lockstep equivalence tests: collect the states the ROS loop
// published, and compare them with an offline trajectory bit for bit.
#pragma once

#include <aurora_msgs/DroneState.h>
#include <gtest/gtest.h>
#include <ros/ros.h>

#include <cstring>
#include <map>
#include <vector>

#include "aurora_sim/ros/conversions.h"
#include "aurora_sim/vehicle/vehicle_type.h"  // kMaxStates

namespace aurora_tests {

// States by step until step `steps` arrived or `timeout` [s] of wall time passed.
inline std::map<unsigned long, aurora_msgs::DroneState> collectStates(ros::NodeHandle& nh, int steps,
                                                                      double timeout = 90.0) {
  std::map<unsigned long, aurora_msgs::DroneState> flown;
  ros::Subscriber sub = nh.subscribe<aurora_msgs::DroneState>(
      "state", 4000, [&](const aurora_msgs::DroneState::ConstPtr& m) { flown[m->step] = *m; });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && ros::WallTime::now() < deadline &&
         (flown.empty() || flown.rbegin()->first < static_cast<unsigned long>(steps))) {
    ros::spinOnce();
    ros::WallDuration(0.005).sleep();
  }
  return flown;
}

// Number of state values of steps 0..steps that differ in any bit from
// `offline[k]` (`states` values per step: a vehicle's kStates, its extra
// states from the message's `extra`); the first few are reported.
inline long bitMismatches(std::map<unsigned long, aurora_msgs::DroneState>& flown,
                          const std::vector<std::vector<double>>& offline, int steps, int states = 12) {
  long mismatches = 0;
  for (int k = 0; k <= steps; ++k) {
    if (!flown.count(k) || k >= static_cast<int>(offline.size())) {
      ADD_FAILURE() << "state of step " << k << " missing";
      return -1;
    }
    if (static_cast<int>(flown[k].extra.size()) != states - 12) {
      ADD_FAILURE() << "step " << k << ": " << flown[k].extra.size() << " extra states, expected " << states - 12;
      return -1;
    }
    double X[aurora_sim::kMaxStates];
    aurora_sim::stateFromMsg(flown[k], X, states);
    for (int i = 0; i < states; ++i) {
      if (std::memcmp(&X[i], &offline[k][i], sizeof(double)) == 0) continue;
      if (mismatches++ < 5) {
        ADD_FAILURE() << "step " << k << " state " << i << ": ROS " << X[i] << " offline " << offline[k][i];
      }
    }
  }
  return mismatches;
}

}  // namespace aurora_tests
