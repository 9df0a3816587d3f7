// ROS wrapper of the delay-study controller: feeds received states into the
// delay buffer and publishes the command computed from the delayed state.
#pragma once

#include <aurora_control/ControllerConfig.h>
#include <aurora_msgs/Control.h>
#include <aurora_msgs/DroneState.h>
#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include <memory>
#include <boost/thread/recursive_mutex.hpp>
#include <string>

#include "aurora_control/delayed_controller.h"
#include "aurora_control/waypoint_task.h"

namespace aurora_control {

class ControllerNode {
 public:
  static constexpr int kHistoryCapacity = 2048;  // largest delay: 2047 samples (68 s)

  // Throws aurora_sim::ParameterError on a missing or invalid parameter.
  ControllerNode(ros::NodeHandle nh, ros::NodeHandle private_nh);

 private:
  using Core = DelayedPdController<kHistoryCapacity>;

  void onState(const aurora_msgs::DroneState::ConstPtr& msg);
  void onTimer(const ros::TimerEvent& event);
  void onReconfigure(ControllerConfig& config, uint32_t level);
  void cycle(const ros::Time& now);
  void publishTaskMarkers();
  long readDelaySamples();

  ros::NodeHandle nh_, pnh_;
  double Ts_;
  bool lockstep_;
  bool timer_triggered_;  // realtime: compute on the 30 Hz timer instead of on each new state
  double stale_timeout_;
  WaypointTask<double> task_;

  std::unique_ptr<Core> core_;     // delay buffer, law, clamp, metrics (ROS-free)
  std::string state_frame_ = "world";
  ros::Time last_state_time_;     // ROS time the newest state arrived
  bool stale_ = false;
  aurora_msgs::Control last_control_;
  bool have_control_ = false;

  boost::recursive_mutex config_mutex_;
  dynamic_reconfigure::Server<ControllerConfig> reconfigure_;
  ros::Publisher cmd_pub_, control_pub_, markers_pub_, desired_path_pub_;
  ros::Subscriber state_sub_;
  ros::Timer timer_;
};

}  // namespace aurora_control
