// ROS wrapper of a vehicle's model: the simulated robot a controller or a
// user flies through its driver's topics (cmd_vel; a drone's takeoff, land,
// reset; its odometry topic), with the project's state message.
#pragma once

#include <aurora_msgs/DroneState.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <tf2_ros/transform_broadcaster.h>

#include <string>

#include <memory>

#include "aurora_common/ros/node_main.h"
#include "aurora_sim/rejection_burst.h"
#include "aurora_sim/vehicle/vehicle_type.h"  // every vehicle with its SimProfile

namespace aurora_sim {

// The simulator of one vehicle type (aurora_sim/vehicle/*.h; what it does
// beyond the model: sim_profile.h).
template <class Vehicle>
class SimNode {
 public:
  enum class Mode { kRealtime, kLockstep };
  enum class Flight { kLanded, kTakingOff, kFlying, kLanding };
  using Profile = SimProfile<Vehicle>;
  static_assert(Vehicle::kStates <= kMaxStates, "the state message holds the vehicle's state");

  // Throws ConfigError on a missing or invalid parameter.
  SimNode(ros::NodeHandle nh, ros::NodeHandle private_nh);

 private:
  void onCmdVel(const geometry_msgs::Twist::ConstPtr& msg);
  void onStepCommand(const geometry_msgs::TwistStamped::ConstPtr& msg);
  void takeCommand(const geometry_msgs::Twist& msg);
  void lockstepStep();
  void onTakeoff(const std_msgs::Empty::ConstPtr&);
  void onLand(const std_msgs::Empty::ConstPtr&);
  void onReset(const std_msgs::Empty::ConstPtr&);
  void logBurst(const BurstReport& r) const;
  void onRealtimeTimer(const ros::TimerEvent&);
  void onLockstepRetry(const ros::WallTimerEvent&);
  void refuseSecondClockOwner() const;

  // Picks the command for this step (user command, hover after a timeout,
  // take-off/landing profile), steps the model, publishes.
  void stepAndPublish(const ros::Time& now, bool command_fresh);
  void publishState(const ros::Time& stamp);
  void resetModel();
  void readParameters();
  void readStart();
  ros::Time lockstepTime() const;

  ros::NodeHandle nh_, pnh_;
  typename Vehicle::template Params<double> params_;
  typename Vehicle::template State<double> model_;
  Mode mode_;
  Flight flight_;
  double cmd_timeout_;
  double takeoff_altitude_;
  double start_[3] = {0.0, 0.0, Profile::kFlies ? 0.75 : 0.0};  // [m] a drone starts in the air
  bool start_at_state_point_ = false;  // ~start is the state's point (a ground robot's control point), not its centre
  bool publish_clock_ = true;
  std::string frame_id_, child_frame_id_;
  unsigned long step_ = 0;
  double stop_after_;          // [s] of sim time; 0 = run until stopped
  int lockstep_subscribers_;   // lockstep starts once `state` has this many subscribers
  bool lockstep_started_ = false;
  double max_real_time_factor_;  // lockstep: at most this many sim seconds per wall second; 0 = unlimited
  ros::WallTime last_step_wall_, lockstep_start_wall_;
  ros::Time start_time_;

  double command_[Vehicle::kInputs] = {};  // last valid user command, model order (clamped when applied)
  ros::Time command_time_;
  bool have_command_ = false;
  RejectionBurst nan_burst_;   // NaN/Inf cmd_vel: one warning per burst, summaries
  double nan_quiet_period_ = 1.0;

  ros::Publisher state_pub_, odom_pub_, path_pub_, clock_pub_;
  ros::Subscriber cmd_sub_, step_cmd_sub_, takeoff_sub_, land_sub_, reset_sub_;
  unsigned long answers_ignored_ = 0;  // lockstep: commands answering a step already stepped
  tf2_ros::TransformBroadcaster tf_;
  ros::Timer timer_;
  ros::WallTimer retry_timer_, shutdown_timer_;
  ros::WallTime last_publish_wall_;
  nav_msgs::Path path_;
  int path_decimation_;
};

// The simulator of the vehicle file loaded under `vehicle` (its `type`).
struct SimOfVehicle {
  static std::shared_ptr<void> make(ros::NodeHandle nh, ros::NodeHandle private_nh);
};
using VehicleSimNode = aurora_common::ChosenNode<SimOfVehicle>;

}  // namespace aurora_sim
