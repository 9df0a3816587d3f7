// The whole of a node's main(): init, construct the node class with
// (nh, private_nh), spin; a ConfigError ends the process with code 2 and
// its message (ROS_FATAL).
#pragma once

#include <ros/ros.h>

#include <cstdio>

#include "aurora_sim/ros/params.h"

namespace aurora_sim {

template <class Node>
int runNode(int argc, char** argv, const char* name) {
  try {
    ros::init(argc, argv, name);
  } catch (const ros::InvalidNameException& e) {
    // e.g. ns:="my drone": one line naming the fix, not an uncaught abort.
    std::fprintf(stderr, "%s: %s: use letters, digits, '_' and '/' (ns:=my_drone)\n", name, e.what());
    return 2;
  }
  // The handles outlive the node: destroying the last NodeHandle shuts
  // rosconsole down, which would swallow the fatal message below.
  ros::NodeHandle nh, private_nh("~");
  try {
    Node node{nh, private_nh};
    ros::spin();
  } catch (const ConfigError& e) {
    ROS_FATAL("%s: %s", name, e.what());
    return 2;
  } catch (const ros::InvalidNameException& e) {
    ROS_FATAL("%s: %s: use letters, digits, '_' and '/' in names", name, e.what());
    return 2;
  }
  return 0;
}

}  // namespace aurora_sim
