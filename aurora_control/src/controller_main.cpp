// Delay-study controller node: constructs the node and spins.
#include <ros/ros.h>

#include "aurora_sim/ros_params.h"
#include "controller_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "controller");
  // Handles outlive the node: the last NodeHandle's destruction shuts
  // rosconsole down, which would swallow the fatal message below.
  ros::NodeHandle nh, private_nh("~");
  try {
    aurora_control::ControllerNode node{nh, private_nh};
    ros::spin();
  } catch (const aurora_sim::ParameterError& e) {
    ROS_FATAL("controller: %s", e.what());
    return 2;
  }
  return 0;
}
