// Motion-capture state estimator node: geometry_msgs/PoseStamped in (any
// rate, e.g. vrpn_client_ros at 100-240 Hz), aurora_msgs/DroneState out at
// the controller's rate, with stale=true while poses have stopped.
#pragma once

#include <aurora_msgs/DroneState.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>
#include <tf2/LinearMath/Transform.h>

#include <string>

#include "aurora_control/robot/mocap_estimator.h"
#include "aurora_sim/ros/vehicle_params.h"

namespace aurora_control {

class MocapEstimatorNode {
 public:
  // Throws aurora_common::ConfigError on a missing or invalid parameter.
  MocapEstimatorNode(ros::NodeHandle nh, ros::NodeHandle private_nh);

 private:
  void onPose(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onTimer(const ros::TimerEvent& event);
  void publish(bool stale);

  ros::NodeHandle nh_, pnh_;
  MocapEstimator estimator_;
  std::string world_frame_, input_frame_;
  tf2::Transform input_to_world_;
  double stale_timeout_;
  double Ts_;
  aurora_sim::VehicleOfFile vehicle_;  // the robot's rate and its state from its body's
  ros::Time next_due_;  // when the next state is due

  ros::Time last_pose_arrival_;
  unsigned long step_ = 0;
  unsigned long rejected_order_ = 0;
  bool warned_frame_ = false, was_stale_ = false;
  ros::Publisher state_pub_;
  ros::Subscriber pose_sub_;
  ros::Timer timer_;
};

}  // namespace aurora_control
