// The whole of a node's main(): init, construct the node class with
// (nh, private_nh), spin; a ParameterError ends the process with code 2 and
// its message (ROS_FATAL).
#pragma once

#include <ros/ros.h>

#include "aurora_sim/ros_params.h"

namespace aurora_sim {

template <class Node>
int runNode(int argc, char** argv, const char* name) {
  ros::init(argc, argv, name);
  // The handles outlive the node: destroying the last NodeHandle shuts
  // rosconsole down, which would swallow the fatal message below.
  ros::NodeHandle nh, private_nh("~");
  try {
    Node node{nh, private_nh};
    ros::spin();
  } catch (const ParameterError& e) {
    ROS_FATAL("%s: %s", name, e.what());
    return 2;
  }
  return 0;
}

}  // namespace aurora_sim
