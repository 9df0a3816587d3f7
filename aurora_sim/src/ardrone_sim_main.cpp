// Simulated Parrot AR.Drone 2.0: constructs the node and spins.
#include <ros/ros.h>

#include "ardrone_sim_node.h"
#include "aurora_sim/ros_params.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "ardrone_sim");
  // Handles outlive the node: the last NodeHandle's destruction shuts
  // rosconsole down, which would swallow the fatal message below.
  ros::NodeHandle nh, private_nh("~");
  try {
    aurora_sim::ArdroneSimNode node{nh, private_nh};
    ros::spin();
  } catch (const aurora_sim::ParameterError& e) {
    ROS_FATAL("ardrone_sim: %s", e.what());
    return 2;
  }
  return 0;
}
