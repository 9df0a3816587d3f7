// The formation node (docs/formation.md, "In the ROS loop"): flies the
// robots of a formation file (the two-drone line, the UAV-UGV line, the
// triangle: formation_crew.h) through their driver topics. It subscribes
// each robot's state (/NS/state), runs the crew's tick (each robot's delay
// or link and law, the formation layer) and publishes each robot's command
// (/NS/cmd_vel, its driver's form) and the layer's state (formation). In
// lockstep it answers once every robot's state of the same step arrived; in
// realtime it runs on a timer of the robots' step on the newest states.
// With real robots (~safety/flight_sequence) it also takes the drones off
// (a ground robot drives to its start point), starts the formation once
// every robot is still at its start point, watches their states and lands
// the drones (a ground robot stops) (formation_supervisor.h;
// formation_sequence.cpp).
#pragma once

#include <aurora_msgs/DroneState.h>
#include <aurora_msgs/Formation.h>
#include <ros/ros.h>

#include <memory>
#include <string>
#include <vector>

#include "aurora_control/formation/formation_crew.h"
#include "aurora_control/formation/formation_supervisor.h"
#include "aurora_control/params/limits.h"
#include "driver_command_channel.h"
#include "state_age.h"

namespace aurora_control {

class FormationNode {
 public:
  // Throws aurora_common::ConfigError on a missing or invalid parameter.
  FormationNode(ros::NodeHandle nh, ros::NodeHandle private_nh);

 private:
  using Supervisor = FormationSupervisor<kMaxCrew>;

  void loadCrew();
  void refuseOtherSims() const;
  void connect();
  void onState(int d, const aurora_msgs::DroneState::ConstPtr& msg);
  void onTimer(const ros::TimerEvent&);
  bool listenersReady() const;
  bool audienceReady();
  int record_subscribers_ = 0;  // recorders of formation to wait for before the first state (record:=true)
  bool audience_ready_ = false; // they and ~formation_subscribers were connected (states are taken from then on)
  void answer(long k, const ros::Time& stamp);
  void publish(const CrewTick& t, const ros::Time& stamp);
  void send(const CrewTick& t, const ros::Time& stamp);
  // Robot d's command: cmd_vel, and in lockstep cmd_vel_stamped with the
  // stamp of the state it answers (the sim steps once per step on it).
  void command(int d, const ros::Time& stamp);
  // The flight sequence (formation_sequence.cpp).
  void configureSequence();
  void flightCycle(const ros::Time& now);
  SafetyConfig robotSafety(int d, const SafetyConfig& drones) const;
  Supervisor::Decision superviseDrones(const ros::Time& now);
  void serviceDriverCommands(const Supervisor::Decision& c, const ros::Time& now);
  CrewTick holdOrHover(const Supervisor::Decision& c);

  ros::NodeHandle nh_, pnh_;
  std::vector<std::string> drones_;  // namespaces, the formation file's order
  bool lockstep_ = false;
  int cmd_subscribers_ = 1;        // lockstep: listeners of each cmd_vel before the first step
  int formation_subscribers_ = 0;  // both modes: listeners of formation before the first state
  std::unique_ptr<FormationCrew> crew_;
  long answered_ = -1;   // lockstep: the newest step answered
  long cycles_ = 0;      // realtime: timer cycles since the first states
  double last_sent_[kMaxCrew][4] = {};
  std::vector<ros::Subscriber> state_subs_;
  std::vector<ros::Publisher> cmd_pubs_, step_cmd_pubs_;
  ros::Publisher formation_pub_, markers_pub_;
  static constexpr long kMarkerDecimation = 3;  // rviz markers at 10 Hz
  ros::Timer timer_;

  // The flight sequence of real drones (off in simulation: mode_ stays "fly").
  bool sequence_ = false;
  SafetyConfig safety_[kMaxCrew];  // each robot's: the drones' ~safety, a ground robot's ~ground/safety
  Supervisor supervisor_;
  TakeoffLand takeoff_land_[kMaxCrew];  // the drones' (a ground robot has none)
  ros::Time last_state_[kMaxCrew];  // when each robot's newest fresh state arrived
  ProcessStall stall_;              // this process's last stall, which the states' ages leave out
  long formation_k_ = 0;           // the formation's next tick (its time stops while the drones hover)
  std::string mode_ = "fly";
  bool told_not_finite_ = false;  // a non-finite command was reported (once)
};

}  // namespace aurora_control
