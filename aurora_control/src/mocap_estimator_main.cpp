// Motion-capture state estimator: constructs the node and spins.
#include <ros/ros.h>

#include "aurora_sim/ros_params.h"
#include "mocap_estimator_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "mocap_estimator");
  ros::NodeHandle nh, private_nh("~");  // outlive the node, see controller_main.cpp
  try {
    aurora_control::MocapEstimatorNode node{nh, private_nh};
    ros::spin();
  } catch (const aurora_sim::ParameterError& e) {
    ROS_FATAL("mocap_estimator: %s", e.what());
    return 2;
  }
  return 0;
}
